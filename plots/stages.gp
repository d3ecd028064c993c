# Successive subdivision stages, stacked from coarse (top) to fine (bottom).
# gnuplot -e "prefix='DIR/stage'; first=1; last=6; title_text='T'; out='O.png'" plots/stages.gp
set terminal pngcairo size 900,700 font "DejaVu Sans,11"
set output out
set title title_text
unset key
set xlabel "t"
set ylabel "value (R(0) = 1), each level 5 below the one above"
unset ytics
set border 1
set xtics nomirror
step = 5
set yrange [-(last - first + 1) * step + step / 2 : step]
plot for [k = first:last] sprintf("%s-%d.tsv", prefix, k) using 1:($2 - (k - first) * step) \
     with linespoints pt 7 ps (k < last - 1 ? 0.5 : 0.2) lw 1.5 lc rgb "#1f4e99", \
     for [k = first:last] sprintf("%s-%d.tsv", prefix, k) every ::0::0 using (0):(-(k - first) * step + 2.2):(sprintf("level %d", k)) with labels left offset 0.5,0 tc rgb "#555555"
