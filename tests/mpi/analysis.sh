#!/bin/sh
# Distributed analysis from the command line: `mpirun -np P noiselab
# acf|psd|hist FIELD.h5 ...` for P = 1..4 against the one-process run of the
# same command on the same file.
#   --json outputs (every number at full precision): each array within
#   1e-12 of its largest |value| (mpi/analysis.h's bound), nulls and
#   strings identical;
#   text outputs: the same lines, numbers within 1e-12 of their column's
#   largest |value| plus the 10 digits they are printed with (5e-10 relative).
# Then bad input under -np 2: exit 2, one line on stderr, no hang.
# Usage: analysis.sh BINDIR  ($MPIRUN from run.sh)
set -u
bin=$1/noiselab
MPIRUN=${MPIRUN:-mpirun --oversubscribe --bind-to none -q}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
say() { echo "analysis.sh: $*"; fail=1; }

# JSON to "key<TAB>index<TAB>value" lines (value as jq prints it: null, numbers, strings)
flat() { jq -r 'paths(scalars) as $p | [($p[0]|tostring), ($p[1:]|map(tostring)|join(".")), (getpath($p)|tostring)] | @tsv' "$1"; }

cmp_json() { # reference, candidate, label
    flat "$1" >"$work/a" && flat "$2" >"$work/b" || { say "$3: not JSON"; return; }
    paste "$work/a" "$work/b" | awk -F'\t' -v what="$3" '
        function num(s) { return s ~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/ }
        { k[NR] = $1; a[NR] = $3; b[NR] = $6
          if ($1 != $4 || $2 != $5) { print what ": key " $1 "." $2 " against " $4 "." $5; bad = 1 }
          if (num($3)) { v = $3 < 0 ? -$3 : $3; if (v > sc[$1]) sc[$1] = v } }
        END { for (i = 1; i <= NR; i++) {
                  if (!num(a[i]) || !num(b[i])) { if (a[i] != b[i]) { print what ": " k[i] " " a[i] " against " b[i]; bad = 1 } continue }
                  d = a[i] - b[i]; if (d < 0) d = -d
                  if (d > 1e-12 * sc[k[i]]) { print what ": " k[i] " " b[i] ", expected " a[i] " (within 1e-12 of " sc[k[i]] ")"; bad = 1 } }
              exit bad }' || fail=1
}

cmp_text() { # reference, candidate, label
    [ "$(wc -l <"$1")" = "$(wc -l <"$2")" ] || { say "$3: $(wc -l <"$2") lines, expected $(wc -l <"$1")"; return; }
    paste "$1" "$2" | awk -F'\t' -v what="$3" '
        function num(s) { return s ~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/ }
        { for (j = 1; j <= NF; j++) f[NR, j] = $j; nf[NR] = NF
          h = NF / 2; for (j = 1; j <= h; j++) if (num($j)) { v = $j < 0 ? -$j : $j; if (v > sc[j]) sc[j] = v } }
        END { for (i = 1; i <= NR; i++) { h = nf[i] / 2
                  for (j = 1; j <= h; j++) {
                      x = f[i, j]; y = f[i, j + h]
                      if (!num(x) || !num(y)) {
                          # comment lines: compare word by word, numbers to their own print precision
                          n1 = split(x, u, / /); n2 = split(y, w, / /)
                          if (n1 != n2) { print what ": line " i ": " y ", expected " x; bad = 1; continue }
                          for (m = 1; m <= n1; m++) {
                              if (!num(u[m]) || !num(w[m])) { if (u[m] != w[m]) { print what ": line " i ": " y ", expected " x; bad = 1 } continue }
                              d = u[m] - w[m]; d = d < 0 ? -d : d; v = u[m] < 0 ? -u[m] : u[m]
                              if (d > 5e-10 * v + 1e-12) { print what ": line " i ": " w[m] ", expected " u[m]; bad = 1 } }
                          continue }
                      d = x - y; d = d < 0 ? -d : d; v = x < 0 ? -x : x
                      if (d > 1e-12 * sc[j] + 5e-10 * v) { print what ": line " i " column " j ": " y ", expected " x; bad = 1 } } }
              exit bad }' || fail=1
}

# Run one command on 1 process (no launcher) and under mpirun -np 1..4.
check() { # args...
    if ! "$bin" "$@" >"$work/ref" 2>"$work/ref.err"; then say "one process: noiselab $*: $(cat "$work/ref.err")"; return; fi
    for p in ${MPI_NPS:-1 2 3 4}; do
        if ! timeout 120 $MPIRUN -np $p "$bin" "$@" >"$work/out" 2>"$work/err"; then
            say "-np $p noiselab $*: $(cat "$work/err")"; continue
        fi
        case " $* " in
        *" --json "*) cmp_json "$work/ref" "$work/out" "-np $p noiselab $*" ;;
        *) cmp_text "$work/ref" "$work/out" "-np $p noiselab $*" ;;
        esac
    done
}

