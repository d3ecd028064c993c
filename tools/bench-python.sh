#!/bin/sh
# Python against C: 2048^2 FFT synthesis (markov:scale=8) by noiselab.Plan from
# Debian's python3 against the same libnoiselab.so call from a small C program
# (python/bench/fft_time.c, linked to BUILD/libnoiselab.so), each the median of
# RUNS (default 9) calls of one plan made outside the timing, with the same
# FFTW planning (NOISELAB_FFTW, NOISELAB_WISDOM from the environment, as make
# bench sets them).  The two alternate ROUNDS times (default 5) and each side
# keeps its smallest median, so that other load on the machine weighs less.
# Prints a TSV row: the C execute into one field and the C allocate +
# execute + free (seconds), the Python call returning a new array (what
# plan(seed) does: allocate, execute) and the Python call refilling one array
# (plan(seed, out=a): execute), and the ratios of like to like: new array
# against allocate + execute + free, refill against execute (target <= 1.1).
# usage: tools/bench-python.sh BUILD [N]
set -eu
top=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$1" && pwd)
n=${2:-2048}
runs=${RUNS:-9}
rounds=${ROUNDS:-5}
spec=markov:scale=8
PYTHON=${PYTHON:-/usr/bin/python3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
${CC:-cc} -O2 -std=c11 -D_GNU_SOURCE -I"$top" -o "$tmp/fft_time" "$top/python/bench/fft_time.c" \
    -L"$build" -lnoiselab -Wl,-rpath,"$build"
best() { awk -v a="$1" -v b="$2" 'BEGIN { print (a == "" || b < a) ? b : a }'; }
ce="" ca="" pn="" po=""
i=0
while [ "$i" -lt "$rounds" ]; do
    set -- $("$tmp/fft_time" "$n" "$runs" "$spec")
    ce=$(best "$ce" "$1") ca=$(best "$ca" "$2")
    set -- $(NOISELAB_LIB="$build/libnoiselab.so" PYTHONPATH="$top/python" PYTHONDONTWRITEBYTECODE=1 \
        "$PYTHON" "$top/python/bench/fft_time.py" "$n" "$runs" "$spec")
    pn=$(best "$pn" "$1") po=$(best "$po" "$2")
    i=$((i + 1))
done
printf 'bench\tsize\tc_execute_s\tc_alloc_execute_s\tpython_new_s\tpython_out_s\tratio_new\tratio_out\ttarget\n'
awk -v n="$n" -v ce="$ce" -v ca="$ca" -v pn="$pn" -v po="$po" -v fftw="${NOISELAB_FFTW:-default}" 'BEGIN {
    printf "python-fft-%s\t%dx%d\t%.4f\t%.4f\t%.4f\t%.4f\t%.3f\t%.3f\t<=1.1\n", fftw, n, n, ce, ca, pn, po, pn / ca, po / ce }'
