# GI '86 Fig. 7: band-pass noise before and after the hyperbolic shaping.
# gnuplot -e "d='DIR'; out='O.png'" plots/nonlin.gp
set terminal pngcairo size 1100,800 font "DejaVu Sans,11"
set output out
set multiplot layout 2,2
unset key
set xrange [0:400]
set xlabel "t (samples)"
set ylabel "value (standard deviation 1)"
set title "band-pass Gaussian noise (input)"
plot d.'/nl-in.tsv' every ::0::400 using 1:2 with lines lc rgb "#1f4e99"
set title "after the pair of nonlinearities (hyperbolic density)"
plot d.'/nl-out.tsv' every ::0::400 using 1:2 with lines lc rgb "#b22222"
set xrange [0:0.3]
set logscale y
set format y "10^{%L}"
set yrange [1e-6:*]
set xlabel "frequency (cycles per sample)"
set ylabel "power spectral density (two-sided)"
set key top right
set title "input spectrum"
plot d.'/nl-psd-in.tsv' using 1:2 with lines lc rgb "#1f4e99" title "measured (8 realizations)", \
     d.'/nl-pred.tsv' using 1:2 with lines dt 2 lw 2 lc rgb "black" title "model"
set title "output spectrum: odd harmonics at 3 f0 and 5 f0"
plot d.'/nl-psd-out.tsv' using 1:2 with lines lc rgb "#b22222" title "measured (8 realizations)", \
     d.'/nl-pred.tsv' using 1:3 with lines dt 2 lw 2 lc rgb "black" title "Hermite series prediction"
unset multiplot
