#!/bin/sh
# Install the Debian packages of deps.txt that are missing (apt-get as root, sudo otherwise).
set -e
list=$(grep -v '^#' "$(dirname "$0")/../deps.txt" | tr '\n' ' ')
missing=""
for p in $list; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "noiselab: installing Debian packages:$missing" >&2
if [ "$(id -u)" = 0 ]; then SUDO=""; else SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q >&2
$SUDO apt-get install -y -q --no-install-recommends $missing >&2
