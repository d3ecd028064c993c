# Fixtures of tests/bad/mpi_hostile.cases: per-process folders and the
# helpers that run a case under mpirun (sourced by fixtures.sh in the
# fixture folder, with $nl the program).
#
# rankR/ is process R's own folder (./inrank runs a command in it): the
# same names there are other files.  in.h5: same size, other samples;
# sized.h5: other sizes; only.h5: on process 0 only; mixed.h5: a field on
# process 0, not HDF5 on process 1; sub/: a folder in each; sub0/: on
# process 0 only; scratch: a link to each one's own sub/; ro: process 1's
# is a folder nobody can create files in.  rank2 is process 0's folder.
mkdir rank0 rank1 rank0/sub rank1/sub rank0/sub0
"$nl" synth fft --acf markov:scale=4 --size 64x48 --seed 1 -o rank0/in.h5
"$nl" synth fft --acf markov:scale=4 --size 64x48 --seed 2 -o rank1/in.h5
"$nl" synth fft --acf markov:scale=4 --size 64x48 --seed 3 -o rank0/sized.h5
"$nl" synth fft --acf markov:scale=4 --size 48x64 --seed 3 -o rank1/sized.h5
cp rank0/in.h5 rank0/only.h5
cp rank0/in.h5 rank0/mixed.h5
printf 'not an HDF5 file\n' >rank1/mixed.h5
ln -s sub rank0/scratch
ln -s sub rank1/scratch
ln -s sub rank0/ro
ln -s /proc/1 rank1/ro
ln -s rank0 rank2
mkdir dir.h5
ls -A rank0 | sort >rank0.list
ls -A rank1 | sort >rank1.list

# ./inrank CMD...: CMD in this process's own folder rankR
cat >inrank <<'SH'
#!/bin/sh
cd "rank${OMPI_COMM_WORLD_RANK:-${PMIX_RANK:-0}}" || exit 3
exec "$@"
SH

# ./np2 [-k SIGNAL SECONDS] CMD...: CMD under mpirun -np ${NP:-2}, at
# most ${MPI_CASE_SECONDS:-30} s (a hang fails fast: status 124); with -k,
# SIGNAL is sent to mpirun after SECONDS.  Then no process of the run may
# remain (10 s to end) and nothing may be left in the process folders or,
# with -k, in this folder: otherwise a line on stderr and status 97 / 96.
# Else mpirun's status.
cat >np2 <<'SH'
#!/bin/sh
fix=$(dirname "$(readlink -f "$0")")
sig= delay=
if [ "$1" = -k ]; then sig=$2 delay=$3; shift 3; fi
mark=nlcase$$
opts="--oversubscribe --bind-to none -q -x NL_MPI_CASE=$mark -x OMP_NUM_THREADS=1"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
secs=${MPI_CASE_SECONDS:-30}
before=$(ls -A | sort)
if [ -z "$sig" ]; then
    timeout -k 3 "$secs" mpirun $opts -np "${NP:-2}" "$@"
    rc=$?
else
    mpirun $opts -np "${NP:-2}" "$@" &
    pid=$!
    sleep "$delay"
    kill -"$sig" $pid
    t=0
    while kill -0 $pid 2>/dev/null && [ $t -lt "$secs" ]; do sleep 1; t=$((t + 1)); done
    kill -0 $pid 2>/dev/null && kill -KILL $pid
    wait $pid
    rc=$?
fi
# the run's processes (not zombies: their environment reads empty)
left() { grep -lsxz "NL_MPI_CASE=$mark" /proc/[0-9]*/environ | cut -d/ -f3; }
t=0
while [ -n "$(left)" ] && [ $t -lt 10 ]; do sleep 1; t=$((t + 1)); done
procs=$(left)
if [ -n "$procs" ]; then
    echo "np2: processes of the run remain after mpirun ended (status $rc): $(echo $procs)" >&2
    kill -KILL $procs 2>/dev/null
    rc=97
fi
for r in rank0 rank1; do
    new=$(ls -A "$fix/$r" | sort | comm -23 - "$fix/$r.list")
    if [ -n "$new" ]; then
        echo "np2: left in $r: $(echo $new) (status $rc)" >&2
        (cd "$fix/$r" && rm -rf $new)
        rc=96
    fi
done
new=$(find "$fix/rank0/sub" "$fix/rank1/sub" "$fix/rank0/sub0" -mindepth 1)
if [ -n "$new" ]; then
    echo "np2: left: $(echo $new | sed "s|$fix/||g") (status $rc)" >&2
    rm -rf $new
    rc=96
fi
# (the process folders' "../out.h5" is the fixture folder's)
new=$(cd "$fix" && ls -A | grep -E '^(out|big)\.h5')
[ -z "$new" ] || { echo "np2: left in the fixture folder: $(echo $new) (status $rc)" >&2; (cd "$fix" && rm -f $new); rc=96; }
if [ -n "$sig" ]; then
    b=$(mktemp)
    printf '%s\n' "$before" >"$b"
    new=$(ls -A | sort | comm -23 - "$b")
    rm -f "$b"
    [ -z "$new" ] || { echo "np2: left: $(echo $new) (status $rc)" >&2; rm -rf $new; rc=96; }
fi
exit $rc
SH
chmod +x inrank np2
