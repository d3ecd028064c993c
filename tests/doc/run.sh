#!/bin/sh
# The documentation test: every command shown on the pages runs, as shown.
#
# usage: tests/doc/run.sh BINDIR [PAGE.md...]   (default: README.md docs/tour.md docs/geostatistics.md docs/scale-out.md)
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
# The page's links to files of the tree, `](path)` and `](path#anchor)`,
# must name files that exist (pictures of paper-figures/ included).
set -u
top=$(cd "$(dirname "$0")/../.." && pwd)
bin=$(cd "$1" && pwd)
shift
[ $# -gt 0 ] || set -- "$top/README.md" "$top/docs/tour.md" "$top/docs/geostatistics.md" "$top/docs/scale-out.md"
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
n=0 links=0 fail=0
for page in "$@"; do
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
    awk -f "$top/tests/doc/extract.awk" "$page" >"$work/cmds" || exit 1
    while IFS="$tab" read -r line cmd; do
        case "$cmd" in '#'*) continue ;; esac
        n=$((n + 1))
        want=0
        case "$cmd" in *'#'*'exits '[0-9]*) want=$(echo "$cmd" | sed 's/.*#.*exits \([0-9]*\).*/\1/') ;; esac
        start=$(date +%s)
        (cd "$pw/try" && timeout -k 5 "$secs" sh -c "$cmd" >"$work/out" 2>"$work/err" </dev/null)
        rc=$?
        took=$(( $(date +%s) - start ))
        if [ "$rc" = "$want" ]; then
            [ -z "${DOC_VERBOSE:-}" ] && [ "$took" -lt 5 ] || printf 'ok   %s:%s (%ss) %s\n' "$name" "$line" "$took" "$cmd"
        else
            fail=$((fail + 1))
            printf 'FAIL %s:%s exit %s, expected %s (%ss): %s\n' "$name" "$line" "$rc" "$want" "$took" "$cmd"
            tail -n 5 "$work/err" | sed 's/^/     | /'
        fi
    done <"$work/cmds"
done
echo "documentation: $n commands and $links links, $fail failed"
[ "$fail" -eq 0 ]
