#!/bin/sh
# Do the likelihood fits find the optimum on real data, and say when there
# is none?  The Meuse data (R's sp package: 155 points, log(zinc)), fitted
# by REML and ML with `noiselab fit` (every profile interval): spherical +
# nugget from seven starting ranges 200 to 12800 (each the start of the wls
# fit the likelihood fit starts from), exponential (markov) + nugget, and
# both with a linear drift.  Needs Rscript with sp (skipped, with a note,
# without); about a minute of one core.
. "$(dirname "$0")/lib.sh"
md="$d/97-fit-meuse-ml.md"
if ! Rscript -e 'suppressMessages(library(sp)); data(meuse)
d <- data.frame(x = meuse$x, y = meuse$y, value = log(meuse$zinc))
write.table(format(d, digits = 17), "'"$d"'/meuse.tsv", sep = "\t", quote = FALSE, row.names = FALSE)' \
    >/dev/null 2>&1; then
    printf '## Likelihood fits on Meuse (noiselab fit)\n\nSkipped: Rscript with sp is not installed.\n' > "$md"
    exit 0
fi
# fit ARGS...: one JSON line per fit
fit() { "$nl" fit "$d/meuse.tsv" --json "$@" | jq -c '{o: .objective, c: .converged, p: .parameters,
    i: .intervals, s: .status, n: .starts, r: .restarts, d: [.drift[]?.value]}'; }
: > "$d/meuse-sph-starts.jsonl"
for a in 200 400 800 1600 3200 6400 12800; do
    fit --model "spherical:var=0.6,scale=$a,nugget=0.05" --method reml >> "$d/meuse-sph-starts.jsonl"
done
fit --model markov --nugget --method reml > "$d/meuse-exp.json"
fit --model spherical --nugget --method reml --drift linear > "$d/meuse-sph-lin-reml.json"
fit --model spherical --nugget --method ml --drift linear > "$d/meuse-sph-lin-ml.json"
worst=$(jq -s 'map(.o) | max' "$d/meuse-sph-starts.jsonl")
best=$(jq -s 'map(.o) | min' "$d/meuse-sph-starts.jsonl")
ranges=$(jq -r -s 'map(.p.scale | . * 10 | round / 10 | tostring) | join(", ")' "$d/meuse-sph-starts.jsonl")
nconv=$(jq -s 'map(select(.c)) | length' "$d/meuse-sph-starts.jsonl")
e() { jq -r "$1" "$d/meuse-exp.json"; }
eo=$(e '.o') ec=$(e '.c') es=$(e '.p.scale') est=$(e '.s.scale') evl=$(e '.i.var[0]') esl=$(e '.i.scale[0]')
evu=$(e '.i.var[1] // "unbounded"') esu=$(e '.i.scale[1] // "unbounded"') enu=$(e '.i.nugget[1]')
lr=$(jq -r '"\(.o * 1000 | round / 1000) at range \(.p.scale | round), drift \(.d | map(. * 1e4 | round / 1e4 | tostring) | join(", "))"' \
    "$d/meuse-sph-lin-reml.json")
lm=$(jq -r '"\(.o * 1000 | round / 1000) at range \(.p.scale | round), drift \(.d | map(. * 1e4 | round / 1e4 | tostring) | join(", "))"' \
    "$d/meuse-sph-lin-ml.json")
r3() { printf '%.3f' "$1"; }
r0() { printf '%.0f' "$1"; }
verdict=FAIL
awk -v w="$worst" -v n="$nconv" -v eo="$eo" -v ec="$ec" -v evl="$evl" -v esl="$esl" -v st="$est" -v evu="$evu" 'BEGIN {
    ok = w <= 194.95 && n == 7 && ec == "false" && st == "at bound" && eo > 195.5 && eo < 195.6 && evu == "unbounded"
    ok = ok && evl > 0.78 && evl < 0.86 && esl > 840 && esl < 900
    exit !ok }' && verdict=pass
cat > "$md" <<MD
## Likelihood fits on Meuse (noiselab fit)

Not a figure of the papers: R's sp data set \`meuse\` (155 points, log(zinc)), fitted by REML
with \`noiselab fit --method reml\` and every profile interval.

Spherical + nugget, from starting ranges 200, 400, ..., 12800 (the start of the wls fit the
REML fit starts from): -2 log L from $(r3 "$best") to $(r3 "$worst") (the optimum, from R's optim on a grid of
ranges: 194.92 at range 3000; a simplex from the wls fit alone stopped at 196.60, range
1203), ranges $ranges; $nconv of 7 converged.

Exponential + nugget: -2 log L falls towards the linear variogram's 195.53 as the scale
grows, with no optimum: the fit ends at the search box's edge (scale $(r0 "$es"), status
"$est", converged: $ec; -2 log L $(r3 "$eo")); the profile intervals' lower ends stay finite
(var $(r3 "$evl"), scale $(r0 "$esl"); R: about 0.82 and 870), their upper ends $evu and $esu,
the nugget's upper end $(r3 "$enu").

Spherical + nugget with a linear drift (1, u, v: the coordinates centred on and scaled by the
bounding box): REML $lr; ML $lm.

Verdict: every start reaches -2 log L <= 194.95 and converges; the exponential fit is at
bound and not converged, with var's and the scale's lower ends within 5% of 0.82 and 870 and
var's upper end unbounded: $verdict.
MD
[ "$verdict" = pass ]
