# Exact ACF of subdivision fields (N = 2) against the target, 1D.
# gnuplot -e "data='D.tsv'; out='O.png'" plots/subdiv_exact.gp
set terminal pngcairo size 1100,700 font "DejaVu Sans,10"
set output out
set multiplot layout 2,2
set key top right
set xlabel "lag (units of t)"
set ylabel "R / R(0)"
set grid
titles = "markov:scale=8 markaussian:alpha=1.4,scale=8 100cos(10t)exp(-|t|) gauss-osc:omega=10"
do for [i = 0:3] {
    set title word(titles, i + 1)
    plot data index (2 * i) using 3:5 with lines lw 2 lc rgb "black" title "target R", \
         ''   index (2 * i) using 3:4 with points pt 7 ps 0.5 lc rgb "#b22222" title "exact, N = 2", \
         ''   index (2 * i + 1) using 3:4 with points pt 6 ps 0.6 lc rgb "#1f4e99" title "exact, N = 4"
}
unset multiplot
