# ./Allrun -all: strain 30 and 120 mm from the keel (right panel, dry face)
# at the three resolutions of the seed paper's Table 1
set terminal pngcairo size 900,900 font ",11"
set output "convergence.png"
set multiplot layout 2,1
set grid
set xlabel "t [ms]"
set ylabel "strain [microstrain]"
set xrange [0:30]
set key top right
set title "Strain 30 mm from the keel, right panel, dry face"
plot for [n=1:3] "case".n."/strainGauges.dat" u 1:7 w l lw 1.5 t "Case ".n
set title "Strain 120 mm from the keel, right panel, dry face"
plot for [n=1:3] "case".n."/strainGauges.dat" u 1:9 w l lw 1.5 t "Case ".n
unset multiplot
