# Keller 2001, Fig. 3: four copies of one periodic ocean patch (noiselab ocean
# --tile: a 2 x 2 picture of a patch of PATCH metres), drawn on axes in metres
# with the copies' boundaries marked.
# gnuplot -e "img='TILE.png'; patch=1000; px=512; title_text='..'; out='O.png'" plots/ocean_tile.gp
set terminal pngcairo size 640,640 font "DejaVu Sans,10"
set output out
set title title_text
set size ratio -1
unset key
set xrange [0:2 * patch]; set yrange [0:2 * patch]
set xtics patch / 2; set ytics patch / 2
set xlabel "x (m)"; set ylabel "y (m)"
set arrow 1 from patch, 0 to patch, 2 * patch nohead front lw 2 dt 2 lc rgb "#d62728"
set arrow 2 from 0, patch to 2 * patch, patch nohead front lw 2 dt 2 lc rgb "#d62728"
plot img binary filetype=png flipy dx=2. * patch / px dy=2. * patch / px with rgbimage
