#!/bin/sh
# Measured FFTW wisdom for the common power-of-two sizes, made by the
# program itself so that the plans are exactly the ones it makes (the same
# transforms, layouts, alignment and thread count): 2D `synth fft` at each
# size N, and `synth circulant` at N/2 (its embedding is N).  The library
# loads the installed file and plans with FFTW_ESTIMATE, which takes these
# measured plans (core/fftw_plan.h).  Takes about 10 s per 4096^2.
# usage: tools/wisdom.sh NOISELAB OUT SIZE...
set -eu
nl=$1
out=$2
shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
for n in "$@"; do
    NOISELAB_FFTW=measure XDG_CACHE_HOME=$tmp "$nl" synth fft --acf markov:scale=8 --size "${n}x$n" -o "$tmp/f.exr"
    NOISELAB_FFTW=measure XDG_CACHE_HOME=$tmp "$nl" synth circulant --acf markov:scale=8 --size "$((n / 2))x$((n / 2))" \
        -o "$tmp/f.exr" > /dev/null
done
if [ -f "$tmp/noiselab/fftw-wisdom" ]; then cp "$tmp/noiselab/fftw-wisdom" "$out.tmp"; else : > "$out.tmp"; fi
mv "$out.tmp" "$out"
