# A field as a sky: low values blue, high values white (clouds).
# picture: a field shown as a sky, its extent in the caption; no axes
# gnuplot -e "data='M.txt'; title_text='T'; out='O.png'" plots/sky.gp
set terminal pngcairo size 900,420 font "DejaVu Sans,11"
set output out
set title title_text
unset key; unset tics; unset border; unset colorbox
set palette defined (0 "#1d4e89", 0.55 "#4f86c6", 0.75 "#b9d3ee", 1 "#ffffff")
set size ratio -1
set autoscale fix
plot data matrix with image
