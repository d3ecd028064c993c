#!/bin/sh
# Builds the baseline for tools/compat/run.sh from a git revision of this
# repository: its tree (git archive) in DIR/src, built there with make all
# (DIR default build/compat-base).  Run at the top of the source tree.
#
#   sh tools/compat/base.sh REV [DIR]
#
# Prints the folder of the baseline's noiselab and noiselab-mpi.  A build of
# the same commit already in DIR is reused.
set -eu
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
    echo "usage: $0 REV [DIR]" >&2
    exit 2
fi
dir=${2:-build/compat-base}
rev=$(git rev-parse --verify "$1^{commit}") || { echo "$0: $1: not a revision of this repository" >&2; exit 2; }
if [ -f "$dir/rev" ] && [ "$(cat "$dir/rev")" = "$rev" ] && [ -x "$dir/src/bin/noiselab" ] && [ -x "$dir/src/bin/noiselab-mpi" ]; then
    echo "compat: the baseline of $rev is built in $dir/src" >&2
else
    rm -rf "$dir"
    mkdir -p "$dir/src"
    git archive "$rev" | tar -x -C "$dir/src"
    echo "compat: building $rev in $dir/src" >&2
    make -C "$dir/src" -j"${COMPAT_JOBS:-2}" all > "$dir/build.log" 2>&1 ||
        { tail -20 "$dir/build.log" >&2; echo "$0: the build of $rev failed (all of it in $dir/build.log)" >&2; exit 1; }
    echo "$rev" > "$dir/rev"
fi
echo "$dir/src/bin"
