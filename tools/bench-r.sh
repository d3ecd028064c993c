#!/bin/sh
# noiselab against R in one run, when R with RandomFields and gstat is
# installed (Debian: r-cran-randomfields r-cran-gstat; not needed otherwise):
#   circulant embedding, 2048^2, exponential covariance of scale 16:
#     noiselab synth circulant  vs  RandomFields RFsimulate(RPcirculant(RMexp))
#   ordinary kriging of 1000 random points onto 256^2 with the variance,
#     exponential covariance of range 0.2 on the unit square:
#     noiselab krige --variance  vs  gstat krige (global neighbourhood)
# Times are wall-clock seconds, medians of 5 runs of noiselab (each a new
# process: reading the input, planning (FFTW_ESTIMATE taking the measured
# plans of the wisdom NOISELAB_WISDOM names, which `make bench` sets to the
# file `make wisdom` makes), writing the EXR output), 3 of
# RandomFields and 1 of gstat (a minute each; R's times are the call only).
# First runs on this machine vary by up to 1.7x (page faults in a VM), so
# single runs are not quoted.
# usage: tools/bench-r.sh NOISELAB WORKDIR  -> TSV on stdout
set -eu
nl=$1
w=$2
if ! command -v Rscript > /dev/null || ! Rscript -e 'library(RandomFields); library(gstat)' > /dev/null 2>&1; then
    echo "bench-r: R with RandomFields and gstat is not installed; skipped" >&2
    exit 0
fi
mkdir -p "$w"
now() { date +%s.%N; }
awk 'BEGIN { srand(7); print "x\ty\tvalue"; for (i = 0; i < 1000; i++) printf "%.6f\t%.6f\t%.6f\n", rand(), rand(), rand() }' > "$w/pts.tsv"
# median wall-clock seconds of running "$@" $1 times
med() {
    k=$1
    shift
    for r in $(seq "$k"); do
        a=$(now)
        "$@"
        b=$(now)
        echo "$a $b"
    done | awk '{ print $2 - $1 }' | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
tc=$(med 5 "$nl" synth circulant --acf markov:scale=16 --size 2048x2048 --seed 1 -o "$w/circ.exr")
tk=$(med 3 "$nl" krige --acf markov:scale=0.2 --data "$w/pts.tsv" --grid 256x256 --extent 0:1,0:1 --variance "$w/kv.exr" -o "$w/ke.exr")
cat > "$w/bench.R" <<R
suppressMessages({ library(RandomFields); library(gstat); library(sp) })
RFoptions(spConform = FALSE, install = "no")
t <- replicate(3, system.time(z <- RFsimulate(RPcirculant(RMexp(var = 1, scale = 16)), x = 1:2048, y = 1:2048, grid = TRUE))[["elapsed"]])
cat(median(t), "\n")
d <- read.delim("$w/pts.tsv"); coordinates(d) <- ~x + y
g <- expand.grid(x = (0:255 + 0.5) / 256, y = (0:255 + 0.5) / 256); gridded(g) <- ~x + y
t <- system.time(k <- krige(value ~ 1, d, g, model = vgm(1, "Exp", 0.2), debug.level = 0))
cat(t[["elapsed"]], "\n")
R
set -- $(Rscript "$w/bench.R")
printf 'case\tnoiselab_s\tR_s\tspeedup\n'
awk -v t="$tc" -v r="$1" 'BEGIN { printf "circulant 2048^2 vs RandomFields\t%.2f\t%.2f\t%.1f\n", t, r, r / t }'
awk -v t="$tk" -v r="$2" 'BEGIN { printf "krige 1000 -> 256^2 +variance vs gstat\t%.2f\t%.2f\t%.1f\n", t, r, r / t }'
