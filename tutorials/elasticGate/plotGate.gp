# Elastic gate: the free end's displacement against the experiment of
# Antoci et al. (2007) and two published simulations (tip.png); the
# particles coloured by pressure (particles.png)
set terminal pngcairo size 1300,550 font ",11"
set output "tip.png"
set multiplot layout 1,2
set xlabel "t after the release [s]"
set xrange [0:0.4]
set key bottom right
set title "Free end, horizontal displacement"
set ylabel "dx [mm]"
plot "data/antoci2007_gateTip.dat" using 1:(1000*$2) with points pt 7 ps 1.2 lc rgb "black" title "experiment (Antoci et al. 2007)", \
     "data/khayyer2018_isphSph_gateTip.dat" index 0 using 1:(1000*$2) with lines dt 2 lc rgb "#808080" title "ISPH-SPH (Khayyer et al. 2018)", \
     "data/yang2012_sphFem_gateTip.dat" index 0 using 1:(1000*$2) with lines dt 3 lc rgb "#808080" title "SPH-FEM (Yang et al. 2012)", \
     "tip.dat" using 1:(1000*$2) with lines lw 2 lc rgb "#1f5fbf" title "mpsFsiFoam"
set title "Free end, vertical displacement"
set ylabel "dy [mm]"
plot "data/antoci2007_gateTip.dat" using 3:(1000*$4) with points pt 7 ps 1.2 lc rgb "black" title "experiment", \
     "data/khayyer2018_isphSph_gateTip.dat" index 1 using 1:(1000*$2) with lines dt 2 lc rgb "#808080" title "ISPH-SPH", \
     "data/yang2012_sphFem_gateTip.dat" index 1 using 1:(1000*$2) with lines dt 3 lc rgb "#808080" title "SPH-FEM", \
     "tip.dat" using 1:(1000*$3) with lines lw 2 lc rgb "#1f5fbf" title "mpsFsiFoam"
unset multiplot

set terminal pngcairo size 1300,900 font ",11"
set output "particles.png"
set multiplot layout 2,2
set size ratio -1
set xrange [-0.005:0.3]
set yrange [-0.005:0.15]
unset xlabel
unset ylabel
set key off
set cbrange [0:1400]
set cblabel "p [Pa]"
set palette rgbformulae 33,13,10
do for [t in "0.04 0.08 0.12 0.16"] {
    set title "t = ".t." s after the release"
    plot "particles_wall.dat" using 1:2 with points pt 7 ps 0.15 lc rgb "#a0a0a0", \
         "particles_".t.".dat" using 1:2:3 with points pt 7 ps 0.2 palette, \
         "particles_structure_".t.".dat" using 1:2 with points pt 7 ps 0.25 lc rgb "black"
}
unset multiplot
