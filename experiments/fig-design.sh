#!/bin/sh
# Beyond GI '86 section 4.1 ("has not been formulated"): designing the
# Gaussian input whose output after a nonlinearity has a wanted ACF, and the
# round trip through synthesis, shaping and measurement (16 realizations of
# 65536 samples each).
. "$(dirname "$0")/lib.sh"
"$nl" nonlin --design --target markov:scale=8 --g laplace --size 65536 --verify 16 -o "$d/design-laplace.tsv"
"$nl" nonlin --design --target 'expr:cos(0.3*t)*exp(-abs(t)/20)' --g chi2-1 --size 65536 --verify 16 -o "$d/design-chi2.tsv"
gnuplot -e "a='$d/design-laplace.tsv'; b='$d/design-chi2.tsv'; out='$dir/design-round-trip.png'" "$top/plots/design.gp"
la=$("$nl" nonlin --design --target markov:scale=8 --g laplace --size 65536 --verify 16 --json | sed -n 's/.*"projection_error":\([^,]*\),.*"measured_error":\([^,}]*\).*/projection \1, measured \2/p' | awk '{ for (i = 1; i <= NF; i++) { v = $i; sub(/,$/, "", v); if (v + 0 == v && v != "") $i = sprintf("%.2g%s", v, ($i ~ /,$/) ? "," : "") } print }')
lb=$("$nl" nonlin --design --target 'expr:cos(0.3*t)*exp(-abs(t)/20)' --g chi2-1 --size 65536 --verify 16 --json | sed -n 's/.*"projection_error":\([^,]*\),"unreachable_lags":\([0-9]*\),.*"measured_error":\([^,}]*\).*/projection \1 (\2 unreachable lags), measured \3/p' | awk '{ for (i = 1; i <= NF; i++) { v = $i; sub(/,$/, "", v); if (v + 0 == v && v != "") $i = sprintf("%.2g%s", v, ($i ~ /,$/) ? "," : "") } print }')
cat > "$d/65-design.md" <<MD
## Designing the input for a wanted output spectrum (beyond GI '86, section 4.1)

> In theory it should be possible to design the spectrum of the undistorted noise so that a
> desired spectrum is achieved *after* distortion, but this approach has not been formulated to
> the author's knowledge.

![design](design-round-trip.png)

\`noiselab nonlin --design --target SPEC --g DIST --verify 16\`: Beckmann's series inverted lag by
lag, the result projected onto the nearest valid (non-negative) spectrum, then 16 fields
synthesised from it, shaped and measured. Errors are the largest |output ACF - target| over the
first 129 lags, relative to the output variance.

- exp(-|t|/8) after a Laplace shaping: $la (the measured error is sampling error).
- cos(0.3t) exp(-|t|/20) after the squared-Gaussian (chi2-1) map: $lb. A one-sided map cannot
  produce the target's strong negative correlations; the design reports the lags it cannot
  reach and delivers the nearest valid input, and measurement agrees with its prediction.
MD
