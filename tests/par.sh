#!/bin/sh
# Run shell commands at once and print their outputs one after the other, in
# the order given; fail when any of them fails.  The test suite's slow
# catalogues run as two shards this way (SHARD=0/2 and SHARD=1/2: see
# tests/bad/run.sh and tests/doc/run.sh).
# usage: tests/par.sh CMD...
set -u
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT INT TERM
i=0 pids=
for c in "$@"; do
    i=$((i + 1))
    sh -c "$c" >"$d/$i" 2>&1 &
    pids="$pids $!"
done
rc=0
for p in $pids; do wait "$p" || rc=1; done
i=0
for c in "$@"; do
    i=$((i + 1))
    cat "$d/$i"
done
exit $rc
