# Design round trip. gnuplot -e "a='A.tsv'; b='B.tsv'; out='O.png'" plots/design.gp
set terminal pngcairo size 1100,450 font "DejaVu Sans,11"
set output out
set multiplot layout 1,2
set grid; set key top right; set xlabel "lag (samples)"; set ylabel "autocovariance (variance at lag 0)"
set title "target exp(-|t|/8) after a Laplace shaping"
plot a using 1:2 with lines lw 3 lc rgb "black" title "target", \
     a using 1:($3*2) with lines dt 2 lc rgb "#1f4e99" title "designed input (x var)", \
     a using 1:5 with points pt 7 ps 0.4 lc rgb "#b22222" title "measured output"
set title "target cos(0.3t) exp(-|t|/20) after chi2-1: out of reach"
plot b using 1:2 with lines lw 3 lc rgb "black" title "target", \
     b using 1:4 with lines dt 2 lc rgb "#1f4e99" title "best reachable (predicted)", \
     b using 1:5 with points pt 7 ps 0.4 lc rgb "#b22222" title "measured output"
unset multiplot
