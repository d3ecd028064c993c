#!/bin/sh
# noiselab against gstat on conditional simulation, when R with gstat and
# sp is installed (its Meuse data come from sp): 100 realizations of
# log(zinc) on the 40 m grid whose cell centres are the meuse.grid points,
# vgm(0.59, "Sph", 897, 0.05), ordinary kriging from the 40 nearest data:
#   noiselab synth circulant --condition --nmax 40 --realizations 100
#     (78 x 104 cells, the data between samples drawn given the grid;
#     writing the 100 EXR files included)
#   gstat krige(..., nsim = 100, nmax = 40) on the 3103 meuse.grid points
#     (sequential Gaussian simulation; the call only)
# Wall-clock seconds, the median of 3 runs each; noiselab's CPU seconds
# (user + system, the median) too, a steadier figure on a shared machine.
# usage: tools/bench-condsim.sh NOISELAB WORKDIR  -> TSV on stdout
set -eu
nl=$1
w=$2
if ! command -v Rscript > /dev/null || ! Rscript -e 'library(gstat); library(sp)' > /dev/null 2>&1; then
    echo "bench-condsim: R with gstat and sp is not installed; skipped" >&2
    exit 0
fi
mkdir -p "$w"
Rscript -e 'library(sp); data(meuse);
    write.table(data.frame(x = meuse$x, y = meuse$y, value = log(meuse$zinc)), "'"$w"'/meuse.tsv", sep = "\t",
                row.names = FALSE, quote = FALSE)' > /dev/null
now() { date +%s.%N; }
med3() { printf '%s\n' "$@" | sort -g | sed -n 2p; }
run() { # wall-clock seconds (and CPU seconds into $w/cpu when /usr/bin/time is installed)
    a=$(now)
    if [ -x /usr/bin/time ]; then
        set -- /usr/bin/time -f '%U %S' -a -o "$w/cpu"
    else
        set --
    fi
    "$@" "$nl" synth circulant --acf spherical:var=0.59,scale=897,nugget=0.05 --size 78x104 \
        --extent 178440:181560,329600:333760 --condition "$w/meuse.tsv" --nmax 40 --realizations 100 --seed 1 \
        -o "$w/z.exr" 2> /dev/null
    b=$(now)
    echo "$a $b" | awk '{ print $2 - $1 }'
}
rm -f "$w/cpu"
tn=$(med3 "$(run)" "$(run)" "$(run)")
cpu=$( [ -f "$w/cpu" ] && awk '{ print $1 + $2 }' "$w/cpu" | sort -g | sed -n 2p || echo -)
cat > "$w/bench.R" <<R
suppressMessages({library(gstat); library(sp)})
data(meuse); data(meuse.grid)
coordinates(meuse) <- ~x + y
coordinates(meuse.grid) <- ~x + y
t <- sapply(1:3, function(i) {
    set.seed(i)
    system.time(krige(log(zinc) ~ 1, meuse, meuse.grid, model = vgm(0.59, "Sph", 897, 0.05), nsim = 100,
                      nmax = 40, debug.level = 0))[["elapsed"]]
})
cat(median(t), "\n")
R
tg=$(Rscript "$w/bench.R")
printf 'case\tnoiselab_s\tnoiselab_cpu_s\tgstat_s\tspeedup\n'
awk -v t="$tn" -v c="${cpu:--}" -v r="$tg" 'BEGIN { printf "condsim Meuse 100 realizations nmax 40 vs gstat\t%.2f\t%s\t%.2f\t%.1f\n", t, c, r, r / t }'
