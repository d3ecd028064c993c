#!/bin/sh
# The singular Gaussian case (Lewis 1987, "Singular processes"): the
# subdivision matrix of exp(-t^2) loses rank in double precision as the
# spacing shrinks, exp(-|t|) never does.  1D, N = 2, 12 levels from spacing 4.
. "$(dirname "$0")/lib.sh"
for k in gauss markov; do
    "$nl" coeffs --acf $k --dim 1 --levels 12 --spacing0 4 --json > "$d/singular-$k.json"
    jq -r '.levels[] | "\(.level)\t\(.spacing)\t\(.classes[0].condition)\t\(.classes[0].variance)\t\(.classes[0].flags | join(","))"' \
        "$d/singular-$k.json" > "$d/singular-$k.tsv"
done
gnuplot -e "g='$d/singular-gauss.tsv'; m='$d/singular-markov.tsv'; out='$dir/singular-gauss.png'; thr=1e10" "$top/plots/singular.gp"
first=$(awk -F'\t' '$5 ~ /singular/ { print $2; exit }' "$d/singular-gauss.tsv")
nm=$(grep -c singular "$d/singular-markov.tsv" || true)
below=$("$nl" check --acf gauss --dim 1 --json | jq '.singular_below_spacing')
verdict=FAIL
[ -n "$first" ] && [ "$nm" -eq 0 ] && verdict=pass
cat > "$d/45-singular.md" <<MD
## The singular Gaussian case (Lewis 1987, "Singular Processes")

> ... the Gaussian autocorrelation [...] the matrix R becomes numerically singular as the
> spacing decreases (paraphrased; the midpoint of a very smooth process is almost exactly
> predictable from its neighbours).

![singular](singular-gauss.png)

