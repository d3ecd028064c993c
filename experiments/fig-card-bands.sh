#!/bin/sh
# The coverage of the card's bands (experiments/card_bands.c): 400 fields of
# markov:scale=8, 1D of 1024 and 2D of 128 x 128 (seeds 1..400), each band
# promising 95%.
. "$(dirname "$0")/lib.sh"
"$xb/card_bands" markov:scale=8 1024 128 400 > "$d/card-bands.tsv"
verdict=pass
awk -F'\t' 'NR > 1 && ($3 < 0.92 || $3 > 0.98) { bad = 1 } END { exit bad }' "$d/card-bands.tsv" || verdict=FAIL
{
    cat <<MD
## The card's bands: how often they hold a field of the model

400 fields of markov:scale=8 (seeds 1 to 400): exact stationary fields by circulant embedding
for the ACF and the histogram, FFT fields for the spectra (their periodogram's expectation is
the sampled model spectrum). Each row is the share of fields whose estimate lies inside the
band \`noiselab card\` draws (95% promised); for the ACF the last column is the Monte-Carlo
standard deviation over the band's (its own error about 3.5%).

| estimate | where | coverage | sd ratio or count |
|---|---|---|---|
MD
    awk -F'\t' 'NR > 1 { printf "| %s | %s | %s | %s |\n", $1, $2, $3, $4 }' "$d/card-bands.tsv"
    cat <<MD

Verdict (every coverage from 92% to 98%): $verdict.
MD
} > "$dir/96-card-bands.md"
[ "$verdict" = pass ]
