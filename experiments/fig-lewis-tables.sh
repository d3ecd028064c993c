#!/bin/sh
# Lewis 1987, Tables 1 and 2: subdivision coefficients recomputed and
# compared digit by digit (see experiments/lewis_tables.c).
set -eu
dir=$1
top=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$dir/data"
"${NOISELAB_EXPERIMENTS:-$top/build/experiments}/lewis_tables" "$dir/data/10-lewis-tables.md"
