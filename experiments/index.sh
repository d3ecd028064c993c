#!/bin/sh
# Write DIR/index.md from the experiments' fragments DIR/data/*.md.
set -eu
dir=$1
secs=$2
{
    echo "# noiselab: reproduced figures"
    echo
    echo "Made by \`make figures\` in ${secs} s on $(nproc) cores. Each section gives what is shown,"
    echo "our picture, the verdict numbers, and what differs from the paper and why."
    echo
    for f in "$dir"/data/*.md; do
        cat "$f"
    done
} > "$dir/index.md.tmp"
mv "$dir/index.md.tmp" "$dir/index.md"
