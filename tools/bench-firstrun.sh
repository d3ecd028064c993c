#!/bin/sh
# First run against steady state of `noiselab synth fft` (2D, N^2), end to
# end, medians of REPS interleaved runs (each a new process):
#   first:   a fresh machine: no wisdom anywhere (an empty cache folder;
#            NOISELAB_FFTW=estimate loads no installed wisdom either), so
#            FFTW_ESTIMATE plans;
#   steady:  measured wisdom for the size (the file `make wisdom` makes,
#            given as WISDOM), which the same FFTW_ESTIMATE planner takes;
#   measure: the former policy's first run, FFTW_MEASURE planning into an
#            empty cache (NOISELAB_FFTW=measure).
# usage: tools/bench-firstrun.sh NOISELAB WISDOM WORKDIR [REPS [SIZES]]  -> TSV
set -eu
nl=$1
wis=$2
w=$3
reps=${4:-5}
sizes=${5:-1024 2048 4096}
mkdir -p "$w"
now() { date +%s.%N; }
# seconds of one run of synth fft at N^2 with env assignments $2...
one() {
    n=$1
    shift
    rm -rf "$w/cache"
    a=$(now)
    env XDG_CACHE_HOME="$w/cache" "$@" "$nl" synth fft --acf markov:scale=16 --size "${n}x$n" --seed 1 -o "$w/f.exr"
    b=$(now)
    echo "$a $b" | awk '{ print $2 - $1 }'
}
med() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
printf 'size\tfirst_s\tsteady_s\tfirst/steady\tmeasure_first_s\tmeasure_first/steady\n'
for n in $sizes; do
    : > "$w/first" && : > "$w/steady" && : > "$w/measure"
    for r in $(seq "$reps"); do
        one "$n" NOISELAB_WISDOM= NOISELAB_FFTW=estimate >> "$w/first"
        one "$n" NOISELAB_WISDOM="$wis" >> "$w/steady"
        one "$n" NOISELAB_WISDOM= NOISELAB_FFTW=measure >> "$w/measure"
    done
    f=$(med < "$w/first") s=$(med < "$w/steady") m=$(med < "$w/measure")
    awk -v n="$n" -v f="$f" -v s="$s" -v m="$m" \
        'BEGIN { printf "fft %d^2\t%.3f\t%.3f\t%.2f\t%.3f\t%.2f\n", n, f, s, f / s, m, m / s }'
done
