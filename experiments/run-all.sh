#!/bin/sh
# Run every experiment into DIR (default paper-figures/) and write DIR/index.md.
set -eu
dir=${1:-paper-figures}
top=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$dir"
start=$(date +%s)
fail=0
for e in "$top"/experiments/fig-*.sh; do
    echo "== $(basename "$e")" >&2
    sh "$e" "$dir" || fail=$((fail + 1))
done
sh "$top/experiments/index.sh" "$dir" "$(( $(date +%s) - start ))"
[ "$fail" -eq 0 ] || { echo "noiselab figures: $fail experiment(s) failed their verdict" >&2; exit 1; }
