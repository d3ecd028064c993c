#!/bin/sh
# The memory limit is per process: a 4096^2 FFT synthesis (float64 output)
# that one process refuses under NOISELAB_MEMORY_LIMIT=300 MiB (its
# estimate, mpi/fft.h: about 3.5 slabs of 128 MiB) is refused with exit 2
# naming the 2 processes it needs, and runs on 2 processes under the same
# limit, each process's measured peak RSS (getrusage, --json's
# peak_rss_mib, the largest of the processes) below the limit.
# Usage: memory.sh BINDIR
set -u
N="$1/noiselab"
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
fail=0
lim=314572800
args="fft --acf markov:scale=20 --size 4096x4096 --precision double"
NOISELAB_MEMORY_LIMIT=$lim "$N" synth $args -o "$w/one.h5" 2>"$w/err"
rc=$?
if [ $rc != 2 ] || ! grep -q "mpirun -np 2)" "$w/err" || [ -e "$w/one.h5" ]; then
    echo "memory.sh: one process: exit $rc (expected 2 naming 2 processes):"; cat "$w/err"; fail=1
fi
$MPIRUN -np 2 -x NOISELAB_MEMORY_LIMIT=$lim "$N" synth $args --json -o "$w/two.h5" >"$w/j" 2>"$w/err" || {
    echo "memory.sh: two processes failed:"; cat "$w/err"; fail=1; }
rss=$(jq .peak_rss_mib "$w/j" 2>/dev/null || echo 1e9)
# (under the sanitizers the RSS holds their shadow memory and quarantine:
# not the program's; NOISELAB_SANITIZED is set by make asan)
if [ -z "${NOISELAB_SANITIZED:-}" ] && ! awk -v r="$rss" -v l=$lim 'BEGIN { exit !(r * 1048576 < l) }'; then
    echo "memory.sh: peak RSS $rss MiB per process on 2 processes, above the limit of $((lim / 1048576)) MiB"; fail=1
fi
exit $fail
