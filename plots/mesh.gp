# The planar quadrilateral mesh with a 4x4 neighbourhood (GI '86, Fig. 2):
# observation points '.' labelled with their coefficients, the mid-face 'x'
# (left) and the mid-edge 'o' (right).
# picture: a diagram of the mesh, its grid lines one spacing apart; no axes
# gnuplot -e "face='F.txt'; edge='E.txt'; out='O.png'" plots/mesh.gp
set terminal pngcairo size 1100,560 font "DejaVu Sans,11"
set output out
set multiplot layout 1,2 title "4x4 neighbourhood of the planar quadrilateral mesh, R = exp(-r), spacing 1"
set size ratio -1
unset key; unset tics; unset border
set xrange [-1.6:2.6]; set yrange [-1.6:2.6]
do for [panel = 1:2] {
    set title (panel == 1 ? "mid-face vertex x: face coefficients" : "mid-edge vertex o: edge coefficients")
    unset arrow
    do for [i = -1:2] {
        set arrow from i, -1 to i, 2 nohead lc rgb "#b0b0b0" lw 1.5
        set arrow from -1, i to 2, i nohead lc rgb "#b0b0b0" lw 1.5
    }
    set arrow from 0, 0 to 1, 0 nohead lc rgb "#404040" lw 3
    set arrow from 1, 0 to 1, 1 nohead lc rgb "#404040" lw 3
    set arrow from 1, 1 to 0, 1 nohead lc rgb "#404040" lw 3
    set arrow from 0, 1 to 0, 0 nohead lc rgb "#404040" lw 3
    file = panel == 1 ? face : edge
    unset label
    if (panel == 1) { set label 1 "x" at 0.5, 0.5 center tc rgb "red" font ",24" }
    if (panel == 2) { set label 1 "o" at 0.5, 0 center tc rgb "red" font ",24" }
    plot file using 1:2 with points pt 7 ps 1.2 lc rgb "black", \
         file using 1:($2 - 0.22):3 with labels font ",10" tc rgb "#1f4e9a"
}
unset multiplot
