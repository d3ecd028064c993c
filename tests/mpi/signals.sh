#!/bin/sh
# A signal to mpirun during an 8192^2 synthesis (about 6 s here), $2 s
# after both of its processes started:
# within 15 s no process of the run remains and neither the output nor its
# temporary is left.  SIGINT and SIGTERM: mpirun sends its processes
# SIGTERM, whose handler (cli/outputs.c) removes the temporary; SIGKILL:
# mpirun cannot, the kernel does (PR_SET_PDEATHSIG, cli/h5_main.c), where
# Open MPI would end them without removing it.  Process 0 itself killed
# outright (SIGKILL, as an MPI library's _exit when its launcher is gone
# would end it, running no handler): the temporary's watcher process
# removes it (cli/outputs.c).  Usage: signals.sh BINDIR
set -u
N="$1/noiselab"
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
fail=0
# the run's live processes (a zombie's environment reads empty)
left() { grep -lsxz "NL_SIGNAL_TEST=$1" /proc/[0-9]*/environ | cut -d/ -f3; }
# the run's process 0 (a child of mpirun $2: not the watchers it forks)
rank0() {
    for p in $(left $1); do
        [ "$(cut -d' ' -f4 /proc/$p/stat 2>/dev/null)" = "$2" ] &&
            grep -qsxz OMPI_COMM_WORLD_RANK=0 /proc/$p/environ && echo $p
    done
}
# $1 signal, $2 seconds after the start, $3 "rank0" to signal process 0
# instead of mpirun
stop() {
    mark=$$-$1-$2
    $MPIRUN -np 2 -x NL_SIGNAL_TEST=$mark -x OMP_NUM_THREADS=1 "$N" synth fft --acf markov:scale=20 --size 8192x8192 \
        -o "$w/big.h5" 2>"$w/err" &
    pid=$!
    # the offset counts from when both processes run (not from mpirun's own
    # start-up, whose length varies with the machine's load)
    t=0
    while [ "$(left $mark | wc -l)" -lt 2 ] && [ $t -lt 200 ] && kill -0 $pid 2>/dev/null; do
        sleep 0.1; t=$((t + 1))
    done
    sleep "$2"
    if [ "${3:-}" = rank0 ]; then kill -"$1" $(rank0 $mark $pid); else kill -"$1" $pid; fi
    t=0
    while { kill -0 $pid 2>/dev/null || [ -n "$(left $mark)" ]; } && [ $t -lt 15 ]; do sleep 1; t=$((t + 1)); done
    procs=$(left $mark)
    if kill -0 $pid 2>/dev/null || [ -n "$procs" ]; then
        echo "signals.sh: SIG$1 ${3:-} at $2 s: mpirun or its processes still run after 15 s"; fail=1
        kill -KILL $pid $procs 2>/dev/null
    fi
    wait $pid 2>/dev/null
    if [ -n "$(ls -A "$w" | grep -v '^err$')" ]; then
        echo "signals.sh: SIG$1 ${3:-} at $2 s: left $(ls -A "$w" | grep -v '^err$' | tr '\n' ' ')"; fail=1
        rm -f "$w"/big.h5*
    fi
}
stop INT 0.3
stop TERM 0.8
stop KILL 0.8
stop KILL 0.8 rank0
exit $fail
