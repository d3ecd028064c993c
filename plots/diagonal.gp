# Diagonal bias of the 2D subdivision mesh: exact ACF contours against the
# isotropic target, and the anisotropy map.
# gnuplot -e "data='MAP.tsv'; out='O.png'" plots/diagonal.gp
set terminal pngcairo size 1100,520 font "DejaVu Sans,10"
set output out
set multiplot layout 1,2
set size ratio -1
set xlabel "lag x (samples)"
set ylabel "lag y (samples)"
set xrange [-20:20]
set yrange [-20:20]
set title "exact ACF (solid) and target exp(-r/12) (dashed), N = 2"
set contour base
set cntrparam levels discrete 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8
unset surface
set view map
set table $exact
splot data using 1:2:3 with lines
unset table
set table $target
splot data using 1:2:4 with lines
unset table
unset contour
set key off
plot $exact with lines lw 2 lc rgb "#b22222", $target with lines lw 1.5 dt 2 lc rgb "black"
set title "anisotropy: exact minus its x-axis profile at the same |lag| (R(0) units)"
set palette defined (-1 "#1f4e99", 0 "white", 1 "#b22222")
set cbrange [-0.01:0.01]
set colorbox
plot data using 1:2:5 with image
unset multiplot