"$bin" synth fft --acf gauss:scale=4 --size 64x45 --seed 3 --precision double -o "$work/f2.h5" &&
"$bin" synth fft --acf markov:scale=3 --clamp --size 20x18x15 --seed 2 -o "$work/f3.h5" &&
"$bin" synth fft --acf markov:scale=5 --clamp --size 301 --seed 4 --precision double -o "$work/f1.h5" ||
    { echo "analysis.sh: cannot make the fields"; exit 1; }
f1=$work/f1.h5 f2=$work/f2.h5 f3=$work/f3.h5
# a field that records a band-limited model (psd --slope keeps inside it)
"$bin" synth fft --spectrum power:d=1 --size 2048 --seed 5 --precision double -o "$work/fp.h5" || say "cannot make fp.h5"
fp=$work/fp.h5
"$bin" synth fft --acf markov:scale=5 --clamp --size 64 --seed 4 -o "$work/f.tsv" || say "cannot make f.tsv"

check acf "$f2"
check acf --json --unbiased --axis y --max-lag 30 "$f2"
check acf --json --radial "$f2"
check acf --json --radial --unbiased --mean 0.1 "$f3"
check acf --json --axis z "$f3"
check acf --json --target gauss:scale=4 "$f2"
check acf --json "$f1"
check acf --radial -o "$work/acf.tsv" "$f3"
check psd "$f2"
check psd --json "$f2"
check psd --json --angular "$f2"
check psd --angular "$f2"
check psd --json --mean 0 "$f3"
check psd --json --slope 0.01:0.3 "$f1"
check psd --json --slope 0.02:0.25 "$f2"
check psd --slope 0.05:0.4 "$f3"
check psd --json --slope 0.001:0.4 "$fp"
check hist "$f2"
check hist --json "$f2"
check hist --json --bins 13 "$f3"
check hist --bins 1 "$f1"
# an output file is written by rank 0 alone, whole
rm -f "$work/o.tsv"
timeout 120 $MPIRUN -np 3 "$bin" hist --bins 9 -o "$work/o.tsv" "$f3" && "$bin" hist --bins 9 -o "$work/r.tsv" "$f3" &&
    cmp_text "$work/r.tsv" "$work/o.tsv" "hist -o under -np 3"
[ "$(ls "$work" | grep -c '\.tmp\.')" = 0 ] || say "temporary files left: $(ls "$work")"

# Memory per process: an estimate one process refuses under a limit runs
# on 4 processes under the same limit, each holding its share.
"$bin" synth fft --acf markov:scale=8 --clamp --size 512x512 --seed 5 -o "$work/big.h5" || say "cannot make big.h5"
# one process: 2 MB of samples, 4.2 MB for the periodogram's transform, 16.8 MB
# for the autocorrelation's padded one; 4 processes: a quarter of each
for run in "3000000 acf --radial" "3000000 psd" "1500000 hist"; do
    set -- $run
    lim=$1; shift
    NOISELAB_MEMORY_LIMIT=$lim "$bin" "$@" "$work/big.h5" >/dev/null 2>&1 && say "$*: one process ran under $lim bytes"
    NOISELAB_MEMORY_LIMIT=$lim timeout 120 $MPIRUN -x NOISELAB_MEMORY_LIMIT -np 4 "$bin" "$@" "$work/big.h5" \
        >"$work/out" 2>"$work/err" || say "-np 4 $* under $lim bytes: $(cat "$work/err")"
done

# Bad input: exit 2, exactly one line on stderr (rank 0's), no hang.
bad() { # expected words, args...
    want=$1; shift
    timeout 60 $MPIRUN -np 2 "$bin" "$@" >"$work/out" 2>"$work/err"
    rc=$?
    if [ $rc != 2 ] || [ "$(wc -l <"$work/err")" != 1 ] || ! grep -q -- "$want" "$work/err"; then
        say "-np 2 noiselab $*: exit $rc (expected 2), stderr:"; sed 's/^/    /' "$work/err"
    fi
}
bad "--max-lag" acf --max-lag 1000 "$f2"
bad "--direct" acf --direct "$f2"
bad "--target with a spectral model" acf --target power:d=2.5 "$f2"
bad "--welch" psd --welch 16 "$f2"
bad "--angular" psd --angular "$f3"
bad "--against" hist --against gauss "$f2"
bad "missing.h5" hist "$work/missing.h5"
bad "missing.h5" psd "$work/missing.h5"
bad "missing.h5" acf "$work/missing.h5"
bad "an ensemble" acf "$f2" "$f2"
bad "--realizations" psd --realizations 2 --acf markov:scale=3 --size 32x32
bad "not .h5" hist "$work/f.tsv"
bad "bins" hist --bins 0 "$f2"
bad "--slope 3:4" psd --slope 3:4 "$f2"
bad "fmin = 0.0009765625" psd --slope 0.0001:0.4 "$fp"
bad "-o" hist -o "$work/no/such/dir/x.tsv" "$f2"

[ $fail = 0 ] && echo "analysis.sh: distributed acf, psd and hist agree with one process"
exit $fail
