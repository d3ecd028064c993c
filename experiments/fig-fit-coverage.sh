#!/bin/sh
# Do fitted parameters' standard errors describe their spread?
# (experiments/fit_coverage.c): 100 fields per model, 128 x 128, seeds
# 1..100, 500 grid nodes drawn from each, fitted by ML and by WLS.
. "$(dirname "$0")/lib.sh"
"$xb/fit_coverage" markov:scale=8,nugget=0.3 markov 1 128 500 100 > "$d/fit-coverage-markov.tsv"
"$xb/fit_coverage" spherical:scale=24 spherical 0 128 500 100 > "$d/fit-coverage-spherical.tsv"
rows() {
    awk -F'\t' -v m="$1" 'NR > 1 && $1 !~ /^#/ { printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", m, $1, $2, $3, $4, $5, $6, $7, $8 }' \
        "$d/fit-coverage-$1.tsv"
}
# ML's Wald intervals are judged: over 100 fields a true 95% coverage gives
# a count with sd sqrt(0.95 0.05 / 100) = 0.022; below 0.95 - 3 sd = 0.885
# the standard errors understate the spread.  WLS's are reported only: they
# treat correlated bins as independent (analysis/fit.h).
# The verdict judges the regular model (markov with a nugget); the
# spherical model's likelihood is not smooth in the range (below), so its
# Wald intervals are reported, with the shortfall, not judged.
verdict=pass
awk -F'\t' '$1 == "ml" && ($8 < 0.885 || $4 < 90) { bad = 1 } END { exit bad }' "$d/fit-coverage-markov.tsv" ||
    verdict=FAIL
sph=$(awk -F'\t' '$1 == "ml" && $2 == "scale" { print $8 }' "$d/fit-coverage-spherical.tsv")
cat > "$d/96-fit-coverage.md" <<MD
## Standard errors of fitted models (noiselab fit)

100 fields of each model, 128 x 128 at unit spacing by circulant embedding (exact; seeds 1 to
100); from each, 500 distinct grid nodes drawn at random are the data. Each data set is fitted
by WLS on its Matheron variogram (gstat's default width and cutoff, Cressie's weights N/gamma^2)
and by ML started from the WLS fit. "sd" is the spread of the estimates over the fields, "mean
se" the mean standard error the fits report; coverage is the share of fields whose interval
est +- 1.96 se holds the true value (nominal 0.95), "log" that of est exp(+-1.96 se/est).

| model | method | parameter | true | fits | mean | sd | mean se | coverage |
|---|---|---|---|---|---|---|---|---|
$(rows markov)
$(rows spherical)

Verdict (every ML coverage of markov with a nugget at least 0.885, 3 binomial sds below 0.95,
with at least 90 fits reporting a standard error): $verdict. Not judged, and stated as a limit
of \`noiselab fit\`: the spherical range's ML interval covers $sph of the time. The WLS standard errors come from the Jacobian as if the
bins were independent; bins share points, so they are a lower bound on the spread, as the
table shows. The spherical model is the hard case for ML too: R has a kink at the range, so
the likelihood's curvature in the range is not smooth (it changes at each pair distance that
the range crosses), and with the range a fifth of the domain the data hold few independent
ranges; the observed information then understates the spread (a larger difference step for
the Hessian, 3e-2 instead of 2e-3, gives the same standard errors: it is not a numerical
artefact).
MD
[ "$verdict" = pass ]
