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
# The rows run in two halves side by side (two processes).
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
# One row: "ok|WRONG|slow|skip <TAB> ms <TAB> got <TAB> spec <TAB> dim <TAB> expected <TAB> cite".
check_row() { # spec dim expected cite out-prefix
    if [ -x /usr/bin/time ]; then
        /usr/bin/time -o "$5.time" -f '%U %S' "$bin" check --acf "$1" --dim "$2" >"$5.out" 2>"$5.err"
        rc=$?
        ms=$(awk '{ printf "%d", ($1 + $2) * 1000 }' "$5.time")
    else
        t0=$(date +%s%N)
        "$bin" check --acf "$1" --dim "$2" >"$5.out" 2>"$5.err"
        rc=$?
        t1=$(date +%s%N)
        ms=$(((t1 - t0) / 1000000))
    fi
    if [ $rc -ne 0 ] && grep -q 'unknown model' "$5.err"; then
        printf 'skip\t0\t-\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4"
        return
    fi
    got=error
    if [ $rc -eq 0 ]; then
        if head -n 1 "$5.out" | grep -q ': positive definite$'; then got=valid; else got=invalid; fi
    elif [ $rc -eq 2 ] && [ "$3" = invalid ]; then
        got=invalid  # refused as input: a family's parameter range that excludes the invalid model
    fi
    ok=ok
    [ "$got" = "$3" ] || ok=WRONG
    [ "$ms" -le $((limit * 1000)) ] || ok=slow
    [ $got = error ] && got="error: $(head -n 1 "$5.err")"
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$ok" "$ms" "$got" "$1" "$2" "$3" "$4"
}

# The rows in two halves, each checked by its own process (two cores).
tab=$(printf '\t')
for file in "$dir/catalogue.tsv" "$dir/catalogue-named.tsv"; do
    [ -f "$file" ] && grep -v '^#' "$file" | grep -v '^$'
done >"$tmp/rows"
for half in 0 1; do
    awk -v h=$half 'NR % 2 == h' "$tmp/rows" | while IFS="$tab" read -r spec dim expected cite; do
        check_row "$spec" "$dim" "$expected" "$cite" "$tmp/$half"
    done >"$tmp/res$half" &
done
wait
cat "$tmp/res0" "$tmp/res1" >"$tmp/res"
status=0
while IFS="$tab" read -r ok ms got spec dim expected cite; do
    [ "$ok" = skip ] && continue
    case $ok in
    WRONG) status=1; echo "WRONG verdict: $spec in ${dim}D: got $got, expected $expected ($cite)" ;;
    slow) status=1; echo "TOO SLOW: $spec in ${dim}D: $ms ms of CPU, over ${limit} s ($cite)" ;;
    esac
    [ -n "$verbose" ] && printf '%s\t%s\t%s\t%s\t%d.%03d s\n' "$spec" "$dim" "$got" "$expected" $((ms / 1000)) $((ms % 1000))
done <"$tmp/res"
rows=$(grep -vc '^skip' "$tmp/res")
right=$(grep -c '^ok' "$tmp/res")
skipped=$(grep -c '^skip' "$tmp/res")
slowest_line=$(grep -v '^skip' "$tmp/res" | sort -t "$tab" -k2,2n | tail -n 1)
slowest=$(printf '%s' "$slowest_line" | cut -f2)
slowest_row="$(printf '%s' "$slowest_line" | cut -f4) in $(printf '%s' "$slowest_line" | cut -f5)D"
echo "check catalogue: $right of $rows right within ${limit} s; $skipped rows of unknown families skipped; slowest $slowest ms ($slowest_row)"
exit $status
