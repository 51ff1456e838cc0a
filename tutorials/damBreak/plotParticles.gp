# Initial particles of the dam break: fluid blue, wall black, dummy grey
# particles_wall.dat: x y kind (1 wall, 2 dummy)
set terminal pngcairo size 1000,700 font ",11"
set output "particles.png"
set size ratio -1
set xlabel "x [m]"
set ylabel "y [m]"
set title "damBreak: initial particles (a = 0.146 m, l0 = a/25)"
set key outside right
plot "particles_wall.dat" using 1:($3 == 2 ? $2 : 1/0) with points pt 7 ps 0.4 lc rgb "#a0a0a0" title "dummy", \
     "particles_wall.dat" using 1:($3 == 1 ? $2 : 1/0) with points pt 7 ps 0.4 lc rgb "black" title "wall", \
     "particles_fluid.dat" using 1:2 with points pt 7 ps 0.4 lc rgb "#1f5fbf" title "fluid"
