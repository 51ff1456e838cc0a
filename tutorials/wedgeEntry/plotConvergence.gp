# ./Allrun -all: strain 30 and 120 mm from the keel (right panel, dry face)
# at the three resolutions of the seed paper's Table 1
gauges(n) = "< postProcessingColumns case".n."/postProcessing/strainProbes/0/strain.dat" \
    ." Time right30_dry right120_dry"

set terminal pngcairo size 900,900 font ",11"
set output "convergence.png"
set multiplot layout 2,1
set grid
set xlabel "t [ms]"
set ylabel "strain [microstrain]"
set xrange [0:30]
set key top right
set title "Strain 30 mm from the keel, right panel, dry face"
plot for [n=1:3] gauges(n) u (1e3*$1):(1e6*$2) w l lw 1.5 t "Case ".n
set title "Strain 120 mm from the keel, right panel, dry face"
plot for [n=1:3] gauges(n) u (1e3*$1):(1e6*$3) w l lw 1.5 t "Case ".n
unset multiplot
