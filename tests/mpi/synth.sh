#!/bin/sh
# Distributed synthesis against one process: for P = 1..4, fft and circulant
# within 1e-12 of the field's largest magnitude (float64; the transforms'
# rounding depends on the cut: measured 0 to 6e-16), subdiv and sparse bit
# for bit, in float64 and against the one-process float32 EXR; --from of an
# .h5 output regenerates it; bad input fails on every process with one
# line from rank 0, exit 2, no file left.  Usage: synth.sh BINDIR
set -u
N="$1/noiselab"
here=$(cd "$(dirname "$0")" && pwd)
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
fail=0
cmp() { /usr/bin/python3 "$here/h5cmp.py" "$@" || fail=1; }

# Every case: one process without mpirun (the reference), then P in MPI_NPS
# (default 1..4).
# $1 tolerance, then the synth arguments.
case_() {
    tol=$1; shift
    rm -f "$w"/*.h5
    if ! "$N" synth "$@" --precision double -o "$w/ref.h5"; then
        echo "synth.sh: one process failed: synth $*"; fail=1; return
    fi
    for p in ${MPI_NPS:-1 2 3 4}; do
        $MPIRUN -np $p "$N" synth "$@" --precision double -o "$w/p$p.h5" || { echo "synth.sh: -np $p failed: synth $*"; fail=1; }
    done
    outs=
    for p in ${MPI_NPS:-1 2 3 4}; do outs="$outs $w/p$p.h5"; done
    cmp "$tol" "$w/ref.h5" $outs
}
case_ 1e-12 fft --acf markov:scale=6 --size 96x64 --seed 5
case_ 1e-12 fft --acf gauss:scale=1.5 --size 15x20x9 --clamp --seed 2
case_ 1e-12 fft --spectrum power:d=3 --size 33x17 --seed 1
case_ 1e-12 circulant --acf markov:scale=5 --size 40x30 --seed 9
case_ 1e-12 circulant --acf gauss:scale=2 --size 12x10x7 --seed 4
case_ 0 subdiv --acf markov:scale=8 --size 96x64 --seed 3
case_ 0 subdiv --acf gauss:scale=4 --size 64x128 --neighborhood 3 --clamp --seed 6
case_ 0 subdiv --acf markov:scale=8 --size 64x64 --displacements correlated --seed 2
case_ 0 subdiv --acf markov:scale=8 --size 50x37 --nonperiodic --origin 5,-9 --seed 8
case_ 0 subdiv --acf markov:scale=8 --size 4096 --seed 8
case_ 0 sparse --acf gauss:scale=3 --size 80x45 --seed 3
case_ 0 sparse --acf markov:scale=4 --size 64x64 --wrap --seed 3
case_ 0 sparse --kernel 'exp(-(x*x+y*y)/8)' --radius 6 --size 40x33 --origin 3,4 --seed 1

# float32 output holds the one-process EXR's values: 3000 samples read
# back from both (nearest sample, printed to 10 digits; a float32 ulp is
# 6e-8 relative) are the same text
f32() {
    "$N" synth "$@" -o "$w/e.exr" && $MPIRUN -np 3 "$N" synth "$@" -o "$w/f.h5" &&
        "$N" sample "$w/e.exr" --random 3000 --seed 7 --interpolation nearest | grep -v '^#' > "$w/e.tsv" &&
        "$N" sample "$w/f.h5" --random 3000 --seed 7 --interpolation nearest | grep -v '^#' > "$w/f.tsv" &&
        diff -q "$w/e.tsv" "$w/f.tsv" >/dev/null || { echo "synth.sh: float32 .h5 differs from the EXR: synth $*"; fail=1; }
}
# (fft and circulant round differently with the cut: compared in float64 above)
f32 subdiv --acf markov:scale=8 --size 96x64 --seed 3
f32 sparse --acf markov:scale=4 --size 64x64 --wrap --seed 3

# --from regenerates an .h5 output (fields and provenance)
$MPIRUN -np 2 "$N" synth --from "$w/ref.h5" --precision double -o "$w/again.h5" || fail=1
cmp 1e-12 "$w/ref.h5" "$w/again.h5"

# bad input under mpirun -np 2: exit 2, one line, no file, no hang
bad() {
    rm -f "$w"/out* "$w/err"
    timeout 60 $MPIRUN -np 2 "$N" synth "$@" 2>"$w/err"
    rc=$?
    lines=$(grep -c . "$w/err")
    left=$(ls "$w" | grep -c '^out' || true)
    if [ $rc != 2 ] || [ "$lines" != 1 ] || [ "$left" != 0 ]; then
        echo "synth.sh: synth $*: exit $rc (expected 2), $lines lines on stderr (expected 1), $left files left:"
        sed 's/^/  /' "$w/err"; fail=1
    fi
}
bad fft --acf markov:scale=6 --size 64x48 -o "$w/nonexistent/out.h5"
bad fft --acf nosuchmodel --size 64x48 -o "$w/out.h5"
bad fft --acf markov:scale=6 --size 64 -o "$w/out.h5"
bad fft --acf markov:scale=6 --size 64x48 -o "$w/out.exr"
bad midpoint --acf power:d=3 --size 64x64 -o "$w/out.h5"
bad fft --acf markov:scale=30 --size 64x48 -o "$w/out.h5"
exit $fail
