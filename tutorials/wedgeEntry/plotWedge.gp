# The elastic wedge's pictures (run in the case folder): strain at the
# gauges 30 and 120 mm from the keel (the seed paper's Fig. 4), the force
# of the water, the wedge coloured by its axial strain at 0, 10, 20 and
# 26 ms (the paper's Fig. 6), and the strain and deflection along the
# panels at those times. The gauges' columns of strain.dat, in the order
# Time left30_wet left30_dry left120_wet left120_dry right30_wet
# right30_dry right120_wet right120_dry (bin/postProcessingColumns).
# Wagner: the spray root passes 30 mm at 2.4 ms, 120 mm at 9.6 ms, the
# chine (300 mm) at 23.9 ms.

gauges = "< postProcessingColumns postProcessing/strainProbes/0/strain.dat" \
    ." Time left30_wet left30_dry left120_wet left120_dry" \
    ." right30_wet right30_dry right120_wet right120_dry"

set terminal pngcairo size 900,600 font ",11"
set grid
set key top right
set xlabel "t [ms]"
set ylabel "strain [microstrain]"
set xrange [0:30]

set output "strain30.png"
set title "Strain 30 mm from the keel (tension positive)"
set arrow 1 from 2.4, graph 0 to 2.4, graph 1 nohead dt 3 lc rgb "gray"
set label 1 "Wagner: wetted at 2.4 ms" at 2.6, graph 0.95
plot gauges u (1e3*$1):(1e6*$6) w l lw 1.5 t "right, wet face", \
     "" u (1e3*$1):(1e6*$7) w l lw 1.5 t "right, dry face", \
     "" u (1e3*$1):(1e6*$2) w l lw 1 dt 2 t "left, wet face", \
     "" u (1e3*$1):(1e6*$3) w l lw 1 dt 2 t "left, dry face"

set output "strain120.png"
set title "Strain 120 mm from the keel (tension positive)"
set arrow 1 from 9.6, graph 0 to 9.6, graph 1 nohead dt 3 lc rgb "gray"
set label 1 "Wagner: wetted at 9.6 ms" at 9.8, graph 0.95
plot gauges u (1e3*$1):(1e6*$8) w l lw 1.5 t "right, wet face", \
     "" u (1e3*$1):(1e6*$9) w l lw 1.5 t "right, dry face", \
     "" u (1e3*$1):(1e6*$4) w l lw 1 dt 2 t "left, wet face", \
     "" u (1e3*$1):(1e6*$5) w l lw 1 dt 2 t "left, dry face"
unset arrow 1
unset label 1

set output "force.png"
set title "Force of the water on the wedge"
set ylabel "F [kN/m]"
set key top left
plot "postProcessing/structureForces/0/force.dat" u ($1*1e3):($3/1e3) w l lw 1.5 t "F_y", \
     "" u ($1*1e3):($2/1e3) w l lw 1 t "F_x"

# The wedge at four times, coloured by axial strain (positions as they
# are: the wedge moves down 4 mm per ms)
set output "wedge.png"
set terminal pngcairo size 1000,800 font ",10"
set multiplot layout 2,2 title "Axial strain of the panels [microstrain]"
set size ratio -1
unset grid
set xlabel "x [m]"
set ylabel "y [m]"
set xrange [0.5:1.1]
set yrange [0.45:0.8]
set cbrange [-3000:3000]
set palette defined (-1 "blue", 0 "#b0b0b0", 1 "red")
unset key
# The times written (a shorter run has fewer of them)
times = system("for t in 0 0.01 0.02 0.026; do [ -d $t/lagrangian/structure ] && echo $t; done")
do for [t in times] {
    set title "t = ".t." s"
    plot "< lagrangianColumns ".t."/lagrangian/structure axialStrain" \
        u 1:2:($3*1e6) w p pt 7 ps 0.25 lc palette
}
unset multiplot

# Strain and deflection along the panels at 0, 10, 20 and 26 ms, the times
# of the paper's Fig. 6: profiles.png, drawn by bin/plotPanelProfiles
