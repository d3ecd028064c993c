#!/bin/sh
# Lewis 1987, Tables 1 and 2: subdivision coefficients recomputed and
# compared digit by digit (see experiments/lewis_tables.c).
. "$(dirname "$0")/lib.sh"
"$xb/lewis_tables" "$dir/data/10-lewis-tables.md"
