#!/bin/sh
# Conditional realizations at the points of a table (synth --condition
# --at, cli/synth_condition.c) have the kriging mean and variance there
# (krige --at on the same table): 150 data at uniform positions of a
# 64 x 64 field (as fig-condsim.sh), 100 points at cell corners (midway
# between four cell centres, where reading the grid by bilinear
# interpolation loses variance), K = 1000 realizations (NOISELAB_FULL:
# 4000) by circulant embedding, exponential and Matern nu = 1.5 models,
# global and nmax 40.  Per point: z = (ensemble mean - estimate) /
# sqrt(variance / K) ~ N(0, 1), ratio = mean square about the estimate /
# kriging variance, K ratio ~ chi2_K; verdict at a family-wise
# false-alarm rate of 1e-3 over the points (Bonferroni, split between
# the two tests).
. "$(dirname "$0")/lib.sh"
md=$d/61-synth-at.md
K=1000
[ -n "${NOISELAB_FULL:-}" ] && K=4000
{
    echo "## Conditional realizations at the points of a table"
    echo
    echo "\`synth circulant --condition data.tsv --extent 0:64,0:64 --at pts.tsv --realizations $K\` against"
    echo "\`krige --at pts.tsv\`: 150 data between samples, 100 points at cell corners (midway between"
    echo "four cell centres). z = (ensemble mean - estimate) / sqrt(variance / K), ratio = mean square"
    echo "about the estimate / kriging variance (1 when exact; its standard deviation sqrt(2/K))."
    echo
    echo "| model | nmax | K | rms z | max abs z (band) | mean ratio | ratio range (band) | seconds | verdict |"
    echo "|---|---|---|---|---|---|---|---|---|"
} > "$md"
"$nl" synth circulant --acf matern:nu=1.5,scale=6 --size 64x64 --seed 3 -o "$d/at-truth.exr" 2>/dev/null
"$nl" sample "$d/at-truth.exr" --random 150 --seed 5 | awk 'BEGIN { print "x\ty\tvalue" }
    $1 ~ /^[-0-9.]/ { print $1 + 0.5 "\t" $2 + 0.5 "\t" $3 }' > "$d/at-data.tsv"
awk 'BEGIN { srand(17); print "id\tx\ty"
            for (j = 0; j < 100; j++) print j + 1 "\t" 1 + int(63 * rand()) "\t" 1 + int(63 * rand()) }' \
    > "$d/at-points.tsv"
# the bands: Bonferroni over the 100 points, 1e-3 split in 4 (two tests, two tails)
bands=$(python3 -c "
from scipy.stats import norm, chi2
a = 1e-3 / 400
print(norm.isf(a), chi2.ppf(a, $K) / $K, chi2.isf(a, $K) / $K)" 2>/dev/null) ||
    bands=$(Rscript -e "a <- 1e-3 / 400; cat(qnorm(a, lower.tail = FALSE), qchisq(a, $K) / $K,
                        qchisq(a, $K, lower.tail = FALSE) / $K)")
fail=0
for model in markov:scale=6 matern:nu=1.5,scale=6; do
    for nmax in 0 40; do
        opt=""
        [ "$nmax" -gt 0 ] && opt="--nmax $nmax"
        start=$(date +%s.%N)
        # shellcheck disable=SC2086
        "$nl" synth circulant --acf "$model" --size 64x64 --condition "$d/at-data.tsv" --extent 0:64,0:64 \
            --at "$d/at-points.tsv" --realizations "$K" --seed 1 $opt -o "$d/at-sim.tsv" 2>/dev/null
        secs=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
        # shellcheck disable=SC2086
        "$nl" krige --data "$d/at-data.tsv" --acf "$model" --at "$d/at-points.tsv" $opt -o "$d/at-krige.tsv"
        row=$(awk -v K="$K" -v bands="$bands" '
            BEGIN { split(bands, b, " "); zc = b[1]; lo = b[2]; hi = b[3] }
            FNR == 1 { next }
            NR == FNR { est[FNR] = $4; var[FNR] = $5; next }
            { s1 = 0; s2 = 0
              for (k = 4; k < 4 + K; k++) { e = $k - est[FNR]; s1 += e; s2 += e * e }
              z = s1 / K / sqrt(var[FNR] / K); r = s2 / K / var[FNR]
              zz += z * z; n++; az = z < 0 ? -z : z; if (az > zmax) zmax = az
              rs += r; if (n == 1 || r < rmin) rmin = r; if (r > rmax) rmax = r
              if (az > zc || r < lo || r > hi) bad++ }
            END { printf "%.2f | %.2f (%.2f) | %.3f | %.3f..%.3f (%.3f..%.3f) | %s", sqrt(zz / n), zmax, zc, rs / n,
                         rmin, rmax, lo, hi, bad ? "FAIL" : "pass" }' "$d/at-krige.tsv" "$d/at-sim.tsv")
        verdict=${row##*| }
        echo "| $model | $nmax | $K | ${row% | *} | $secs | $verdict |" >> "$md"
        [ "$verdict" = pass ] || fail=1
    done
done
echo >> "$md"
cat "$md"
[ "$fail" -eq 0 ]
