#!/bin/sh
# noiselab against gstat on the geostatistics tasks of `noiselab bench`,
# when R with gstat is installed (Debian: r-cran-gstat):
#   the variogram of 100,000 uniform points of the unit square (gstat's
#     default cutoff and 15 bins): noiselab variogram  vs  gstat variogram()
#   ordinary kriging of them onto 1000 x 1000 cell centres with the
#     variance, exponential covariance of range 0.05, the 32 nearest data:
#     noiselab krige --nmax 32  vs  gstat krige(..., nmax = 32)
# One run each (minutes for gstat); wall-clock seconds; noiselab's include
# reading the table and writing the EXR, R's are the call only.  Peak
# memory of noiselab's process from /usr/bin/time when it is installed.
# usage: tools/bench-gstat.sh NOISELAB WORKDIR [POINTS GRID]  -> TSV on stdout
set -eu
nl=$1
w=$2
np=${3:-100000}
g=${4:-1000}
if ! command -v Rscript > /dev/null || ! Rscript -e 'library(gstat)' > /dev/null 2>&1; then
    echo "bench-gstat: R with gstat is not installed; skipped" >&2
    exit 0
fi
mkdir -p "$w"
now() { date +%s.%N; }
awk -v n="$np" 'BEGIN { srand(7); print "x\ty\tvalue"; for (i = 0; i < n; i++) printf "%.6f\t%.6f\t%.6f\n", rand(), rand(), rand() }' > "$w/pts.tsv"
peak() { # seconds and peak MB of "$@"
    if [ -x /usr/bin/time ]; then
        /usr/bin/time -f '%e %M' -o "$w/time.txt" "$@" > /dev/null
        awk '{ printf "%s %.0f\n", $1, $2 / 1024 }' "$w/time.txt"
    else
        a=$(now); "$@" > /dev/null; b=$(now)
        echo "$a $b" | awk '{ print $2 - $1, "-" }'
    fi
}
set -- $(peak "$nl" variogram "$w/pts.tsv" -o "$w/vg.tsv")
tv=$1 mv=$2
set -- $(peak "$nl" krige --data "$w/pts.tsv" --acf markov:scale=0.05 --grid "${g}x$g" --extent 0:1,0:1 --nmax 32 \
    -o "$w/k.exr" --variance "$w/kv.exr")
tk=$1 mk=$2
cat > "$w/bench.R" <<R
suppressMessages(library(gstat))
d <- read.delim("$w/pts.tsv")
t <- system.time(v <- variogram(value ~ 1, ~x + y, d))
cat(t[["elapsed"]], "\n")
gr <- expand.grid(x = (0:($g - 1) + 0.5) / $g, y = (0:($g - 1) + 0.5) / $g)
t <- system.time(k <- krige(value ~ 1, ~x + y, d, gr, model = vgm(1, "Exp", 0.05), nmax = 32, debug.level = 0))
cat(t[["elapsed"]], "\n")
R
set -- $(Rscript "$w/bench.R")
printf 'case\tnoiselab_s\tnoiselab_peak_MB\tgstat_s\tspeedup\n'
awk -v t="$tv" -v m="$mv" -v r="$1" -v n="$np" 'BEGIN { printf "variogram %d points vs gstat\t%.2f\t%s\t%.2f\t%.1f\n", n, t, m, r, r / t }'
awk -v t="$tk" -v m="$mk" -v r="$2" -v n="$np" -v g="$g" 'BEGIN { printf "krige %d points -> %d^2 nmax 32 +variance vs gstat\t%.2f\t%s\t%.2f\t%.1f\n", n, g, t, m, r, r / t }'
