#!/bin/sh
# Fetch the exemplar images into DIR from Debian packages, without
# installing them: grass, gravel, brick, camera (BSD-3-Clause) from
# python3-skimage; the GIMP patterns stone33 (a fieldstone wall) and fibers
# (scattered straws) from gimp-data (GPL-3+).
set -e
dir=$1
mkdir -p "$dir"
cd "$dir"
[ -f grass.png ] && [ -f gravel.png ] && [ -f brick.png ] && [ -f camera.png ] && [ -f stone33.pat ] &&
    [ -f fibers.pat ] && exit 0
fetch() { # PACKAGE
    rm -f "$1"_*.deb
    apt-get download "$1" >/dev/null 2>&1 || {
        [ "$(id -u)" = 0 ] && apt-get update -q >/dev/null 2>&1 && apt-get download "$1" >/dev/null 2>&1
    } || { echo "noiselab: cannot download $1 for the exemplar images" >&2; exit 1; }
}
fetch python3-skimage
p=./usr/lib/python3/dist-packages/skimage/data
dpkg-deb --fsys-tarfile python3-skimage_*.deb |
    tar -x --strip-components=7 -f - $p/grass.png $p/gravel.png $p/brick.png $p/camera.png
rm -f python3-skimage_*.deb
fetch gimp-data
p=./usr/share/gimp/2.0/patterns
dpkg-deb --fsys-tarfile gimp-data_*.deb | tar -x --strip-components=7 -f - $p/Stone/stone33.pat $p/Legacy/fibers.pat
rm -f gimp-data_*.deb
