#!/bin/sh
# Each shared library exports exactly what its installed headers declare:
# nm -D --defined-only of libnoiselab.so and libnoiselab_mpi.so against the
# functions tools/exports.sh finds in the headers, every difference either
# way named (a function a header declares that the library does not define
# is as wrong as an internal one it lets out).  Also: the GSL guard, whose
# state is process-wide, is libnoiselab.so's alone (libnoiselab_mpi.so
# links hidden copies of a few stateless objects, see the Makefile).
#
# usage: tests/api/exports.sh LIBNOISELAB.so LIBNOISELAB_MPI.so
#   PUB_HDR, MPI_HDR: the installed module headers (the Makefile's lists);
#   MPI_CFLAGS: MPI's and HDF5's include flags.
set -u
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
fail=0

# same LIBRARY HEADER...: the library's defined dynamic symbols against the
# headers' functions.
same() {
    lib=$1
    shift
    if ! sh tools/exports.sh "$@" >"$tmp/decl" 2>"$tmp/log"; then
        echo "exports: FAILED tools/exports.sh for $lib" >&2
        sed 's/^/    /' "$tmp/log" >&2
        fail=$((fail + 1))
        return
    fi
    awk '{ print $1 }' "$tmp/decl" | LC_ALL=C sort -u >"$tmp/want"
    nm -D --defined-only "$lib" | awk 'NF >= 3 { print $NF }' | LC_ALL=C sort -u >"$tmp/have"
    LC_ALL=C comm -13 "$tmp/want" "$tmp/have" | sed "s|^|    exported, declared by no installed header: |" >"$tmp/diff"
    LC_ALL=C comm -23 "$tmp/want" "$tmp/have" | sed "s|^|    declared, not exported: |" >>"$tmp/diff"
    if [ -s "$tmp/diff" ]; then
        echo "exports: FAILED $(basename "$lib")" >&2
        cat "$tmp/diff" >&2
        fail=$((fail + 1))
    else
        echo "exports: $(basename "$lib"): $(wc -l <"$tmp/have") functions, as its headers declare"
    fi
}

same "$1" ${PUB_HDR:-} include/noiselab.h
CPPFLAGS="${MPI_CFLAGS:-}" same "$2" ${MPI_HDR:-} include/noiselab_mpi.h
if nm "$2" 2>/dev/null | grep -q ' nl_gsl_'; then
    echo "exports: FAILED $(basename "$2") holds a copy of the GSL guard (core/gsl_guard.c)" >&2
    fail=$((fail + 1))
fi
[ "$fail" -eq 0 ]
