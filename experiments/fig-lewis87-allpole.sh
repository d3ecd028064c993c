#!/bin/sh
# Lewis 1987, eq. (8): the midpoint estimator as a non-causal all-pole filter
# H(z), and the claim that "a minimum neighborhood size of four is needed to
# produce an oscillatory noise" (experiments/lewis87_allpole.c): poles and
# response of the estimator for N = 1..6 on cos(2 pi t / 6) exp(-|t| / 8), and
# the exact ACF of the fields it makes (1024 samples, 7 levels, white coarse
# grid).
. "$(dirname "$0")/lib.sh"
"$xb/lewis87_allpole" "$d/allpole-resp.tsv" "$d/allpole-poles.tsv" "$d/allpole-acf.tsv" "$d/allpole-summary.tsv"
gnuplot <<GP
set terminal pngcairo size 1500,470 font "DejaVu Sans,11"
set output '$dir/lewis87-allpole.png'
set multiplot layout 1,3 title "Eq. (8): the estimator of the level of spacing 4 as an all-pole filter, R = cos(2{/Symbol p}t/6) exp(-|t|/8)"
set title "|H(e^{i{/Symbol q}})|^2 = 1 / D({/Symbol q})^2"
set logscale y
set yrange [0.1:1e4]
set xlabel "{/Symbol q} / {/Symbol p} (the level's fine grid; the model's peak at 2/3)"
set key top left
set grid
set arrow 1 from 2.0/3, 0.1 to 2.0/3, 1e4 nohead dt 2 lc rgb "gray"
plot '$d/allpole-resp.tsv' index 0 using 3:4 with lines lw 2 lc rgb "#9400d3" title "N = 1 (2 points)", \
     '' index 1 using 3:4 with lines lw 2 lc rgb "#009e73" title "N = 2 (4 points)", \
     '' index 3 using 3:4 with lines lw 2 lc rgb "#56b4e9" title "N = 4", \
     '' index 5 using 3:4 with lines lw 2 dt 2 lc rgb "#e69f00" title "N = 6"
unset arrow 1
unset logscale y
set title "poles (roots of z^{2N-1} D(z)) and the unit circle"
set size ratio -1
set xrange [-2.2:2.2]; set yrange [-1.6:2.3]
set xlabel "Re z"; set ylabel "Im z"
set key top center horizontal
set parametric
set trange [0:2*pi]
plot cos(t), sin(t) with lines lc rgb "gray" title "|z| = 1", \
     '$d/allpole-poles.tsv' index 0 using 2:3 with points pt 7 ps 1.6 lc rgb "#9400d3" title "N = 1", \
     '' index 1 using 2:3 with points pt 5 ps 1.3 lc rgb "#009e73" title "N = 2", \
     '' index 3 using 2:3 with points pt 9 ps 1.1 lc rgb "#56b4e9" title "N = 4"
unset parametric
set size noratio
set title "exact ACF of the synthesised field (all levels)"
set autoscale
set xrange [0:40]; set yrange [-0.8:1.05]
set xlabel "lag (samples)"; set ylabel "R / R(0)"
set key top right vertical
plot '$d/allpole-acf.tsv' index 0 using 2:4 with lines lw 3 lc rgb "black" title "target", \
     '' index 0 using 2:3 with linespoints pt 7 ps 0.6 lw 2 lc rgb "#9400d3" title "N = 1", \
     '' index 1 using 2:3 with linespoints pt 5 ps 0.6 lw 2 lc rgb "#009e73" title "N = 2", \
     '' index 3 using 2:3 with lines lw 2 dt 2 lc rgb "#56b4e9" title "N = 4"
