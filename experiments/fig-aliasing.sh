#!/bin/sh
# Aliasing across subdivision levels (Lewis 1987, "Aliasing"): for each
# level k of the Fig. 2 set-up (coarse spacing 2, spacing 2/2^k), a periodic
# 4096-sample field (seed 7) and the energy that changes when it is viewed
# one level down, measured and predicted from the spectrum; the oscillatory
# cos(10 t) exp(-t^2) against the monotone exp(-|t|).
. "$(dirname "$0")/lib.sh"
printf 'level\tosc\tosc_pred\tmarkov\tmarkov_pred\tosc_correlated\n' > "$d/aliasing.tsv"
fail=0
for k in 2 3 4 5 6 7 8 9; do
    h=$(awk -v k=$k 'BEGIN { printf "%.17g", 2 / 2 ^ k }')
    row=$k
    for spec in gauss-osc:omega=10 markov; do
        "$nl" synth subdiv --acf $spec --size 4096 --levels $k --spacing "$h" --seed 7 -o "$d/alias.tsv"
        j=$("$nl" detect "$d/alias.tsv" --levels $k --acf $spec --json)
        a=$(echo "$j" | sed -n 's/.*"aliasing":\([0-9.e+-]*\),.*/\1/p')
        p=$(echo "$j" | sed -n 's/.*"aliasing_predicted":\([0-9.e+-]*\),.*/\1/p')
        row="$row	$a	$p"
        # measured and predicted must fall on the same side of the threshold
        awk -v a="$a" -v p="$p" 'BEGIN { exit !((a > 0.1) == (p > 0.1)) }' || fail=$((fail + 1))
    done
    # the oscillatory noise again with correlated displacements
    "$nl" synth subdiv --acf gauss-osc:omega=10 --size 4096 --levels $k --spacing "$h" --seed 7 \
        --displacements correlated -o "$d/alias.tsv"
    a=$("$nl" detect "$d/alias.tsv" --levels $k --acf gauss-osc:omega=10 --json |
        sed -n 's/.*"aliasing":\([0-9.e+-]*\),.*/\1/p')
    row="$row	$a"
    printf '%s\n' "$row" >> "$d/aliasing.tsv"
done
rm -f "$d/alias.tsv"
gnuplot -e "data='$d/aliasing.tsv'; out='$dir/aliasing.png'" "$top/plots/aliasing.gp"
worst=$(awk 'NR > 1 && $2 > m { m = $2; k = $1 } END { printf "%.2f at level %d", m, k }' "$d/aliasing.tsv")
fine=$(awk 'NR > 1 && $1 >= 5 && $4 > m { m = $4 } END { printf "%.4f", m }' "$d/aliasing.tsv")
excess=$(awk 'NR > 1 && $1 >= 4 && $2 - $3 > m { m = $2 - $3 } END { printf "%.3f", m }' "$d/aliasing.tsv")
excessc=$(awk 'NR > 1 && $1 >= 4 && $6 - $3 > m { m = $6 - $3 } END { printf "%.3f", m }' "$d/aliasing.tsv")
verdict=pass
[ "$fail" -eq 0 ] || verdict=FAIL
cat > "$d/40-aliasing.md" <<MD
## Aliasing across levels (Lewis 1987, "Aliasing")

> For example, the perceived noise in Figure 2 would change significantly between construction
> levels three and four if these were used as keyframes in a zoom.

![aliasing](aliasing.png)

Each point is one periodic field made with k levels from coarse samples 2 apart (the set-up
of the Fig. 2 reproduction), measured by \`noiselab detect\`: the energy by which every other
sample differs from the low-passed, decimated field, over the variance. Verdict: the oscillatory
noise peaks at $worst (its spectral peak at 1.6 cycles per unit lies between half Nyquist and
Nyquist there); exp(-|t|) stays at most $fine from level 5 on; measurement and the prediction
from the spectrum agree on the side of the 0.1 threshold at every level: $verdict ($fail
disagreements).

What differs: our level numbers count from coarse samples 2 apart, which the paper does not
give; its "levels three and four" are the transition where the spectral peak crosses half the
Nyquist rate, our levels 3 to 2. From level 4 on, the oscillatory field's measured aliasing is
far above the prediction (which is zero to rounding): the subdivision field has more energy
above half Nyquist than its target has, another face of the method's own error (the exact
covariance of subdivision fields is computed in analysis/subdiv_exact.c): at most $excess
above the prediction from level 4 on. With correlated displacements (\`--displacements
correlated\`, last column of data/aliasing.tsv) the excess is at most $excessc.
MD
[ "$fail" -eq 0 ]
