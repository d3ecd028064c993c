#!/bin/sh
# The library as a user gets it: `make install` into a scratch DESTDIR
# (writing nothing into the checkout), then every program of examples/ and
# the README's C example ("Using the library") built with the README's two
# pkg-config lines, as written there, against the shared and against the
# static library, and run; noiselab.pc found by PKG_CONFIG_PATH alone (no
# sysroot, no --define-prefix), also once the tree is moved; the installed
# headers, man page and symbols checked; the Python package imported from the
# DESTDIR with the installed library; the include layering of the source
# folders checked; `make uninstall` leaves no file behind.  Called by `make
# test` with CC, EXAMPLE_CFLAGS (the build's optimisation and sanitizer
# flags), MAKE and VERSION in the environment.
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
CC=${CC:-cc}
MAKE=${MAKE:-make}
EXAMPLE_CFLAGS=${EXAMPLE_CFLAGS:--O2}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
root=$tmp/root
prefix=/usr/local
libdir=$root$prefix/lib
pass=0
fail=0

# check NAME COMMAND...: run it, count it, show its output when it fails.
check() {
    name=$1
    shift
    if "$@" >"$tmp/log" 2>&1; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "install: FAILED $name" >&2
        sed 's/^/    /' "$tmp/log" >&2
    fi
}

# Only nl_ and NL_ names exported (nm output on stdin, name in the last field;
# AddressSanitizer adds a __odr_asan.NAME marker for each nl_ data object).
only_nl() { awk 'NF >= 2 && $NF !~ /^(nl_|NL_|__odr_asan[.]nl_)/ { print "not in the nl_ namespace: " $NF; bad = 1 } END { exit bad }'; }

