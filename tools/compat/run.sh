#!/bin/sh
# Runs every line of tools/compat/commands.txt with two builds and compares
# what they did: per line stdout, stderr and exit status, and every file the
# lines wrote, byte for byte (version strings and timings normalised, see
# compare.py).  One line per difference, then "N passed, M failed".
#
#   sh tools/compat/run.sh BASE_BINDIR NEW_BINDIR
#
# Each build's noiselab and noiselab-mpi are copied to the same place and
# the lines run in a fresh folder at the same path, so absolute paths in
# the outputs agree; the environment is fixed (env -i): LC_ALL=C,
# OMP_NUM_THREADS=2, NOISELAB_FFTW=estimate (no wisdom: the same FFTW plans
# for both), an empty HOME.  COMPAT_COMMANDS=FILE runs another list;
# COMPAT_KEEP=1 keeps the folders (they are kept anyway when a line differs);
# COMPAT_RAW=1 leaves the timings as they are (to find what varies: run one
# build against itself).
# Exit status 0 when everything agrees, 1 when something differs, 2 for bad
# usage.
set -u
export LC_ALL=C
if [ $# -ne 2 ] || [ ! -x "$1/noiselab" ] || [ ! -x "$2/noiselab" ]; then
    echo "usage: $0 BASE_BINDIR NEW_BINDIR (each holding noiselab and noiselab-mpi)" >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
base=$(cd "$1" && pwd)
new=$(cd "$2" && pwd)
cmds=${COMPAT_COMMANDS:-$here/commands.txt}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/compat.XXXXXX") || exit 2
timeout_s=${COMPAT_TIMEOUT:-300}

# run_build BINDIR NAME: every line in $tmp/w/run, then $tmp/w moves to $tmp/NAME
run_build() {
    w=$tmp/w
    rm -rf "$w"
    mkdir -p "$w/bin" "$w/lib" "$w/run" "$w/out" "$w/home" "$w/tmp"
    cp "$1/noiselab" "$w/bin/"
    [ -x "$1/noiselab-mpi" ] && cp "$1/noiselab-mpi" "$w/bin/"
    # the shared libraries where the build has them (the programs link the
    # static library today; a later build may not)
    if [ -d "$1/../build" ]; then
        for f in "$1"/../build/libnoiselab*.so*; do
            [ -e "$f" ] && cp -P "$f" "$w/lib/"
        done
    fi
    "$w/bin/noiselab" --version 2>/dev/null | awk '{print $NF; exit}' > "$tmp/$2.version"
    n=0
    start=$(date +%s)
    : > "$w/listing"
    while IFS= read -r line || [ -n "$line" ]; do
        n=$((n + 1))
        case "$line" in '' | '#'*) continue ;; esac
        printf '%s\n' "$line" > "$w/out/$n.cmd"
        (cd "$w/run" && env -i PATH="$w/bin:/usr/local/bin:/usr/bin:/bin" HOME="$w/home" TMPDIR="$w/tmp" \
            LD_LIBRARY_PATH="$w/lib" LC_ALL=C OMP_NUM_THREADS=2 NOISELAB_FFTW=estimate \
            OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
            timeout "$timeout_s" sh -c "$line" < /dev/null > "$w/out/$n.out" 2> "$w/out/$n.err"
            echo $? > "$w/out/$n.rc")
        # the files this line made or changed (path, mtime, size, inode against
        # the listing after the line before; a file belongs to the last line
        # that changed it)
        (cd "$w/run" && find . -type f -printf '%p\t%T@ %s %i\n' | sort > "$w/listing.new")
        comm -13 "$w/listing" "$w/listing.new" | cut -f1 > "$w/out/$n.files"
        mv "$w/listing.new" "$w/listing"
    done < "$cmds"
    echo "compat: $2 ($1): $(ls "$w/out" | grep -c '\.cmd$') lines in $(( $(date +%s) - start )) s" >&2
    mv "$w" "$tmp/$2"
}

run_build "$base" base
run_build "$new" new
python3 "$here/compare.py" "$tmp/base" "$tmp/new" "$(cat "$tmp/base.version")" "$(cat "$tmp/new.version")"
status=$?
if [ $status -eq 0 ] && [ "${COMPAT_KEEP:-0}" != 1 ]; then
    rm -rf "$tmp"
else
    echo "compat: the runs are in $tmp (base/, new/: run/ the files, out/ N.cmd N.out N.err N.rc N.files)" >&2
fi
exit $status
