# A synthesised field beside its ensemble ACF against the target.
# gnuplot -e "field='F.png'; data='D.tsv'; title_text='T'; out='O.png'" plots/field_acf.gp
set terminal pngcairo size 1100,480 font "DejaVu Sans,11"
set output out
set multiplot layout 1,2 title title_text
unset key; unset tics; unset border
set size ratio -1
set title "one realization (seed 1), mean ± 3 sd"
plot field binary filetype=png with rgbimage
set size noratio
set border; set tics; set key top right
set title "ensemble mean ± 2 standard errors, and the target R"
set xlabel "lag (samples)"; set ylabel "R(lag)"
set grid
plot data using 1:($2-2*$3):($2+2*$3) with filledcurves lc rgb "#b0c4de" title "x: mean ± 2 se", \
     ''   using 1:2 with points pt 7 ps 0.6 lc rgb "#1f4e99" title "x: ensemble mean", \
     ''   using 1:4 with points pt 6 ps 0.8 lc rgb "#b22222" title "y: ensemble mean", \
     ''   using 1:6 with lines lw 2 lc rgb "black" title "target R along x", \
     ''   using 1:7 with lines lw 2 dt 2 lc rgb "#555555" title "target R along y"
unset multiplot
