#!/bin/sh
# The quick subset of the experiments that `make test` runs: each one's
# verdict must pass, exactly as in `make figures`, but into a scratch folder.
set -eu
dir=$1
top=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$dir"
fail=0
for e in lewis-tables creases aliasing gi86-fig7; do
    if sh "$top/experiments/fig-$e.sh" "$dir" >"$dir/$e.log" 2>&1; then
        echo "experiment $e: verdict passed"
    else
        echo "experiment $e: verdict FAILED (see $dir/$e.log)" >&2
        fail=$((fail + 1))
    fi
done
[ "$fail" -eq 0 ]