unset multiplot
GP
tc=$(awk 'NF == 4 && $1 == 1 { if ($2 > 0 && ($4 < 0) != (p < 0)) n++; p = $4 } END { print n }' "$d/allpole-acf.tsv")
# verdict: (i) the paper's pole argument, per stage: the two-point filter has
# no damped complex pole pair at any level (its complex poles, when |a_0| >
# 1/2, lie on the unit circle), four points have one at the level of
# spacing 4 with its interior peak within 0.1 pi of 2 pi / 3; (ii) across
# stages ("the cumulative spectral definition ... is greater than one would
# expect on the basis of the neighborhood size alone"): the two-point
# field's ACF changes sign as often as the target's (+-1), but its error is
# at least 3 times the four-point field's
verdict=$(awk -F'\t' -v tc="$tc" '
    $1 == 1 { d1 = $7; u1 = $8; c1 = $5; e1 = $6 }
    $1 == 2 { x2 = $3; p2 = $4; e2 = $6 }
    END { ok = d1 == 0 && x2 >= 4 && (p2 - 2 / 3) ^ 2 <= 0.01 && (c1 - tc) ^ 2 <= 1 && e1 >= 3 * e2
          print ok ? "pass" : "FAIL" }' "$d/allpole-summary.tsv")
tab=$(awk -F'\t' '{ printf "| %d | %d | %d | %d | %s | %d | %.3f |\n", $1, 2 * $1, $7, $8, $4 == "nan" ? "-" : $4, $5, $6 }' \
    "$d/allpole-summary.tsv")
e1=$(awk -F'\t' '$1 == 1 { print $6 }' "$d/allpole-summary.tsv")
e2=$(awk -F'\t' '$1 == 2 { print $6 }' "$d/allpole-summary.tsv")
cat > "$d/29-allpole.md" <<MD
## Lewis 1987, eq. (8): the estimator as an all-pole filter, and "a neighbourhood of four"

> The Z-transform of (3) [...] is H(z) = 1 / (1 - sum_k a_k (z^(2k+1) + z^(-2k-1))) (8), which is
> a noncausal "all pole" filter. [...] Since the estimation filter is non-causal and symmetric,
> each spectrum peak will actually correspond to *two* conjugate pole pairs located at inverse
> positions inside and outside the "Z-plane" unit circle. This suggests that a minimum
> neighborhood size of four is needed to produce an oscillatory noise by stochastic subdivision.

![all-pole](lewis87-allpole.png)

\`build/experiments/lewis87_allpole\`: R = cos(2 pi t / 6) exp(-|t| / 8) (period 6, not a power of
two times the spacing), a periodic 1D field of 1024 samples in 7 levels from spacing 128, where R is
e^-16 (the coarse grid is white: every oscillation comes from refinement). For each N the
coefficients of eq. (4) at each level, D(theta) = 1 - 2 sum_k a_k cos((2k+1) theta), the 4N - 2
roots of z^(2N-1) D(z) (gsl_poly_complex_solve), and the exact ACF of the synthesised field
(covariance propagated through the levels, analysis/subdiv_exact.h). Left and middle: the level of
spacing 4, whose fine grid has the model's peak at theta = 2 pi / 3.

| N | points | damped complex poles (all levels) | complex poles on the unit circle | interior peak theta/pi (spacing 4) | sign changes of the field's ACF, lags 0..40 (target $tc) | max error / R(0) |
|---|---|---|---|---|---|---|
$tab

Verdict **$verdict**. The pole argument holds stage by stage: with two points the denominator
z D(z) = -a_0 (z^2 - z / a_0 + 1) has a reciprocal pair of roots, real when |a_0| < 1/2 and, when
|a_0| > 1/2, a conjugate pair *on* the unit circle (an undamped pole: the response is infinite at
one frequency) - never the damped conjugate pair with its inverse that a spectral peak of finite
width needs; four points (N = 2) have it, and the peak of the level of spacing 4 sits near the
model's (table). But the paper's next sentence is the one that decides the field: "the
cumulative spectral definition produced by the subdivision approach is greater than one would
expect on the basis of the neighborhood size alone". A two-point subdivision *does* make an
oscillatory noise here: its ACF changes sign as often as the target's, because the level whose
two-point coefficient is negative (R(s/2) < 0) alternates its new points and the finer levels
interpolate them; what it gets wrong is the amplitude: error $e1 of R(0) against $e2 with four
points, little better beyond (Table 1's oscillatory model needs no more than four either). So
"four are needed" is right for a single stage's filter, and for an accurate oscillatory ACF; for
oscillation as such, two points suffice through the levels. The verdict fails if the two-point
filter has a damped complex pair at any level, if four points have none or misplace the peak by
more than 0.1 pi, if the two-point field stops oscillating, or if four points do not cut the error
at least threefold.

What differs: not a figure of the paper; the paper's argument made measurable.
MD
[ "$verdict" = pass ]
