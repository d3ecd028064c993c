# Keller 2001, section 2: time slices of a 3D (x, y, t) and a 4D (x, y, z = 0, t)
# rank-1 lattice field, as written by build/experiments/keller_spacetime PREFIX
# (PREFIX-S-C.png: S = 3, 4; C = 0..4 for t = 0, 0.04, ..., 0.16; grey = field
# over its standard deviation, -2.5 black to 2.5 white; 128 x 128 over one period).
# gnuplot -e "prefix='DIR/st'; out='O.png'" plots/spacetime.gp
set terminal pngcairo size 1180,560 font "DejaVu Sans,10"
set output out
set multiplot title "Rank-1 lattice fields over space-time, Gaussian correlation: slices at t = 0 .. 0.16 of the time period" \
    layout 2,5 margins 0.07,0.90,0.10,0.88 spacing 0.012,0.08
set size ratio -1
set palette grey
set cbrange [-2.5:2.5]
set xrange [0:1]; set yrange [0:1]
set xtics 0.5; set ytics 0.5
unset colorbox
do for [s = 3:4] {
    do for [c = 0:4] {
        set title sprintf("t = %.2f", 0.04 * c)
        set xlabel (s == 4 ? "x (period)" : "")
        set ylabel (c == 0 ? (s == 3 ? "3D (x, y, t), N = 8192\ny (period)" : "4D (x, y, z = 0, t), N = 16384\ny (period)") : "")
        set format y (c == 0 ? "%g" : "")
        set format x (s == 4 ? "%g" : "")
        if (c == 4) {
            set colorbox user origin 0.915,0.18 size 0.015,0.62
            set cblabel "field / standard deviation" offset 1.5,0
        } else {
            unset colorbox
        }
        plot sprintf("%s-%d-%d.png", prefix, s, c) binary filetype=png flipy dx=1./128 dy=1./128 \
            using ($1 / 255. * 5 - 2.5) with image notitle
    }
}
unset multiplot
