#!/bin/sh
# The catalogue of hostile inputs: run every case of tests/bad/*.cases and
# check the contract of the command line on each.
#
# usage: tests/bad/run.sh NOISELAB FINITE [CASEFILE...]
#   NOISELAB  the program under test; FINITE  build/tests/finite (exit 0 when
#   every value of a field file is finite)
#
# A case is one line of four tab-separated fields:
#   RULE  EXIT  NEEDLE  COMMAND
# RULE: the rule of the hardening contract it exercises (1 finite or refused,
# 2 not silently wrong, 3 bounded, 4 clean on failure and signals, 5 never
# aborts, 6 messages name the value, 7 slow cases fast or refused).
# EXIT: the expected exit status.  NEEDLE: text the one-line message must
# contain ("-": none).  COMMAND: a shell command run in a fresh folder that
# holds the fixtures (tests/bad/fixtures.sh), with $NL the program.
# Lines starting with # and blank lines are skipped.
#
# Checked for every case: the exit status; no crash (status >= 128 other
# than an expected one) and at most CASE_SECONDS (default 60) of run time;
# no file left in the folder but the fixtures and, for EXIT 0, the outputs;
# for EXIT 2: exactly one line on stderr, "noiselab: ..." containing NEEDLE;
# for EXIT 0: no nan or inf on stdout or in any text output, and every EXR
# output finite.  SHARD=I/N runs only the cases whose number (from 0, over
# all the files) is I modulo N, with fixtures of its own (tests/par.sh runs
# the shards at once).  BAD_TIMES=FILE appends each case's milliseconds.
set -u
shard=${SHARD:-0/1}
si=${shard%/*} sn=${shard#*/}
NL=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
FINITE=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
shift 2
here=$(cd "$(dirname "$0")" && pwd)
[ $# -gt 0 ] || set -- "$here"/*.cases
secs=${CASE_SECONDS:-60}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM
export NL
# The program's error exits leave their memory to exit() by design: leaks are
# checked in the library's tests, not in these processes (as in tests/util.c).
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
mkdir "$work/fix"
(cd "$work/fix" && sh "$here/fixtures.sh" "$NL") || { echo "bad-inputs: the fixtures could not be made"; exit 1; }
ls -A "$work/fix" | sort >"$work/fixlist"
pass=0 fail=0 n=0
tab=$(printf '\t')
for file in "$@"; do
    while IFS="$tab" read -r rule exit needle cmd; do
        case "$rule" in ''|'#'*) continue ;; esac
        n=$((n + 1))
        [ $(( (n - 1) % sn )) = "$si" ] || continue
        d="$work/case"
        rm -rf "$d" && mkdir "$d"
        ln -s "$work"/fix/* "$d/"
        start=$(date +%s%N)
        (cd "$d" && timeout -k 5 "$secs" sh -c "$cmd" >"$work/out" 2>"$work/err" </dev/null)
        rc=$?
        took=$(( ($(date +%s%N) - start) / 1000000 ))
        [ -z "${BAD_TIMES:-}" ] || printf '%s\t%s\t%s\n' "$took" "$(basename "$file")" "$(echo "$cmd" | tr '\n' ' ')" >>"$BAD_TIMES"
        why=""
        [ "$rc" = "$exit" ] || why="exit $rc, expected $exit"
        [ "$rc" = 124 ] && why="ran over $secs s"
        new=$(ls -A "$d" | sort | comm -23 - "$work/fixlist")
        if [ "$exit" = 2 ]; then
            [ -z "$new" ] || why="$why; left: $(echo $new)"
            [ "$(wc -l <"$work/err")" = 1 ] || why="$why; stderr has $(wc -l <"$work/err") lines"
            head -c 10 "$work/err" | grep -q '^noiselab: ' || why="$why; stderr does not start with \"noiselab: \""
            [ "$needle" = - ] || grep -qF -- "$needle" "$work/err" || why="$why; message does not name \"$needle\""
        elif [ "$exit" = 0 ]; then
            grep -qiwE 'nan|-nan|inf|-inf|infinity' "$work/out" && why="$why; non-finite number on stdout"
            for f in $new; do
                case "$f" in
                *.exr) "$FINITE" "$d/$f" >/dev/null 2>&1 || why="$why; $f not finite" ;;
                *.tsv|*.json|*.md|*.txt|*.obj) grep -qiwE 'nan|-nan|inf|-inf|infinity' "$d/$f" && why="$why; $f has nan/inf" ;;
                *.tmp|*.tmp.*|.*tmp*) why="$why; temporary $f left" ;;
                esac
            done
        fi
        why=${why#; }
        if [ -z "$why" ]; then
            pass=$((pass + 1))
            eval "r$rule=\$(( \${r$rule:-0} + 1 ))"
        else
            fail=$((fail + 1))
            echo "bad-inputs: FAILED [rule $rule] $(basename "$file"): $(echo "$cmd" | tr "\n" " ")" | sed "s|$NL|noiselab|g"
            echo "    $why (${took} ms)"
            sed 's/^/    stderr: /' "$work/err" | head -3
        fi
    done <"$file"
done
tag=bad-inputs
[ "$sn" = 1 ] || tag="bad-inputs (shard $shard)"
printf '%s: per rule:' "$tag"
for r in 1 2 3 4 5 6 7; do eval "printf ' %s:%s' $r \${r$r:-0}"; done
echo
echo "$tag: $pass passed, $fail failed"
[ "$fail" = 0 ]
