# Exemplars beside their sparse-convolution resyntheses, with radial spectra.
# gnuplot -e "dir='D'; names='grass gravel brick'; out='O.png'" plots/resynthesis.gp
set terminal pngcairo size 1050,(words(names) * 330 + 10) font "DejaVu Sans,10"
set output out
nrow = words(names)
set multiplot layout nrow,3
do for [i = 1:nrow] {
    n = word(names, i)
    unset key; unset tics; unset border; set size ratio -1
    set title sprintf("%s: exemplar", n)
    plot sprintf("%s/rs-%s-ex.png", dir, n) binary filetype=png with rgbimage
    set title sprintf("%s: resynthesis (sparse convolution)", n)
    plot sprintf("%s/rs-%s.png", dir, n) binary filetype=png with rgbimage
    set size noratio; set border; set tics; set key bottom left
    set logscale xy; set format y "10^{%L}"
    set xlabel "frequency (cycles per pixel)"; set ylabel "power (radial mean, two-sided)"; set title "radial power spectra"
    plot sprintf("%s/rs-%s-ex.tsv", dir, n) using 1:2 with lines lw 2 lc rgb "black" title "exemplar", \
         sprintf("%s/rs-%s.tsv", dir, n) using 1:2 with lines lw 1.5 lc rgb "#b22222" title "resynthesis"
    unset logscale; unset xlabel; unset ylabel; set format y "%g"
}
unset multiplot
