# GI '86 sec. 3.1, kernels band-limited by depth: a textured plane in
# perspective, point-sampled, band-limited and the reference.
# picture: three renderings of one perspective view, its geometry in the caption; no axes
# gnuplot -e "plain='A.png'; band='B.png'; ref='C.png'; out='O.png'" plots/depth_bandlimit.gp
set terminal pngcairo size 700,1100 font "DejaVu Sans,11"
set output out
set multiplot layout 3,1
unset key; unset tics; unset border; set size ratio -1
set title 'point-sampled kernel: aliasing towards the horizon'
plot plain binary filetype=png with rgbimage
set title 'band-limited kernels chosen by depth (5 levels, sigma = footprint / 2)'
plot band binary filetype=png with rgbimage
set title 'reference: each pixel the mean of up to 16 x 16 point samples'
plot ref binary filetype=png with rgbimage
unset multiplot