\`noiselab coeffs --acf gauss|markov --dim 1 --levels 12 --spacing0 4 --json\`. Verdict
**$verdict**: the Gaussian's matrix passes the condition threshold (1e10) from spacing $first on,
where \`coeffs\` flags it singular and solves by the pseudo-inverse (and resets the uniform
solution to nearest neighbours at the finest level, as the paper prescribes); the Markovian
matrix is flagged at no level ($nm). \`noiselab check --acf gauss --dim 1\` reports
singular_below_spacing = $below. The displacement variance of the Gaussian falls to rounding
(a negative value is clamped to 0, never used), so finer levels add no detail: the process is
smooth beyond what double precision can represent. The jump at the finest level is the
nearest-neighbour reset: its variance is that of the 0, 1/2, 1/2, 0 predictor, larger than the
(numerically lost) optimum's.

What differs: not a figure of the paper; its claim made visible.
MD

# "Any process whose spectrum falls off faster than f^-1 will be numerically
# singular at small scales": condition number of the N = 2 matrix against the
# spacing for spectra f^-d.  R = exp(-|t|^a) has S ~ f^-(1+a) (d = 1.5, 2,
# 2.5); matern nu has d = 2 nu + 1 (4, 6); the Gaussian falls faster than any
# power.  Scale 1, spacing 4 2^-k, k = 0..39.
set -- "markaussian:alpha=0.5 1.5" "markov 2" "markaussian:alpha=1.5 2.5" "matern:nu=1.5 4" "matern:nu=2.5 6" \
    "gauss inf"
: > "$d/singular-slopes.tsv"
plot=""
for md in "$@"; do
    m=${md% *} dd=${md#* } f=$d/singular-cond-$(echo "$m" | tr -c 'a-z0-9\n' '_').tsv
    "$nl" coeffs --acf "$m" --dim 1 --levels 40 --spacing0 4 --neighborhood 2 --json |
        jq -r '.levels[] | "\(.spacing)\t\(.classes[0].condition // 1e300)\t\(.classes[0].flags | join(",") | if . == "" then "-" else . end)"' > "$f"
    ck=$("$nl" check --acf "$m" --dim 1 --json | jq -r '.singular_below_spacing // 0')
    # least-squares slope of log cond on log spacing over the levels with cond
    # from 30 to 1e9 (the power-law regime before the pseudo-inverse), the
    # first spacing flagged singular, and the spacing where the fitted power
    # law reaches 1e10 (extrapolated when no level reaches it)
    awk -F'\t' -v m="$m" -v dd="$dd" -v ck="$ck" '
        $2 >= 30 && $2 < 1e9 { x = log($1); y = log($2); n++; sx += x; sy += y; sxx += x * x; sxy += x * y }
        first == "" && $3 ~ /singular/ { first = $1 }
        END { if (n < 2) { print m "\t" dd "\t-\t-\t" first "\t-\t-\t" ck "\t" n; exit }
              p = (n * sxy - sx * sy) / (n * sxx - sx * sx); b = (sy - p * sx) / n
              pred = dd == "inf" ? 6 : (dd - 1 < 6 ? dd - 1 : 6)
              sstar = exp((log(1e10) - b) / p)
              printf "%s\t%s\t%.3f\t%g\t%s\t%.3g\t%.1f\t%s\t%d\n", m, dd, -p, pred, first == "" ? "none" : first, sstar,
                  -log(sstar) / log(2), ck, n }' "$f" >> "$d/singular-slopes.tsv"
    t="$m (f^{-$dd})"
    [ "$dd" = inf ] && t="$m (faster than any power)"
    plot="$plot${plot:+, }'$f' using 1:(\$2 < 1e100 ? \$2 : 1/0) with linespoints lw 2 title '$t'"
done
gnuplot <<GP
set terminal pngcairo size 900,560 font "DejaVu Sans,11"
set output '$dir/singular-slopes.png'
set title "Condition number of the 1D subdivision matrix (N = 2) against spacing, R(0) = 1, scale 1"
set logscale xy
set format x "10^{%L}"; set format y "10^{%L}"
set xrange [*:*] reverse
set yrange [1:1e18]
set xlabel "observation spacing s (in correlation scales)"
set ylabel "condition number"
set key bottom right font ",10"
set grid
plot $plot, 1e10 with lines dt 2 lc rgb "red" title "singular beyond this (1e10)", \
     1/2.2e-16 with lines dt 3 lc rgb "black" title "1/eps"
GP
# verdict: the rough models' slopes equal d - 1 to 0.1 (cond ~ s^-(d-1): no
# power-law spectrum steeper than f^-1 stays regular as s -> 0, the paper's
# claim in exact arithmetic), and exp(-|t|) (d = 2) is first flagged more
# than 30 halvings below its scale (beyond any field synthesis can make:
# --levels <= 30), where `check` (24 halvings) is right to stay silent, while
# check flags every differentiable model
v2=$(awk -F'\t' '$2 != "inf" && $2 < 3 { if (($3 - ($2 - 1)) ^ 2 > 0.01) bad = 1 }
    $1 == "markov" { if ($5 == "none" || $5 >= 2 ^ -30 || $8 != 0) bad = 1 }
    $1 == "gauss" || $1 ~ /matern/ { if ($8 == 0) bad = 1 }
    END { print bad ? "FAIL" : "pass" }' "$d/singular-slopes.tsv")
tab=$(awk -F'\t' '{ printf "| %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6, $7, ($8 == 0 ? "none" : $8) }' \
    "$d/singular-slopes.tsv")
mk=$(awk -F'\t' '$1 == "markov" { print $7 }' "$d/singular-slopes.tsv")
mh=$(awk -F'\t' '$2 == 1.5 { printf "%.0f", $7 }' "$d/singular-slopes.tsv")
mkf=$(awk -F'\t' '$1 == "markov" { print $5 }' "$d/singular-slopes.tsv")
cat >> "$d/45-singular.md" <<MD

### "Any spectrum falling faster than f^-1 becomes numerically singular": who is right?

> The considerations mentioned in this section should be kept in mind however, since any process
> whose spectrum falls off faster than f^-1 will be numerically singular at small scales.

![condition numbers](singular-slopes.png)

\`noiselab coeffs --acf MODEL --dim 1 --neighborhood 2 --levels 40 --spacing0 4 --json\` for
spectra f^-d (R(0) = 1, scale 1), the condition number of the 4 x 4 matrix of eq. (4) against the
spacing. Slope: least squares of -log cond on log s over the levels with cond from 30 to 1e9. "Singular at":
the first spacing \`coeffs\` flags (cond > 1e10; none within 40 halvings of 4); "1e10 at": the
fitted power law's spacing for 1e10 (extrapolated), and the number of halvings below the scale.
\`check\` column: \`noiselab check --acf MODEL --dim 1\`'s singular_below_spacing (it scans 24
halvings below the model's scale).

| model | d | slope | predicted min(d - 1, 6) | singular at | 1e10 at | halvings | check |
|---|---|---|---|---|---|---|---|
$tab

Verdict **$v2**. Both are right about different things. In exact arithmetic the paper is right:
for a rough spectrum f^-d (1 < d < 3) the condition number grows as s^-(d-1) (measured slopes
above, predicted d - 1 for R(t) = 1 - c|t|^(d-1) + ...), so every spectrum steeper than f^-1
drives it to infinity as the spacing shrinks; smooth models grow faster, capped by the
neighbourhood (4N - 2 = 6 for N = 2: the Gaussian's slope). In double precision, "numerically
singular at small scales" is a matter of how small: exp(-|t|) (f^-2) is first flagged at spacing
$mkf, more than 30 halvings below its correlation scale (the fit puts 1e10 at $mk halvings): a
field with over 2^30 samples per correlation length, beyond what synthesis can make (at most 30
levels; windows within 2^30 samples); f^-1.5 would need about $mh halvings. \`check\` is right not to flag
exp(-|t|): at every spacing a field can use, its matrix is well conditioned (1e10 means a
relative solution error below 2e-6). Steeper rough spectra (f^-2.5) and every differentiable
model (Matern nu >= 1.5, Gaussian) do become singular within reach, and \`check\` flags them.
MD
[ "$verdict" = pass ] && [ "$v2" = pass ]
