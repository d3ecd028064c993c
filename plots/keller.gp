# Keller 2001, Figs. 1 and 2.
# gnuplot -e "d='DIR'; out1='F1.png'; out2='F2.png'" plots/keller.gp
set terminal pngcairo size 900,450 font "DejaVu Sans,11"
set output out1
set multiplot layout 1,2
unset key; set size ratio -1; set xrange [0:1]; set yrange [0:1]; set xtics 0.25; set ytics 0.25
set xlabel "x (unit period)"; set ylabel "y (unit period)"
set title "rectangular grid, N = 64 (rank 2)"
plot d.'/grid64.tsv' using 1:2 with points pt 7 ps 0.8 lc rgb "#1f4e99"
set title "Fibonacci lattice, N = F_{10} = 55 (rank 1)"
plot d.'/fib55.tsv' using 1:2 with points pt 7 ps 0.8 lc rgb "#b22222"
unset multiplot
set terminal pngcairo size 1000,500 font "DejaVu Sans,11"
set output out2
set multiplot layout 1,2
set title "periodic Delaunay triangulation, N = 55"
plot for [dx=-1:0] for [dy=-1:0] d.'/fib55-tri.tsv' using ($1+dx):($2+dy) with lines lc rgb "#555555", \
     d.'/fib55.tsv' using 1:2 with points pt 7 ps 0.7 lc rgb "#b22222"
set title "wave vectors K_N, N = F_{10} .. F_{17}"
set xrange [-32:32]; set yrange [-32:32]; set xtics 10; set ytics 10
set xlabel "k_1 (cycles per period)"; set ylabel "k_2 (cycles per period)"
set key outside right
plot for [i=17:10:-1] sprintf("%s/wv-%d.tsv", d, i) using 2:3 with points pt 7 ps 0.35 title sprintf("F_{%d}", i), \
     '-' using 1:2 with lines lw 2 lc rgb "black" title "|k|_1 = 3"
3 0
0 3
-3 0
0 -3
3 0
e
unset multiplot
