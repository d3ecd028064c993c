#!/bin/sh
# Distributed synthesis: strong and weak scaling and memory per process.
# Each run is `mpirun -np P noiselab synth ... --json -o F.h5` with one
# OpenMP thread per process (P processes use P cores); its work is what the
# run reports (the slowest process's synthesis plus writing, between
# barriers: the launcher's start, about 0.4-1 s here and varying, is left
# out and reported as the median wall time beside it).  Speed-up =
# work(1) / work(P), medians of REPS runs.  Memory: the largest peak RSS of
# the processes.  P = 4 on this 2-core machine oversubscribes: a memory row,
# not a speed one.
# usage: tools/bench-mpi.sh BINDIR WORKDIR [REPS]  -> TSV
set -eu
bin=$(cd "$1" && pwd)
w=$2
reps=${3:-5}
mkdir -p "$w"
MPIRUN="mpirun --oversubscribe --bind-to none -q"
[ "$(id -u)" = 0 ] && MPIRUN="$MPIRUN --allow-run-as-root"
export OMP_NUM_THREADS=1
now() { date +%s.%N; }
med() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# one P method size [options]: appends wall, work and RSS to $w/wall, $w/work, $w/rss
one() {
    p=$1 m=$2 s=$3
    shift 3
    a=$(now)
    $MPIRUN -np "$p" "$bin/noiselab" synth "$m" --size "$s" --seed 1 "$@" --json -o "$w/f.h5" > "$w/j"
    b=$(now)
    echo "$a $b" | awk '{ print $2 - $1 }' >> "$w/wall"
    jq '.seconds.synthesis + .seconds.write' "$w/j" >> "$w/work"
    jq '.peak_rss_mib' "$w/j" >> "$w/rss"
}
# case P method size [options]: one row, speed-up against $W1 (empty: this is P = 1)
row() {
    c=$1
    shift
    : > "$w/wall" && : > "$w/work" && : > "$w/rss"
    for r in $(seq "$reps"); do one "$@"; done
    work=$(med < "$w/work")
    [ -z "$W1" ] && W1=$work
    awk -v c="$c" -v m="$2" -v s="$3" -v p="$1" -v t="$(med < "$w/wall")" -v k="$work" -v w1="$W1" \
        -v r="$(sort -g "$w/rss" | tail -1)" 'BEGIN {
        # strong: speed-up w1/wP, efficiency w1/(P wP); weak: the same share per
        # process, efficiency w1/wP; memory rows: one run each, no speed
        sp = c == "memory" ? "-" : sprintf("%.2f", w1 / k)
        ef = c == "memory" ? "-" : sprintf("%.2f", c == "weak" ? w1 / k : w1 / k / p)
        printf "%s\t%s\t%s\t%d\t%.3f\t%.3f\t%s\t%s\t%.0f\n", c, m, s, p, t, k, sp, ef, r }'
}
printf 'case\tmethod\tsize\tP\twall_s\twork_s\tspeedup\tefficiency\tpeak_rss_MiB\n'
for spec in "fft 4096x4096 --acf markov:scale=20" "circulant 2048x2048 --acf markov:scale=20" \
            "subdiv 4096x4096 --acf markov:scale=20" "sparse 2048x2048 --acf gauss:scale=4"; do
    W1=
    row strong 1 $spec
    row strong 2 $spec
done
# weak: the same share per process (4096 x 2048 each)
W1=
row weak 1 fft 4096x2048 --acf markov:scale=20
row weak 2 fft 4096x4096 --acf markov:scale=20
# memory per process (P = 4 oversubscribed), float64
for spec in "4096x4096" "512x512x512"; do
    W1=
    for p in 1 2 4; do
        reps=1 row memory $p fft "$spec" --acf markov:scale=20 --precision double
    done
done
rm -f "$w/f.h5" "$w/j"
