#!/bin/sh
# The spectral slope of psd --slope on band-limited power laws
# (experiments/slope_band.c): 200 realizations (seeds 1..200) each of
# power:d=1 on 65536 samples and power:d=3,fmin=0.02 on 256 x 256, fitted
# inside the model's band and through its lower edge (the band psd --slope
# now refuses for such a field).
. "$(dirname "$0")/lib.sh"
K=${K:-200}
{
    printf 'model\tN\tdim\tF1\tF2\tmean\tse_mean\tsd\tfit_se\tcoverage\n'
    "$xb/slope_band" power:d=1 1 65536 1 "$K" 0.0009765625 0.4
    "$xb/slope_band" power:d=1 1 65536 1 "$K" 0.0001 0.4
    "$xb/slope_band" power:d=3,fmin=0.02 3 256 2 "$K" 0.02 0.5
    "$xb/slope_band" power:d=3,fmin=0.02 3 256 2 "$K" 0.004 0.5
} > "$d/slope-band.tsv"
row() { sed -n "$(($1 + 1))p" "$d/slope-band.tsv"; }
# inside the band: mean within 3 standard errors of -d; the scatter within
# 15% of the fit's reported error (3 standard errors of a standard
# deviation over 200 draws, 1/sqrt(400) = 5% each); coverage of the 95%
# interval within 3 binomial standard errors (1.5%); through the edge the
# mean is off by more than 0.5
ok() { # row d
    row "$1" | awk -F'\t' -v d="$2" '{ exit !(($6 + d) ^ 2 <= 9 * $7 ^ 2 && $8 >= 0.85 * $9 && $8 <= 1.15 * $9 &&
                                               $10 >= 0.904 && $10 <= 0.996) }'
}
off() { row "$1" | awk -F'\t' -v d="$2" '{ exit !(($6 + d) ^ 2 > 0.25) }'; }
verdict=pass
ok 1 1 && off 2 1 && ok 3 3 && off 4 3 || verdict=FAIL
cell() { row "$1" | cut -f"$2"; }
cat > "$d/94-slope-band.md" <<MD
## The spectral slope inside the model's band (noiselab psd --slope)

$K realizations (seeds 1 to $K) of each field, rounded to the 10 digits a TSV file keeps, then
the periodogram and the least-squares slope of its log over [F1, F2] (\`psd --slope\`): the mean
slope with its standard error, the scatter of the slopes, the standard error the fit reports
(from its residuals; \`analysis/slope.h\`) and how often its 95% interval holds -d.

| field | band | mean slope | scatter | fit's error | coverage |
|---|---|---|---|---|---|
| power:d=1, 65536 | [fmin = 1/1024, 0.4] | $(cell 1 6) ± $(cell 1 7) | $(cell 1 8) | $(cell 1 9) | $(cell 1 10) |
| power:d=1, 65536 | [0.0001, 0.4] | $(cell 2 6) ± $(cell 2 7) | $(cell 2 8) | $(cell 2 9) | $(cell 2 10) |
| power:d=3,fmin=0.02, 256 x 256 | [fmin = 0.02, 0.5] | $(cell 3 6) ± $(cell 3 7) | $(cell 3 8) | $(cell 3 9) | $(cell 3 10) |
| power:d=3,fmin=0.02, 256 x 256 | [0.004, 0.5] | $(cell 4 6) ± $(cell 4 7) | $(cell 4 8) | $(cell 4 9) | $(cell 4 10) |

Verdict (inside the band: the mean within 3 of its standard errors of -d, the scatter within
15% of the fit's error, coverage 90.4% to 99.6%; through fmin: off by more than 0.5): $verdict.
Below fmin the field holds no power, and its periodogram only rounding; the fit through those
ordinates is flattened and its interval, too wide yet never holding -d, says nothing of it.
\`psd --slope\` refuses such a band for a field whose file records its model.
MD
[ "$verdict" = pass ]
