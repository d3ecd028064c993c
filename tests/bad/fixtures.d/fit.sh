# Degenerate and large data for `fit` (tests/bad/fit_hostile.cases); sourced
# by tests/bad/fixtures.sh in the fixture folder ($nl the program).
# fit_pts VAL N SEED: N random points in the unit square with values VAL
# (an awk expression of x, y, i and r, a uniform draw)
fit_pts() {
    awk -v n="$2" -v s="$3" 'BEGIN { srand(s); print "x\ty\tvalue"
        for (i = 0; i < n; i++) { x = rand(); y = rand(); r = rand(); printf "%.9g\t%.9g\t%.9g\n", x, y, '"$1"' } }'
}
fit_pts r 40 3 >fit_rand.tsv
# two data at one place with different values, and with the same value
{ cat fit_rand.tsv; printf '0.5\t0.5\t1\n0.5\t0.5\t3\n'; } >fit_coin.tsv
{ cat fit_rand.tsv; printf '0.5\t0.5\t2\n0.5\t0.5\t2\n'; } >fit_dup.tsv
fit_pts 2.5 30 4 >fit_const.tsv
awk 'BEGIN { print "x\ty\tvalue"; for (i = 0; i < 30; i++) printf "%g\t%g\t%g\n", i / 29, i * 7 % 30 / 29, i / 29 }' >fit_linear.tsv
# a smooth surface (matern's nu heads to its upper bound) and points on a line
fit_pts 'sin(3 * x) + cos(2 * y)' 60 6 >fit_smooth.tsv
awk 'BEGIN { srand(7); print "x\ty\tvalue"; for (i = 0; i < 30; i++) printf "%.9g\t%.9g\t%.9g\n", i / 29, i / 29, rand() }' >fit_line.tsv
fit_pts r 4 8 >fit_four.tsv
fit_pts r 3 9 >fit_three.tsv
# coordinates near the ends of double precision
awk 'BEGIN { srand(10); print "x\ty\tvalue"; for (i = 0; i < 30; i++) printf "%.9g\t%.9g\t%.9g\n", rand() * 1e300, rand() * 1e300, rand() }' >fit_huge.tsv
awk 'BEGIN { srand(11); print "x\ty\tvalue"; for (i = 0; i < 30; i++) printf "%.9g\t%.9g\t%.9g\n", rand() * 1e-300, rand() * 1e-300, rand() }' >fit_tiny.tsv
printf 'x\tvalue\n-1.5e308\t1\n1.5e308\t2\n0\t0.5\n1\t1.5\n2\t0.2\n3\t0.9\n' >fit_span.tsv
# too many data for a likelihood fit
fit_pts r 4096 12 >fit_4096.tsv
fit_pts r 2500 13 >fit_2500.tsv
/usr/bin/python3 - <<'PY'
import h5py, numpy as np
with h5py.File("fit_const.h5", "w") as f:
    f["field"] = np.full((16, 16), 3.25)
PY
fit_pts 'r * 1e-200' 40 14 >fit_tinyvalues.tsv
fit_pts 'r * 1e200' 40 15 >fit_hugevalues.tsv
# four data on a line, two of them at one place
printf 'x\tvalue\n0\t1\n0\t3\n1\t2\n3\t0.5\n' >fit_fourc.tsv
# Reads a fit's JSON on stdin; fails unless its uncertainty is honest: each
# free parameter has a standard error that is a number not vanishingly
# small next to its value (and an interval, where given, wider than 0), or
# a status saying why not (at a bound: no standard error, an interval
# reaching it); each NAME=LO:HI lies in [LO, HI]; objective<MAX.
cat >fit_check.py <<'PY'
import json, math, sys
d = json.load(sys.stdin)
status = d.get("status", {})
bad = []
for name, v in d["parameters"].items():
    se, st = d["standard_errors"].get(name), status.get(name, "ok")
    iv = d.get("intervals", {}).get(name)
    if st not in ("ok", "fixed"):
        # at a bound, the interval reaches that end; not identifiable: none
        if se is not None or (iv is not None and st != "at bound"):
            bad.append("%s is %s but has numbers" % (name, st))
        continue
    if st == "ok" and (se is None or not se > 1e-9 * abs(v)):
        bad.append("%s: standard error %s of %g" % (name, se, v))
    if iv is not None and iv[1] is not None and not iv[1] > iv[0] * (1 + 1e-9):
        bad.append("%s: interval %s has no width" % (name, iv))
for arg in sys.argv[1:]:
    if arg.startswith("objective<"):
        if not d["objective"] < float(arg[10:]):
            bad.append("objective %g" % d["objective"])
        continue
    name, rng = arg.split("=")
    lo, hi = map(float, rng.split(":"))
    if not lo <= d["parameters"][name] <= hi:
        bad.append("%s = %g outside %s" % (name, d["parameters"][name], rng))
if bad:
    sys.exit("fit_check: " + "; ".join(bad))
PY
