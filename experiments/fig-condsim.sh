#!/bin/sh
# Conditional simulation with data between grid samples has the kriging
# mean and variance (experiments/condsim_meuse.c): 200 realizations on
# Meuse (log(zinc), 155 points, the 40 m grid whose cell centres are the
# meuse.grid points; gstat's vgm(0.59, "Sph", 897, 0.05)) and on 150
# random points of a 64 x 64 grid (Matern nu = 1.5, smooth: the hardest
# case for the screening; and exponential), for fft, circulant and
# subdiv, global and nmax 40.  Subdivision represents no nugget (its Meuse
# rows use the model without it) and is not exact for the Matern (its own
# covariance error, not conditioning's: not run there).  Needs R's sp package for Meuse (skipped without it).
. "$(dirname "$0")/lib.sh"
md=$d/60-condsim.md
{
    echo "## Conditional simulation with data between samples"
    echo
    echo "200 realizations (seeds 1..200); z = (ensemble mean - kriging estimate) / sqrt(kriging variance / 200)"
    echo "(rms 1 when exact); ratio = ensemble variance / kriging variance averaged over the cells (1 when"
    echo "exact), its range over the cells; screening: the stated error of drawing the data given 4 x 4 samples."
    echo "Hood 2 and 6 rows compare the neighbourhood's size (the default, 4, is judged)."
    echo
    echo "| data | method | hood | nmax | K | rms z | ratio | range | screening | plan s | realizations s | verdict |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
} > "$md"
fail=0
if Rscript -e 'library(sp)' >/dev/null 2>&1; then
    Rscript -e 'library(sp); data(meuse); data(meuse.grid);
        write.table(data.frame(x = meuse$x, y = meuse$y, value = log(meuse$zinc)), "'"$d"'/meuse.tsv",
                    sep = "\t", row.names = FALSE, quote = FALSE);
        write.table(data.frame(x = meuse.grid$x, y = meuse.grid$y, value = 0), "'"$d"'/meuse-cells.tsv",
                    sep = "\t", row.names = FALSE, quote = FALSE)' >/dev/null
    m=spherical:var=0.59,scale=897
    "$xb/condsim_meuse" "$md" "$d/meuse.tsv" "$d/meuse-cells.tsv" "$m,nugget=0.05" 78 104 178440 329600 40 200 \
        meuse fft,circulant || fail=1
    "$xb/condsim_meuse" "$md" "$d/meuse.tsv" "$d/meuse-cells.tsv" "$m,nugget=0.05" 78 104 178440 329600 40 200 \
        meuse circulant 2,6 || fail=1
    "$xb/condsim_meuse" "$md" "$d/meuse.tsv" "$d/meuse-cells.tsv" "$m" 78 104 178440 329600 40 200 \
        meuse-no-nugget subdiv || fail=1
else
    echo "(Meuse skipped: R's sp package is not installed.)" >> "$md"
fi
# 150 points at uniform positions (seed 5) of a 64 x 64 Matern field of
# spacing 1, extent 0:64; the values from one realization (seed 3) read
# by bilinear interpolation; every cell is checked.
"$nl" synth circulant --acf matern:nu=1.5,scale=6 --size 64x64 --seed 3 -o "$d/condsim-truth.exr" 2>/dev/null
"$nl" sample "$d/condsim-truth.exr" --random 150 --seed 5 | awk 'BEGIN { print "x\ty\tvalue" }
    $1 ~ /^[-0-9.]/ { print $1 + 0.5 "\t" $2 + 0.5 "\t" $3 }' > "$d/condsim-points.tsv"
awk 'BEGIN { print "x\ty\tvalue"; for (j = 0; j < 64; j++) for (i = 0; i < 64; i++) print i + 0.5 "\t" j + 0.5 "\t0" }' \
    > "$d/condsim-cells.tsv"
"$xb/condsim_meuse" "$md" "$d/condsim-points.tsv" "$d/condsim-cells.tsv" matern:nu=1.5,scale=6 64 64 0 0 1 200 \
    matern fft,circulant || fail=1
"$xb/condsim_meuse" "$md" "$d/condsim-points.tsv" "$d/condsim-cells.tsv" markov:scale=6 64 64 0 0 1 200 \
    markov fft,circulant,subdiv || fail=1
echo >> "$md"
[ "$fail" -eq 0 ]
