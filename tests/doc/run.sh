#!/bin/sh
# The documentation test: every command shown on the pages runs, as shown.
#
# usage: tests/doc/run.sh BINDIR [PAGE.md...]   (default: README.md docs/tour.md docs/geostatistics.md docs/meuse.md docs/scale-out.md docs/validating.md docs/expressions.md docs/formats.md docs/course/README.md)
#
# Each page's commands (tests/doc/extract.awk: the lines of its indented code
# blocks) run in order, one `sh -c` each, in a fresh empty folder `try/`
# made next to links to the tree's experiments/ and bin/ (so `../bin/noiselab`
# and `../experiments/...` mean what the pages say), with BINDIR first on the
# PATH. A command must exit 0 unless its line's comment announces otherwise
# with the words `exits N` (`# refused: exits 2`), and then it must exit N. A page opts a block out with
# `<!-- doc-test: skip REASON -->` just before it. Each command may run
# CMD_SECONDS (default 120); DOC_KEEP=DIR keeps each page's folder in DIR
# (DIR/README/try, DIR/tour/try) instead of removing it.  Failures and commands of 5 s or more are
# printed with their time (every command with DOC_VERBOSE=1), never asserted.
#
# The output a page shows is checked too. An indented block just after
# `<!-- doc-test: output -->` (blank lines allowed between; the block ends at
# the next line that is not indented, so some text must come before the next
# commands) is what the command before it prints, stdout then stderr. The rule
# (tests/doc/compare.awk): the shown lines are the output's lines in order, a
# line `...` standing for any number of lines (so a page may show only the
# lines it talks about), and without `...` at its ends the block starts at the
# first line printed and ends at the last. Two lines agree when they split
# into the same text and numbers (a number: optional sign, digits with an
# optional point, optional exponent): the text between numbers the same (runs
# of blanks count as one), and each number the page shows equal to the printed
# one rounded to the digits shown. A page that shows 1.038 needs a printed value
# that rounds to 1.038 at 3 decimals (1.0378819 does, 1.0386 does not), 2.5e-07
# one whose mantissa rounds to 2.5, 12 one that rounds to 12; -0.000 is 0.000.
# DOC_KEEP also keeps what each command printed, in DIR/PAGE/out/LINE (stdout,
# then stderr), to paste from.
# The page's links to files of the tree, `](path)` and `](path#anchor)`,
# must name files that exist (pictures of paper-figures/ included).
# SHARD=I/N tests only the pages whose number (from 0) is I modulo N
# (tests/par.sh runs the shards at once).
set -u
shard=${SHARD:-0/1}
si=${shard%/*} sn=${shard#*/}
top=$(cd "$(dirname "$0")/../.." && pwd)
bin=$(cd "$1" && pwd)
shift
[ $# -gt 0 ] || set -- "$top/README.md" "$top/docs/tour.md" "$top/docs/geostatistics.md" "$top/docs/meuse.md" "$top/docs/scale-out.md" "$top/docs/validating.md" "$top/docs/expressions.md" "$top/docs/formats.md" "$top/docs/course/README.md"
# docs/scale-out.md's mpirun lines, as CI runs them (root; 2 processes on 2 cores)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
secs=${CMD_SECONDS:-120}
if [ -n "${DOC_KEEP:-}" ]; then # keep each page's folder there, to look at what it made
    mkdir -p "$DOC_KEEP" && work=$(cd "$DOC_KEEP" && pwd)
else
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT INT TERM
fi
PATH="$bin:$PATH"
export PATH
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
tab=$(printf '\t')
# the output shown since the last command ($work/want) against what it printed
compare_output() {
    [ -s "$work/want" ] || return 0
    outs=$((outs + 1))
    if [ -z "$last" ]; then
        fail=$((fail + 1))
        printf 'FAIL %s:%s shows output before any command\n' "$name" "$(head -n 1 "$work/want" | cut -f 1)"
    elif ! awk -f "$top/tests/doc/compare.awk" "$work/want" "$pw/out/$last" >"$work/why"; then
        fail=$((fail + 1))
        printf 'FAIL %s:%s output of the command on line %s: %s\n' "$name" "$(cut -d ' ' -f 2 "$work/why" | tr -d :)" "$last" "$(cut -d ' ' -f 3- "$work/why")"
    fi
    : >"$work/want"
}
n=0 links=0 fail=0 outs=0 k=0
for page in "$@"; do
    k=$((k + 1))
    [ $(( (k - 1) % sn )) = "$si" ] || continue
    name=$(basename "$page")
    pdir=$(cd "$(dirname "$page")" && pwd)
    for link in $(grep -o '](\([^)#: ]*\)[)#]' "$page" | sed 's/^](//; s/[)#]$//'); do
        links=$((links + 1))
        [ -e "$pdir/$link" ] || { fail=$((fail + 1)); printf 'FAIL %s: links to %s, which does not exist\n' "$name" "$link"; }
    done
    pw="$work/${name%.md}"
    rm -rf "$pw" && mkdir -p "$pw/try"
    ln -s "$top/experiments" "$pw/experiments"
    ln -s "$bin" "$pw/bin"
    mkdir -p "$pw/out"
    awk -f "$top/tests/doc/extract.awk" "$page" >"$work/cmds" || exit 1
    : >"$work/want"
    last=""
    while IFS="$tab" read -r line kind cmd; do
        if [ "$kind" = o ]; then
            printf '%s\t%s\n' "$line" "$cmd" >>"$work/want"
            continue
        fi
        compare_output
        case "$cmd" in '#'*) continue ;; esac
        n=$((n + 1))
        want=0
        case "$cmd" in *'#'*'exits '[0-9]*) want=$(echo "$cmd" | sed 's/.*#.*exits \([0-9]*\).*/\1/') ;; esac
        start=$(date +%s)
        (cd "$pw/try" && timeout -k 5 "$secs" sh -c "$cmd" >"$work/out" 2>"$work/err" </dev/null)
        rc=$?
        took=$(( $(date +%s) - start ))
        last=$line
        cat "$work/out" "$work/err" >"$pw/out/$line"
        if [ "$rc" = "$want" ]; then
            [ -z "${DOC_VERBOSE:-}" ] && [ "$took" -lt 5 ] || printf 'ok   %s:%s (%ss) %s\n' "$name" "$line" "$took" "$cmd"
        else
            fail=$((fail + 1))
            printf 'FAIL %s:%s exit %s, expected %s (%ss): %s\n' "$name" "$line" "$rc" "$want" "$took" "$cmd"
            tail -n 5 "$work/err" | sed 's/^/     | /'
        fi
    done <"$work/cmds"
    compare_output
done
[ "$sn" = 1 ] || printf '(shard %s) ' "$shard"
echo "documentation: $n commands, $outs outputs and $links links, $fail failed"
[ "$fail" -eq 0 ]
