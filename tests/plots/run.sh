#!/bin/sh
# Every picture of the gallery has labelled axes: each gnuplot script the
# experiments use (plots/*.gp, tools/*.gp, and the scripts written inline in
# experiments/*.sh: here-documents fed to gnuplot or written to a .gp file,
# and multi-line `gnuplot -e "set terminal ..."` programs) must set a
# non-empty xlabel and ylabel, unless it says why it has no axes in a line
#     # picture: REASON
# (a picture shown as an image: unset border, no tics).  No figure is drawn:
# the scripts are read, not run.  Exit 1 naming every script that fails.
# usage: sh tests/plots/run.sh [REPO]   (default: the repository holding it)
set -eu
top=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# check NAME FILE: 0 when FILE labels both axes or carries the marker
check() {
    awk -v name="$1" '
        /^[ \t]*#[ \t]*picture:[ \t]*[^ \t]/ { pic = 1 }
        { line = $0; sub(/^[ \t]*/, "", line) }
        { n = split(line, part, ";")
          for (i = 1; i <= n; i++) {
              s = part[i]; sub(/^[ \t]*/, "", s)
              if (s ~ /^set +xl(abel)? +/ && s !~ /^set +xl(abel)? +(""|'"''"')[ \t]*$/) x = 1
              if (s ~ /^set +yl(abel)? +/ && s !~ /^set +yl(abel)? +(""|'"''"')[ \t]*$/) y = 1
              if (s ~ /^(s?plot) /) plots = 1
          } }
        END {
            if (!plots || pic || (x && y)) exit 0
            printf "%s: no %s%s%s (label the axes with units, or say why not in a \"# picture: REASON\" line)\n",
                name, x ? "" : "xlabel", (x || y) ? "" : " and ", y ? "" : "ylabel"
            exit 1 }' "$2"
}

fail=0 count=0
for f in "$top"/plots/*.gp "$top"/tools/*.gp; do
    [ -f "$f" ] || continue
    count=$((count + 1))
    check "${f#"$top"/}" "$f" || fail=$((fail + 1))
done
# inline scripts: one file per script, named after the experiment and line
for e in "$top"/experiments/*.sh; do
    awk -v out="$tmp/$(basename "$e")" '
        !inside && /gnuplot[^|]*<</ || !inside && /cat +>[^<]*\.gp"? *<</ {
            t = $0; sub(/.*<< *-?/, "", t); gsub(/["'"'"']/, "", t); sub(/[ \t].*/, "", t)
            if (t != "") { inside = 1; term = t; f = out "." NR; next } }
        !inside && /gnuplot +-e +"set terminal/ {
            inside = 2; f = out "." NR; s = $0; sub(/.*gnuplot +-e +"/, "", s); print s > f
            if (s ~ /"[ \t]*$/) { inside = 0; close(f) }
            next }
        inside == 1 { if ($0 == term) { inside = 0; close(f) } else print > f; next }
        inside == 2 { print > f; if ($0 ~ /"[ \t]*$/) { inside = 0; close(f) } }' "$e"
done
for f in "$tmp"/*.sh.*; do
    [ -f "$f" ] || continue
    count=$((count + 1))
    b=$(basename "$f")
    check "experiments/${b%.*} (gnuplot script at line ${b##*.})" "$f" || fail=$((fail + 1))
done
echo "plots: $count gnuplot scripts, $fail without axis labels or a picture marker"
[ "$fail" -eq 0 ]
