# Two pictures side by side. gnuplot -e "f1='A.png'; f2='B.png'; t1='..'; t2='..'; out='O.png'" plots/pair.gp
# picture: two images side by side, their size in the caption; no axes
set terminal pngcairo size 1000,530 font "DejaVu Sans,11"
set output out
set multiplot layout 1,2
unset key; unset tics; unset border; set size ratio -1
set title t1; plot f1 binary filetype=png with rgbimage
set title t2; plot f2 binary filetype=png with rgbimage
unset multiplot
