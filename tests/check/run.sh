#!/bin/sh
# The literature catalogue of model validity: every (model, dimension) of
# catalogue.tsv and catalogue-named.tsv (spec, dim, expected verdict,
# citation; tab-separated, # comments) through `noiselab check`, each
# verdict compared with the expected one and each check timed (at most
# LIMIT seconds, 5 unless set: the CPU seconds, user and system, of the
# check as /usr/bin/time counts them, so that a loaded machine does not
# fail it; wall-clock seconds where /usr/bin/time is missing).  Rows of catalogue-named.tsv whose family
# the binary does not know are skipped and counted.  Usage:
#     sh tests/check/run.sh BIN [-v]
# A row expected invalid that check refuses as bad input (exit status 2,
# a parameter outside the family's range) counts as right.
# -v prints every row: verdict, expected, seconds.  Exit status 1 when a
# verdict is wrong or a check too slow, 2 on bad usage.
bin=${1:?usage: sh tests/check/run.sh BIN [-v]}
verbose=${2:-}
limit=${LIMIT:-5}
dir=$(dirname "$0")
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT
status=0
rows=0 right=0 skipped=0 slowest=0 slowest_row=
for file in "$dir/catalogue.tsv" "$dir/catalogue-named.tsv"; do
    [ -f "$file" ] || continue
    tab=$(printf '\t')
    while IFS="$tab" read -r spec dim expected cite; do
        case $spec in '#'* | '') continue ;; esac
        t0=$(date +%s%N)
        if [ -x /usr/bin/time ]; then
            /usr/bin/time -o "$tmp/time" -f '%U %S' "$bin" check --acf "$spec" --dim "$dim" >"$tmp/out" 2>"$tmp/err"
            rc=$?
            ms=$(awk '{ printf "%d", ($1 + $2) * 1000 }' "$tmp/time")
        else
            "$bin" check --acf "$spec" --dim "$dim" >"$tmp/out" 2>"$tmp/err"
            rc=$?
            t1=$(date +%s%N)
            ms=$(((t1 - t0) / 1000000))
        fi
        if [ $rc -ne 0 ] && grep -q 'unknown model' "$tmp/err"; then
            skipped=$((skipped + 1))
            continue
        fi
        rows=$((rows + 1))
        got=error
        if [ $rc -eq 0 ]; then
            if head -n 1 "$tmp/out" | grep -q ': positive definite$'; then got=valid; else got=invalid; fi
        elif [ $rc -eq 2 ] && [ "$expected" = invalid ]; then
            got=invalid  # refused as input: a family's parameter range that excludes the invalid model
        fi
        if [ "$ms" -gt "$slowest" ]; then slowest=$ms; slowest_row="$spec in ${dim}D"; fi
        ok=yes
        [ "$got" = "$expected" ] || ok=no
        [ "$ms" -le $((limit * 1000)) ] || ok=slow
        if [ $ok = yes ]; then
            right=$((right + 1))
        else
            status=1
            echo "WRONG ($ok): $spec in ${dim}D: got $got, expected $expected ($cite)$([ $got = error ] && printf ': %s' "$(cat "$tmp/err")")"
        fi
        [ -n "$verbose" ] && printf '%s\t%s\t%s\t%s\t%d.%03d s\n' "$spec" "$dim" "$got" "$expected" $((ms / 1000)) $((ms % 1000))
    done <"$file"
done
echo "check catalogue: $right of $rows right within ${limit} s; $skipped rows of unknown families skipped; slowest $slowest ms ($slowest_row)"
exit $status