# An #include "..." of an installed header that is not installed itself.
includes_installed() {
    bad=0
    for h in $(find "$root$prefix/include" -name '*.h'); do
        for inc in $(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$h"); do
            [ -f "$(dirname "$h")/$inc" ] || { echo "${h#$root}: includes \"$inc\", which is not installed"; bad=1; }
        done
    done
    return $bad
}

# Every installed module header is reachable from noiselab.h.
front_door_complete() {
    bad=0
    for h in $(cd "$root$prefix/include" && find noiselab -name '*.h' | sort); do
        front=noiselab.h
        case $h in noiselab/mpi/*) front=noiselab_mpi.h ;; esac
        grep -q "^#include \"$h\"" "$root$prefix/include/$front" || { echo "$front does not include $h"; bad=1; }
    done
    return $bad
}

# Each installed header compiles on its own.
self_contained() {
    bad=0
    for h in $(cd "$root$prefix/include" && find noiselab -name '*.h' | sort); do
        printf '#include <%s>\n' "$h" | $CC -std=c11 -Wall -Wextra -Werror -fsyntax-only $cflags $mpiflags -x c - || { echo "$h is not self-contained"; bad=1; }
    done
    return $bad
}

# No folder includes one above it: core <- synth, analysis, render <- cli
# (analysis may use synth; render may use synth and analysis).
layering() {
    bad=0
    for rule in "core:synth|analysis|render|cli|bench" "synth:analysis|render|cli|bench" \
        "analysis:render|cli|bench" "render:cli|bench"; do
        dir=${rule%%:*}
        grep -nE "^[[:space:]]*#[[:space:]]*include[[:space:]]*\"(\.\./)?(${rule#*:})/" "$dir"/*.c "$dir"/*.h 2>/dev/null &&
            { echo "  ^ $dir/ may not include these"; bad=1; }
    done
    return $bad
}

no_file_left() {
    left=$(find "$root" ! -type d)
    [ -z "$left" ] || { echo "left after uninstall:"; echo "$left"; return 1; }
}

# build_run NAME SRC: the program against the shared library, then the static one.
# The README's lines `cc app.c $(pkg-config ...)` under "make install", as
# written there (comments off): the first for the shared library, the second
# (--static) for libnoiselab.a.
readme_cc() {
    awk '/doc-test: skip \(tools\/test-install.sh/ { blk = 1; next }
         blk && /^    cc app[.]c / { sub(/^    /, ""); sub(/[[:space:]]+#[^#]*$/, ""); print; next }
         blk && /^[^ ]/ && !/^$/ { exit }' README.md
}
cc_shared=$(readme_cc | grep -v -e '--static' | head -n 1)
cc_static=$(readme_cc | grep -e '--static' | head -n 1)
# cc as the README's lines call it, with the build's flags (sanitizers under make asan).
cc() { command $CC $EXAMPLE_CFLAGS "$@"; }
# in_dir DIR LINE: run LINE (a README command) in DIR.
in_dir() { (cd "$1" && eval "$2"); }

# build_run NAME SRC: the program, as app.c, built by the README's lines
# against the shared library, then the static one, and run.
build_run() {
    d=$tmp/$1
    mkdir -p "$d" && cp "$2" "$d/app.c"
    check "$1: README's line builds it against libnoiselab.so" in_dir "$d" "$cc_shared -o shared"
    check "$1: run against the installed libnoiselab.so" sh -c "LD_LIBRARY_PATH='$libdir' ldd '$d/shared' | grep -q '=> $libdir/libnoiselab.so' && \
        LD_LIBRARY_PATH='$libdir' '$d/shared'"
    check "$1: README's --static line builds it against libnoiselab.a" in_dir "$d" "$cc_static -o static"
    check "$1: linked with libnoiselab.a, ldd names no libnoiselab" sh -c "ldd '$d/static' && ! ldd '$d/static' | grep -q libnoiselab"
    check "$1: run, linked statically" "$d/static"
}

# The checkout as git and the clock see it, build/ and bin/ left out (what
# make builds), to show that install and uninstall write nothing else.
tree_state() {
    if git -C "$top" rev-parse --git-dir >/dev/null 2>&1; then
        git -C "$top" status --porcelain --ignored --untracked-files=all | grep -v -e '^.. build/' -e '^.. bin/'
    fi
    find "$top" \( -path "$top/.git" -o -path "$top/build" -o -path "$top/bin" \) -prune -o -newer "$tmp/stamp" -print
}
wrote_nothing() {
    tree_state >"$tmp/after"
    diff -u "$tmp/before" "$tmp/after" || { echo "^ written into the checkout (+ lines)"; false; }
}

# PKG_CONFIG_PATH=DIR pkg-config --variable=VAR noiselab names the folder WANT.
pc_names() {
    got=$(PKG_CONFIG_PATH=$1 pkg-config --variable="$2" noiselab) &&
        [ -d "$got" ] && [ "$(cd "$got" && pwd -P)" = "$(cd "$3" && pwd -P)" ] ||
        { echo "$2 is \"$got\", expected $3"; false; }
}

check "README: the two cc lines under make install" test -n "$cc_shared" -a -n "$cc_static"
# Whatever install needs is built first, so that the checkout's state is
# compared around the install alone.
$MAKE --no-print-directory all wisdom >"$tmp/log" 2>&1 || { echo "install: make all failed" >&2; cat "$tmp/log" >&2; exit 1; }
touch "$tmp/stamp"
sleep 1 # (find -newer: a second apart on coarse clocks)
tree_state >"$tmp/before"
check "make install DESTDIR=..." $MAKE --no-print-directory install DESTDIR="$root" PREFIX=$prefix
check "make install wrote nothing into the checkout" wrote_nothing
# As a user of a staged tree does it: no PKG_CONFIG_SYSROOT_DIR, no --define-prefix.
unset PKG_CONFIG_SYSROOT_DIR PKG_CONFIG_LIBDIR
export PKG_CONFIG_PATH="$libdir/pkgconfig"
check "pkg-config finds the staged includedir" pc_names "$libdir/pkgconfig" includedir "$root$prefix/include"
check "pkg-config finds the staged libdir" pc_names "$libdir/pkgconfig" libdir "$libdir"
# A moved tree describes itself too.
mv "$root" "$tmp/moved"
check "pkg-config finds a moved tree's libdir" pc_names "$tmp/moved$prefix/lib/pkgconfig" libdir "$tmp/moved$prefix/lib"
mv "$tmp/moved" "$root"
# Debian's multiarch layout: PCDIR three folders under PREFIX.
ma=$tmp/ma/usr/lib/x86_64-linux-gnu
mkdir -p "$ma/pkgconfig"
sh tools/pcfile.sh noiselab.pc.in /usr /usr/lib/x86_64-linux-gnu /usr/include /usr/lib/x86_64-linux-gnu/pkgconfig "$VERSION" -lm \
    >"$ma/pkgconfig/noiselab.pc"
mkdir -p "$tmp/ma/usr/include"
check "multiarch noiselab.pc: libdir" pc_names "$ma/pkgconfig" libdir "$ma"
check "multiarch noiselab.pc: includedir" pc_names "$ma/pkgconfig" includedir "$tmp/ma/usr/include"
export NOISELAB_FFTW=estimate # as in the other tests: no measured plans
cflags=$(pkg-config --cflags noiselab)
mpiflags=$(PKG_CONFIG_PATH= PKG_CONFIG_SYSROOT_DIR= pkg-config --cflags hdf5-openmpi mpi)

for f in bin/noiselab-mpi lib/libnoiselab_mpi.a lib/libnoiselab_mpi.so include/noiselab_mpi.h bin/noiselab lib/libnoiselab.a lib/libnoiselab.so lib/libnoiselab.so.${VERSION%%.*} \
    lib/libnoiselab.so.$VERSION include/noiselab.h lib/pkgconfig/noiselab.pc share/man/man1/noiselab.1; do
    check "$f installed" test -e "$root$prefix/$f"
done
check "soname libnoiselab.so.${VERSION%%.*}" sh -c "readelf -d '$libdir/libnoiselab.so.$VERSION' | grep -q 'SONAME.*\\[libnoiselab.so.${VERSION%%.*}\\]'"
check "examples installed" sh -c "ls '$root$prefix/share/doc/noiselab/examples/'*.c"
check "pkg-config --modversion is $VERSION" test "$(pkg-config --modversion noiselab)" = "$VERSION"
check "noiselab --version is $VERSION" test "$("$root$prefix/bin/noiselab" --version)" = "noiselab $VERSION"
check "installed headers include only installed headers" includes_installed
check "noiselab.h includes every installed header" front_door_complete
check "each installed header compiles on its own" self_contained
check "noiselab.h compiles as C++ (extern \"C\")" sh -c "printf '#include <noiselab.h>\nint main() { return nl_version() == 0; }\n' | \
    ${CXX:-g++} $EXAMPLE_CFLAGS -Wall -Werror -x c++ - $cflags -o '$tmp/cxx' \$(pkg-config --libs noiselab) && LD_LIBRARY_PATH='$libdir' '$tmp/cxx'"
check "man -l renders noiselab(1) without warnings" sh -c "MANWIDTH=80 man --warnings -l '$root$prefix/share/man/man1/noiselab.1' \
    2>'$tmp/man.err' | grep -q 'noiselab bench' && ! test -s '$tmp/man.err' || { cat '$tmp/man.err'; false; }"
check "man noiselab finds it with MANPATH" sh -c "test \"\$(MANPATH='$root$prefix/share/man' man -w noiselab)\" = '$root$prefix/share/man/man1/noiselab.1'"
nm -D --defined-only "$libdir/libnoiselab.so" >"$tmp/nm-so" 2>&1
check "nm -D libnoiselab.so: nl_/NL_ names only" only_nl <"$tmp/nm-so"
# Weak and unique definitions (nm types W, V, u) are the inline and template
# instantiations a C++ translation unit (core/formats/vdb_io.cc) emits for
# the headers it includes; the linker merges them with every other copy:
# they are not names the library defines.
nm -g --defined-only "$libdir/libnoiselab.a" 2>/dev/null | grep -v ':$' | grep -v ' [WVu] ' >"$tmp/nm-a"
check "nm -g libnoiselab.a: nl_/NL_ names only" only_nl <"$tmp/nm-a"
nm -D --defined-only "$libdir/libnoiselab_mpi.so" >"$tmp/nm-mpi" 2>&1
check "nm -D libnoiselab_mpi.so: nl_/NL_ names only" only_nl <"$tmp/nm-mpi"
# The distributed module as a user builds it, and the installed noiselab
# handing an .h5 run to the installed noiselab-mpi beside it.
printf '#include <noiselab.h>\n#include <noiselab_mpi.h>\nint main(void)\n{\n    size_t s0, ns;\n    nl_mpi_block(10, 3, 2, &s0, &ns);\n    return !(s0 == 8 && ns == 2);\n}\n' >"$tmp/mpi.c"
check "noiselab_mpi.h: a program builds and runs" sh -c "$CC $EXAMPLE_CFLAGS -o '$tmp/mpi' '$tmp/mpi.c' $cflags $mpiflags \
    -L'$libdir' -lnoiselab_mpi \$(pkg-config --libs noiselab) && LD_LIBRARY_PATH='$libdir' '$tmp/mpi'"
check "installed noiselab writes .h5 through noiselab-mpi" sh -c "LD_LIBRARY_PATH='$libdir' '$root$prefix/bin/noiselab' synth fft \
    --acf markov:scale=2 --size 16x16 -o '$tmp/i.h5' && h5dump -a /field/method '$tmp/i.h5' | grep -q fft"
check "include layering core <- synth, analysis, render <- cli" layering

# The version macros, the library's nl_version() and pkg-config agree.
printf '#include <noiselab.h>\n#include <stdio.h>\n#include <string.h>\nint main(void)\n{\n    printf("%%d.%%d.%%d\\n", NL_VERSION_MAJOR, NL_VERSION_MINOR, NL_VERSION_PATCH);\n    return strcmp(NL_VERSION_STRING, nl_version()) || strcmp(NL_VERSION_STRING, "%s");\n}\n' "$VERSION" >"$tmp/version.c"
build_run version "$tmp/version.c"

for src in examples/*.c; do
    build_run "$(basename "$src" .c)" "$src"
done
awk '/^## Using the library/ { in_sec = 1; next } /^## / { in_sec = 0 }
     in_sec && /^```c$/ { code = 1; next } code && /^```$/ { exit } code { print }' README.md >"$tmp/readme.c"
check "README: a \`\`\`c block under \"Using the library\"" test -s "$tmp/readme.c"
[ -s "$tmp/readme.c" ] && build_run readme "$tmp/readme.c"

# The Python package from the DESTDIR with the installed library (by its
# soname on LD_LIBRARY_PATH), outside the tree: the issue's one-liner.
pyver=$(/usr/bin/python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])')
pydir=$root$prefix/lib/python$pyver/dist-packages
check "python package installed in $prefix/lib/python$pyver/dist-packages" test -f "$pydir/noiselab/__init__.py"
cat >"$tmp/py.py" <<EOF
import noiselab
assert noiselab.__file__.startswith("$pydir"), noiselab.__file__
maps = [l.split()[-1] for l in open("/proc/self/maps") if "libnoiselab" in l]
assert maps and all(m.startswith("$libdir") for m in maps), maps
print(noiselab.synth('fft', acf='markov:scale=8', size=(64, 64), seed=7).std())
import sys
assert "matplotlib" not in sys.modules, "import noiselab imported matplotlib"
try:
    import matplotlib
except ImportError:  # noiselab.plot is optional: matplotlib (python3-matplotlib) is not a dependency
    matplotlib = None
if matplotlib:
    matplotlib.use("Agg")
    import noiselab.plot
    assert noiselab.plot.__file__.startswith("$pydir"), noiselab.plot.__file__
EOF
# (a sanitized library does not load into python3: not under make asan)
case $EXAMPLE_CFLAGS in
*sanitize*) echo "install: python import skipped (a sanitized library does not load into /usr/bin/python3)" ;;
*) check "python: import the installed package with the installed library" sh -c "cd '$tmp' && env -u NOISELAB_LIB \
    PYTHONDONTWRITEBYTECODE=1 PYTHONPATH='$pydir' LD_LIBRARY_PATH='$libdir' /usr/bin/python3 '$tmp/py.py'" ;;
esac

check "make uninstall" $MAKE --no-print-directory uninstall DESTDIR="$root" PREFIX=$prefix
check "make uninstall leaves no file" no_file_left
check "make install and uninstall wrote nothing into the checkout" wrote_nothing

echo "install: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
