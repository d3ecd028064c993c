#!/bin/sh
# The method's own error: exact covariance of subdivision fields against the
# target, and the diagonal bias of the 2D mesh (experiments/subdiv_exact.c).
. "$(dirname "$0")/lib.sh"
"$xb/subdiv_exact" "$dir/data/25-subdiv-exact.md" "$dir/data/subdiv-exact.tsv" "$dir/data/subdiv-diagonal.tsv" \
    "$dir/data/subdiv-corr.tsv"
gnuplot -e "data='$dir/data/subdiv-exact.tsv'; out='$dir/subdiv-exact.png'" "$top/plots/subdiv_exact.gp"
gnuplot -e "data='$dir/data/subdiv-diagonal.tsv'; out='$dir/subdiv-diagonal.png'" "$top/plots/diagonal.gp"
gnuplot -e "data='$dir/data/subdiv-corr.tsv'; out='$dir/subdiv-corr.png'" "$top/plots/subdiv_corr.gp"
