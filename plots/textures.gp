# Four textures in a 2 x 2 montage. gnuplot -e "f1='A.png'; f2='B.png'; f3='C.png'; f4='D.png'; ta='..'; tb='..'; tc='..'; td='..'; out='O.png'" plots/textures.gp
# picture: textures shown as images, their size in samples in the caption; no axes
set terminal pngcairo size 900,930 font "DejaVu Sans,11"
set output out
set multiplot layout 2,2
unset key; unset tics; unset border; set size ratio -1
set title t1; plot f1 binary filetype=png with rgbimage
set title t2; plot f2 binary filetype=png with rgbimage
set title t3; plot f3 binary filetype=png with rgbimage
set title t4; plot f4 binary filetype=png with rgbimage
unset multiplot
