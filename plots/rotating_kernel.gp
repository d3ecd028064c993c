# GI '86 sec. 3.1, a kernel rotated by theta(x, y): the shaded texture beside
# the crest directions, prescribed and measured, on the texture's 512 x 512
# pixels.
# gnuplot -e "img='T.png'; vec='V.txt'; out='O.png'" plots/rotating_kernel.gp
# (vec: x y dx_measured dy_measured dx_prescribed dy_prescribed per window)
set terminal pngcairo size 1000,530 font "DejaVu Sans,11"
set output out
set multiplot layout 1,2
unset key; set size ratio -1
set xlabel "x (pixels)"; set ylabel "y (pixels)"
set xrange [0:512]; set yrange [512:0]; set xtics 128; set ytics 128
set title "kernel rotated by theta(x, y), shaded"
plot img binary filetype=png flipy with rgbimage
set title "crest direction: prescribed (black), measured (red)"
plot vec using ($1-$5/2):($2-$6/2):5:6 with vectors nohead lw 3 lc rgb "black", \
     '' using ($1-$3/2):($2-$4/2):3:4 with vectors nohead lw 1.5 lc rgb "red"
unset multiplot
