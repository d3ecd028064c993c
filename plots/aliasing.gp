# Aliasing energy when zooming out one level, measured and predicted.
# gnuplot -e "data='D.tsv'; out='O.png'" plots/aliasing.gp
set terminal pngcairo size 900,520 font "DejaVu Sans,11"
set output out
set title "energy changed by dropping to the level below (decimation without low-pass), / variance"
set xlabel "level (spacing 2 / 2^{level})"
set ylabel "aliased fraction"
set key top right
set logscale y
set format y "10^{%L}"
set yrange [1e-6:2]
set grid
plot data using 1:2 with linespoints lw 2 pt 7 lc rgb "#b22222" title "cos(10t) exp(-t^2): measured", \
     ''   using 1:3 with lines dt 2 lw 2 lc rgb "#b22222" title "predicted from its spectrum", \
     ''   using 1:4 with linespoints lw 2 pt 5 lc rgb "#1f4e99" title "exp(-|t|): measured", \
     ''   using 1:5 with lines dt 2 lw 2 lc rgb "#1f4e99" title "predicted", \
     0.1 with lines lc rgb "black" title "threshold"
