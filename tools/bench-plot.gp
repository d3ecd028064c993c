# Time against size, log-log, for each method of `noiselab bench` (solid)
# beside its floor measured in the same run (dashed, same colour), with
# guides for the expected growth (grey): N log N through the fft at 1024^2,
# N through subdivision at 1024^2.
# usage: gnuplot -e "in='bench.tsv'; out='bench.png'" tools/bench-plot.gp
set datafile separator "\t"
set terminal pngcairo size 900,640 font ",11"
set output out
set logscale xy
set xlabel "samples"
set ylabel "seconds (median)"
set title "noiselab bench: methods (solid) and their floors (dashed)"
set key outside right top
set grid
cases = "fft circulant subdiv sparse acf psd krige rank1"
m(c) = c[1:strstrt(c." ", " ") - 1]
# the guides' anchors: the first fft and subdiv rows
stats in using (m(strcol(1)) eq "fft" ? $2 : NaN):3 nooutput
n0 = STATS_min_x; t0 = STATS_min_y
stats in using (m(strcol(1)) eq "subdiv" ? $2 : NaN):3 nooutput
n1 = STATS_min_x; t1 = STATS_min_y
set xrange [1e4:1e8]
plot t0 * x * log(x) / (n0 * log(n0)) with lines dt 3 lc rgb "#888888" title "N log N", \
     t1 * x / n1 with lines dt 4 lc rgb "#bbbbbb" title "N", \
     for [i = 1:words(cases)] in using (m(strcol(1)) eq word(cases, i) && strstrt(strcol(1), "variance") == 0 ? $2 : NaN):3 \
         with linespoints lw 2 pt 7 lc i title word(cases, i), \
     for [i = 1:words(cases)] in using (m(strcol(1)) eq word(cases, i) && strstrt(strcol(1), "variance") == 0 ? $2 : NaN):5 \
         with linespoints dt 2 pt 6 lc i notitle, \
     in using (strstrt(strcol(1), "variance") ? $2 : NaN):3 with points pt 5 ps 1.5 lc 7 title "krige +variance"
