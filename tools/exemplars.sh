#!/bin/sh
# Fetch the exemplar images (grass, gravel, brick, camera; BSD-3-Clause) from
# Debian's python3-skimage package into DIR, without installing it.
set -e
dir=$1
mkdir -p "$dir"
cd "$dir"
[ -f grass.png ] && [ -f gravel.png ] && [ -f brick.png ] && [ -f camera.png ] && exit 0
rm -f python3-skimage_*.deb
apt-get download python3-skimage >/dev/null 2>&1 || {
    [ "$(id -u)" = 0 ] && apt-get update -q >/dev/null 2>&1 && apt-get download python3-skimage >/dev/null 2>&1
} || { echo "noiselab: cannot download python3-skimage for the exemplar images" >&2; exit 1; }
p=./usr/lib/python3/dist-packages/skimage/data
dpkg-deb --fsys-tarfile python3-skimage_*.deb |
    tar -x --strip-components=7 -f - $p/grass.png $p/gravel.png $p/brick.png $p/camera.png
rm -f python3-skimage_*.deb
