#!/bin/sh
# noiselab.pc on stdout, from noiselab.pc.in.  The prefix is named relative
# to the folder that holds the .pc file (${pcfiledir}, which pkg-config and
# pkgconf both define), so the file describes the tree it sits in: a staged
# install (DESTDIR) or a moved one works with PKG_CONFIG_PATH alone, without
# --define-prefix, and a normal install as well.  Folders outside PREFIX
# (LIBDIR=/opt/lib with PREFIX=/usr), or a PCDIR outside PREFIX, stay absolute.
# usage: tools/pcfile.sh TEMPLATE PREFIX LIBDIR INCLUDEDIR PCDIR VERSION LIBS_PRIVATE
set -eu
[ $# -eq 7 ] || { echo "usage: tools/pcfile.sh TEMPLATE PREFIX LIBDIR INCLUDEDIR PCDIR VERSION LIBS_PRIVATE" >&2; exit 2; }
template=$1 libs_private=$7 version=$6
# Trailing slashes off, so that PREFIX=/usr/ and PCDIR=/usr/lib/pkgconfig/ match.
trim() { printf '%s\n' "$1" | sed 's|//*$||'; }
prefix=$(trim "$2") libdir=$(trim "$3") includedir=$(trim "$4") pcdir=$(trim "$5")

# ${prefix}/REST for a folder under PREFIX, else the folder itself.
under_prefix() {
    case $1 in
    "$prefix") printf '%s\n' '${prefix}' ;;
    "$prefix"/*) printf '%s\n' "\${prefix}/${1#"$prefix"/}" ;;
    *) printf '%s\n' "$1" ;;
    esac
}

# PCDIR under PREFIX: one .. per folder between them (lib/pkgconfig: ../..).
case $pcdir in
"$prefix"/*)
    up=$(printf '%s\n' "${pcdir#"$prefix"/}" | sed 's|/\{1,\}|/|g; s|[^/][^/]*|..|g')
    pc_prefix="\${pcfiledir}/$up" ;;
*) pc_prefix=$prefix ;;
esac

sed -e "s|@PREFIX@|$pc_prefix|; s|@LIBDIR@|$(under_prefix "$libdir")|; s|@INCLUDEDIR@|$(under_prefix "$includedir")|" \
    -e "s|@VERSION@|$version|; s|@LIBS_PRIVATE@|$libs_private|" "$template"
