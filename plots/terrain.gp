# A height field in perspective with lighting (pm3d).
# picture: a perspective view, scale given in the caption; no axes
# gnuplot -e "data='M.txt'; title_text='T'; out='O.png'; zs=1" plots/terrain.gp
set terminal pngcairo size 1000,640 font "DejaVu Sans,11"
set output out
set title title_text
unset key; unset tics; unset border; unset colorbox
set view 62, 32, 1.4, 1.0
set view equal xyz
set pm3d depthorder lighting primary 0.55 specular 0.15
set palette defined (0 "#2f4f2f", 0.35 "#6b8e23", 0.6 "#a08c5a", 0.85 "#8b7d6b", 1 "#f5f5f5")
if (exists("water")) set palette defined (0 "#0b2545", 0.55 "#2f6690", 0.85 "#8fb8de", 1 "#f0f6fc")
set style fill solid
set xyplane 0
splot data matrix using 1:2:($3*zs) with pm3d
