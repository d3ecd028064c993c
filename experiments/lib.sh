# Sourced by every experiment (`. "$(dirname "$0")/lib.sh"`, with the output
# folder as the experiment's $1): sets dir (that folder), d (its data/, made
# here), top (the repository), nl (the noiselab binary; $NOISELAB overrides)
# and xb (the experiments' C programs; $NOISELAB_EXPERIMENTS overrides).
set -eu
dir=$1
top=$(cd "$(dirname "$0")/.." && pwd)
nl=${NOISELAB:-$top/bin/noiselab}
xb=${NOISELAB_EXPERIMENTS:-$top/build/experiments}
d=$dir/data
mkdir -p "$d"

# per_sd FIELD K: K over the field's standard deviation (a height scale that
# draws K units per standard deviation whatever the field's variance)
per_sd() {
    awk -v v="$("$nl" hist "$1" | sed -n 's/^# variance //p')" -v k="$2" 'BEGIN { print k / sqrt(v) }'
}

# psd_peak FIELD: the frequency at which the field's (radial) spectrum peaks
psd_peak() {
    "$nl" psd "$1" --json | jq '[.freq, .psd] | transpose | max_by(.[1]) | .[0]'
}

# landscape FIELD OUT K [render options]: FIELD in perspective (noiselab
# render --perspective, 800 x 450) with heights of K samples per standard
# deviation
landscape() {
    _f=$1 _o=$2 _k=$3
    shift 3
    "$nl" render "$_f" --perspective --size 800x450 --zscale "$(per_sd "$_f" "$_k")" "$@" -o "$_o"
}
