#!/bin/sh
# noiselab against R in one run, when R with RandomFields and gstat is
# installed (Debian: r-cran-randomfields r-cran-gstat; not needed otherwise):
#   circulant embedding, 2048^2, exponential covariance of scale 16:
#     noiselab synth circulant  vs  RandomFields RFsimulate(RPcirculant(RMexp))
#   ordinary kriging of 1000 random points onto 256^2 with the variance,
#     exponential covariance of range 0.2 on the unit square:
#     noiselab krige --variance  vs  gstat krige (global neighbourhood)
# Times are wall-clock seconds of one run each; noiselab's include reading
# the input and writing the EXR output, R's only the call.
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
t0=$(now)
"$nl" synth circulant --acf markov:scale=16 --size 2048x2048 --seed 1 -o "$w/circ.exr"
t1=$(now)
"$nl" krige --acf markov:scale=0.2 --data "$w/pts.tsv" --grid 256x256 --extent 0:1,0:1 --variance "$w/kv.exr" -o "$w/ke.exr"
t2=$(now)
cat > "$w/bench.R" <<R
suppressMessages({ library(RandomFields); library(gstat); library(sp) })
RFoptions(spConform = FALSE, install = "no")
t <- system.time(z <- RFsimulate(RPcirculant(RMexp(var = 1, scale = 16)), x = 1:2048, y = 1:2048, grid = TRUE))
cat(t[["elapsed"]], "\n")
d <- read.delim("$w/pts.tsv"); coordinates(d) <- ~x + y
g <- expand.grid(x = (0:255 + 0.5) / 256, y = (0:255 + 0.5) / 256); gridded(g) <- ~x + y
t <- system.time(k <- krige(value ~ 1, d, g, model = vgm(1, "Exp", 0.2), debug.level = 0))
cat(t[["elapsed"]], "\n")
R
set -- $(Rscript "$w/bench.R")
printf 'case\tnoiselab_s\tR_s\tspeedup\n'
awk -v a="$t0" -v b="$t1" -v r="$1" 'BEGIN { printf "circulant 2048^2 vs RandomFields\t%.2f\t%.2f\t%.1f\n", b - a, r, r / (b - a) }'
awk -v a="$t1" -v b="$t2" -v r="$2" 'BEGIN { printf "krige 1000 -> 256^2 +variance vs gstat\t%.2f\t%.2f\t%.1f\n", b - a, r, r / (b - a) }'
