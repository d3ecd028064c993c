# Condition number of the subdivision matrix and the displacement variance
# per level, Gaussian against Markovian (Lewis 1987, "Singular processes").
# gnuplot -e "g='G.tsv'; m='M.tsv'; out='O.png'; thr=1e10" plots/singular.gp
set terminal pngcairo size 1100,460 font "DejaVu Sans,11"
set output out
set multiplot layout 1,2 title "Subdivision to exp(-t^2) and exp(-|t|), N = 2, spacing halved per level"
set logscale xy
set format y "10^{%L}"
set xlabel "spacing (units of t)"
set key top left
set grid
set xrange [*:*] reverse
set title "condition number of the 4 x 4 matrix"
set ylabel "condition number"
plot g using 2:3 with linespoints pt 7 lw 2 title "gauss exp(-t^2)", \
     m using 2:3 with linespoints pt 5 lw 2 title "markov exp(-|t|)", \
     thr with lines dt 2 lc rgb "red" title "pseudo-inverse beyond this"
set title "displacement variance (eq. 7)"
set ylabel "variance (R(0) = 1)"
set key bottom left
set yrange [1e-18:2]
plot g using 2:($4 > 0 ? $4 : 1e-18) with linespoints pt 7 lw 2 title "gauss (0 drawn at 10^{-18})", \
     m using 2:4 with linespoints pt 5 lw 2 title "markov"
unset multiplot
