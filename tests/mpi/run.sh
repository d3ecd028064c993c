#!/bin/sh
# The distributed tests: every program build/tests/mpi/NAME (from
# tests/mpi/NAME.c) under mpirun -np 1, 2, 3 and 4, then every
# tests/mpi/*.sh, which compare the command line's distributed runs with
# one-process ones.  MPI_NPS: the process counts (default "1 2 3 4"; make
# test runs "2 3", an even and an uneven split, and make test-slow "1 4").
# Usage: run.sh BINDIR TESTBINDIR
set -eu
bindir=$(cd "$1" && pwd)
mkdir -p "$2"
testbin=$(cd "$2" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
# mpirun refuses root unless told; above 2 processes on 2 cores it needs
# --oversubscribe.  Sanitizer builds: Open MPI's own allocations outlive
# MPI_Finalize, so leak checking is off here (the library's are checked by
# the Criterion suite).
MPIRUN="mpirun --oversubscribe --bind-to none -q"
[ "$(id -u)" = 0 ] && MPIRUN="$MPIRUN --allow-run-as-root"
MPI_NPS=${MPI_NPS:-1 2 3 4}
export MPIRUN MPI_NPS ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0"
export OMP_NUM_THREADS=1
fail=0
for t in "$testbin"/*; do
    [ -x "$t" ] || continue
    for p in $MPI_NPS; do
        # a hang (a collective call some process never makes) fails here
        if ! timeout -k 5 600 $MPIRUN -np $p "$t" >"$testbin/$(basename "$t").np$p.log" 2>&1; then
            echo "FAIL: $(basename "$t") on $p processes:"; sed 's/^/  /' "$testbin/$(basename "$t").np$p.log" | tail -20
            fail=1
        fi
    done
done
for s in "$here"/*.sh; do
    [ "$s" = "$here/run.sh" ] && continue
    if ! sh "$s" "$bindir"; then
        echo "FAIL: $(basename "$s")"; fail=1
    fi
done
[ $fail = 0 ] && echo "mpi: all distributed tests passed"
exit $fail
