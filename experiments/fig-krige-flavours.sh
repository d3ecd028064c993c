#!/bin/sh
# Block, trans-Gaussian and indicator kriging on fields of a known model
# (experiments/krige_flavours.c): a Markov field Y (variance 0.5, scale 12)
# on 64 x 64 nodes, 150 data nodes per field, Z = exp(Y).  Two sizes:
#   make figures (default): K = 40 fields, about 2 s of one core.
#   make experiments (NOISELAB_FULL=1): K = 400 fields, about 20 s.
. "$(dirname "$0")/lib.sh"
if [ "${NOISELAB_FULL:-0}" = 1 ]; then K=400; else K=40; fi
"$xb/krige_flavours" markov:var=0.5,scale=12 0.5 12 64 150 "$K" > "$d/krige-flavours.tsv"
get() { awk -F'\t' -v q="$1" -v c="$2" '$1 == q { print $c }' "$d/krige-flavours.tsv"; }
# The verdict: each mean within 3 standard errors (over the K independent
# fields) of what it should be: the standardised errors of block and point
# kriging of Y have variance 1 and the block's mean 0; trans-Gaussian
# kriging is unbiased; each indicator's mean probability is its frequency
# (the se of a difference: both se's in quadrature, an upper bound since the
# two are positively correlated).  Power: the plain back-transform exp(pred)
# must show its bias (more than 3 se), else the fields are too few to see one.
verdict=$(awk -F'\t' 'NR > 1 && $1 !~ /^#/ { m[$1] = $2; s[$1] = $3 }
    function near(x, want, se) { return (x - want) * (x - want) <= 9 * se * se }
    END {
        ok = near(m["block_z_var"], 1, s["block_z_var"]) && near(m["block_z_mean"], 0, s["block_z_mean"]) &&
             near(m["point_z_var"], 1, s["point_z_var"]) && near(m["tg_bias"], 0, s["tg_bias"]) &&
             m["exp_pred_bias"] > 3 * s["exp_pred_bias"]
        for (q = 1; q <= 3; q++) {
            a = "ik_p" q "_mean"; b = "ik_p" q "_freq"
            ok = ok && near(m[a], m[b], sqrt(s[a] * s[a] + s[b] * s[b]))
        }
        print ok ? "pass" : "FAIL" }' "$d/krige-flavours.tsv")
rows=$(awk -F'\t' 'NR > 1 && $1 !~ /^#/ { printf "| %s | %s | %s |\n", $1, $2, $3 }' "$d/krige-flavours.tsv")
cat > "$d/97-krige-flavours.md" <<MD
## Block, trans-Gaussian and indicator kriging (noiselab krige --block, --transform, --indicator)

$K Markov fields Y (variance 0.5, scale 12) on 64 x 64 nodes of unit spacing (circulant
embedding, exact; seeds 1 to $K), 150 random nodes of each as data, and the lognormal Z =
exp(Y). Block kriging of Y predicts the means of 36 blocks of 4 x 4 nodes with
\`--block-points 4\`, whose 16 points are the block's nodes: "block_z" are the standardised
errors (truth - estimate) / sqrt(variance), which should have mean 0 and variance 1
("point_z_var": point kriging of Y at 64 other nodes). At those 64 nodes Z is predicted by
trans-Gaussian kriging (log; "tg") and by the back-transforms exp(pred) and exp(pred + var/2)
of the ordinary kriging of Y: their mean errors ("bias") and root mean square errors. Indicator
kriging of Z at exp(-sigma), 1 and exp(sigma) (P(Z <= t) = 0.159, 0.5, 0.841; Markov models of
scale 12 and variance p(1 - p)): the mean corrected probability, the frequency of Z <= t and
the Brier score (the marginal's alone scores p(1 - p): 0.134, 0.25, 0.134), and the share of
nodes whose probabilities the order-relation correction changed. Means over the fields, with
their standard errors.

| quantity | mean | se |
|---|---|---|
$rows

Verdict (block and point z variances 1 and block z mean 0, trans-Gaussian bias 0, each mean
probability its frequency, all within 3 se; exp(pred)'s bias seen, above 3 se): $verdict.
exp(pred + var/2), the lognormal back-transform of simple kriging, is nearly unbiased here
too: with all 150 data in every neighbourhood the Lagrange multiplier is near 0 and the
generalised-least-squares mean near the truth's, where trans-Gaussian kriging (Cressie 1993,
eq. 3.2.40; gstat's krigeTg) and it agree to first order.
MD
[ "$verdict" = pass ]
