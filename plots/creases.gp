# Midpoint displacement beside generalized subdivision of the same fractal
# target, with the curvature ratio per level below.
# gnuplot -e "mp='A.tsv'; gs='B.tsv'; rmp='A.ratios'; rgs='B.ratios'; out='O.png'" plots/creases.gp
set terminal pngcairo size 1000,750 font "DejaVu Sans,11"
set output out
set multiplot layout 3,1
unset key
set xrange [0:4096]
set format y ""
set ytics ()
set xlabel "position (samples)"
set ylabel "height (arbitrary units)"
set title "midpoint displacement, H = 0.8 (f^{-2.6}): creases at the vertices of early levels"
plot mp every ::0::4096 using 0:2 with lines lc rgb "#b22222"
set title "generalized subdivision (N = 2) to power:d=2.6"
plot gs every ::0::4096 using 0:2 with lines lc rgb "#1f4e99"
set title "mean squared second difference at the samples made at each level / at the finest level (1 = no crease)"
set xrange [0.5:12.5]
set format y "%g"
set ytics auto
set yrange [0:*]
set xlabel "level"
set ylabel "curvature ratio (1 = no crease)"
set key top left
set style data linespoints
plot rmp using 1:2 lw 2 pt 7 lc rgb "#b22222" title "midpoint displacement", \
     rgs using 1:2 lw 2 pt 5 lc rgb "#1f4e99" title "generalized subdivision", \
     1.5 with lines dt 2 lc rgb "black" title "crease threshold", 1 with lines lc rgb "#888888" notitle
unset multiplot
