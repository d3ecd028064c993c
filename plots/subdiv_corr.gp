# Exact ACF of the Table 1 model (N = 4) with independent and correlated
# displacements against the target, 1D.
# gnuplot -e "data='D.tsv'; out='O.png'" plots/subdiv_corr.gp
set terminal pngcairo size 1100,420 font "DejaVu Sans,10"
set output out
set multiplot layout 1,2
set key top right
set xlabel "lag (units of t)"
set ylabel "R / R(0)"
set grid
do for [i = 0:1] {
    set title "100cos(10t)exp(-|t|), N = 4, ".(i ? "correlated displacements (4 taps)" : "independent displacements")
    plot data index i using 3:5 with lines lw 2 lc rgb "black" title "target R", \
         ''   index i using 3:4 with points pt 7 ps 0.5 lc rgb (i ? "#1f4e99" : "#b22222") title "exact expected ACF"
}
unset multiplot
