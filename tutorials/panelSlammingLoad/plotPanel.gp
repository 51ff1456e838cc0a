# The panel's wet-face strain at 30 and 120 mm from the keel: the particle
# structure against the finite elements of the panel it makes and of 2 mm
set terminal pngcairo size 900,560 noenhanced
set xlabel 't [ms]'
set ylabel 'strain, wet face [microstrain]'
set key top left
set grid
p = 'postProcessing/strainProbes/0/strain.dat'
do for [g in "30 120"] {
    set output 'strain'.g.'.png'
    col = (g eq "30") ? 2 : 4
    set title 'Wagner load, one way: strain at '.g.' mm from the keel'
    plot p u ($1*1e3):(column(col)*1e6) w l lw 2 t 'particles ('.rows.' rows of '.spacing.' m)', \
         'postProcessing/strainFE.dat' u ($1*1e3):(column(col)*1e6) w l dt 2 lw 2 t 'finite elements, '.made.' m', \
         'postProcessing/strainFE_nominal.dat' u ($1*1e3):(column(col)*1e6) w l dt 3 lw 2 t 'finite elements, '.nominal.' m'
}
