# Dam break particles coloured by pressure at t = 0, 0.1, 0.2, 0.3 s
set terminal pngcairo size 1000,1100 font ",11"
set output "particles.png"
set multiplot layout 4,1
set size ratio -1
set xrange [-0.03:0.62]
set yrange [-0.03:0.32]
set cbrange [0:3000]
set cblabel "p [Pa]"
set palette rgbformulae 33,13,10
do for [t in "0 0.1 0.2 0.3"] {
    set title "t = ".t." s"
    plot "particles_wall.dat" using 1:2 with points pt 7 ps 0.2 lc rgb "#a0a0a0" notitle, \
         "particles_".t.".dat" using 1:2:3 with points pt 7 ps 0.35 palette notitle
}
unset multiplot
