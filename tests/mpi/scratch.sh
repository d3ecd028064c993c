#!/bin/sh
# Node-local storage under one name: every process sees "$w/scratch", but
# each its own folder there (a tmpfs mounted in a mount namespace of its
# own, as /scratch is on each node of a cluster).  The resolved paths are
# equal, the folders are not: synth -o and acf of a file there must refuse
# on every process with one line from rank 0 naming the path, exit 2, no
# hang (a collective create or open of files that differ never returns),
# nothing left.  Needs unshare -m (root, or user namespaces): skipped
# without it.  Usage: scratch.sh BINDIR
set -u
N="$1/noiselab"
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
if ! unshare -m true 2>/dev/null; then
    echo "scratch.sh: skipped (no mount namespaces here: unshare -m)"
    exit 0
fi
mkdir "$w/scratch"
fail=0
"$N" synth fft --acf markov:scale=4 --size 64x48 --seed 1 -o "$w/in.h5" || exit 1
# $1 the command, run in each process's own scratch; $2 what the message names
refused() {
    timeout -k 3 60 $MPIRUN -np 2 unshare -m sh -c "mount -t tmpfs none '$w/scratch' && cp '$w/in.h5' '$w/scratch/' &&
        $1; rc=\$?; [ -z \"\$(ls -A '$w/scratch' | grep -v '^in.h5\$')\" ] || rc=99; exit \$rc" >"$w/out" 2>"$w/err"
    rc=$?
    if [ $rc != 2 ] || [ "$(wc -l <"$w/err")" != 1 ] || ! grep -q "^noiselab: .*$2" "$w/err" || [ -n "$(ls -A "$w/scratch")" ]; then
        echo "scratch.sh: $1: exit $rc (expected 2, one line naming $2, nothing left):"; sed 's/^/  /' "$w/err"; fail=1
    fi
}
refused "$N synth fft --acf markov:scale=4 --size 64x48 -o '$w/scratch/out.h5'" "\"$w/scratch/out.h5\" is .* another one on process 1"
refused "$N synth subdiv --acf markov:scale=8 --size 64x64 -o '$w/scratch/out.h5'" "-o: \"$w/scratch/out.h5\""
refused "$N acf '$w/scratch/in.h5' --max-lag 4" "\"$w/scratch/in.h5\" is .* another one on process 1"
exit $fail
