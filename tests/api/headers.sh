#!/bin/sh
# Every installed header compiles on its own, as C11 and as C++ (-Wall
# -Wextra -Werror), and a C++ program that includes it alone calls its
# functions with C linkage (extern "C": the address of each function the
# header declares, taken in C++, names the unmangled symbol).
#
# usage: tests/api/headers.sh
#   PUB_HDR, MPI_HDR: the installed module headers (the Makefile's lists);
#   MPI_CFLAGS: MPI's and HDF5's include flags; CC, CXX (gcc, g++).
set -u
cd "$(dirname "$0")/../.."
CC=${CC:-gcc}
CXX=${CXX:-g++}
# MPI's own headers are system headers: their warnings are not ours.
mpi_sys=$(printf '%s\n' ${MPI_CFLAGS:-} | sed 's/^-I/-isystem /' | tr '\n' ' ')
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
pass=0
fail=0

bad() {
    fail=$((fail + 1))
    echo "headers: FAILED $1" >&2
    sed 's/^/    /' "$tmp/log" >&2
}

CPPFLAGS="$mpi_sys" sh tools/exports.sh ${PUB_HDR:-} ${MPI_HDR:-} >"$tmp/decl" 2>"$tmp/log" || { bad "tools/exports.sh"; exit 1; }
for h in ${PUB_HDR:-} ${MPI_HDR:-} include/*.h; do
    printf '#include "%s"\n' "$h" >"$tmp/t.c"
    if $CC -std=c11 -Wall -Wextra -Werror -fsyntax-only -I. $mpi_sys -x c "$tmp/t.c" >"$tmp/log" 2>&1; then
        pass=$((pass + 1))
    else
        bad "$h alone as C11"
    fi
    # C++: the header alone, then the address of each function it declares
    awk -v h="$h" '$2 == h { printf "void *take_%s = (void *)&%s;\n", $1, $1 }' "$tmp/decl" >>"$tmp/t.c"
    if $CXX -Wall -Wextra -Werror -c -I. $mpi_sys -x c++ "$tmp/t.c" -o "$tmp/t.o" >"$tmp/log" 2>&1; then
        pass=$((pass + 1))
        nm -u "$tmp/t.o" | awk '{ print $NF }' >"$tmp/undef"
        if awk -v h="$h" 'NR == FNR { seen[$1] = 1; next }
            $2 == h && !seen[$1] { print $1 ": not an unmangled (extern \"C\") symbol in C++"; bad = 1 }
            END { exit bad }' "$tmp/undef" "$tmp/decl" >"$tmp/log"; then
            pass=$((pass + 1))
        else
            bad "$h: extern \"C\""
        fi
    else
        bad "$h alone as C++"
    fi
done
echo "headers: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
