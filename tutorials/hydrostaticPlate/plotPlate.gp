# Hydrostatic plate: mid-span deflection against beam theory, and the
# fluid's load on the plate against the water's weight (Allrun gives
# -e "weight = ...; wFE = ...; wEB = ...; wT = ..." from the case's
# dictionaries)
set terminal pngcairo size 1300,550 font ",11"
set output "deflection.png"
# wFE: the plane-strain plate clamped at its faces (plateReference);
# wEB: Euler-Bernoulli, clamped-clamped, q L^4/(384 E' I);
# wT: with Timoshenko's shear deflection q L^2/(8 k G h), k = 5/6
set multiplot layout 1,2
set title "Mid-span deflection"
set xlabel "t [s]"
set ylabel "-w [mm]"
set key bottom right
set yrange [0:*]
plot "postProcessing/midspan/0/displacement.dat" using 1:(-1000*$3) with lines lc rgb "#1f5fbf" title "mpsFsiFoam", \
     1000*wFE with lines lw 2 lc rgb "#c03020" title "plane-strain plate (finite elements)", \
     1000*wEB with lines dt 2 lc rgb "black" title "beam theory (Euler-Bernoulli)", \
     1000*wT with lines dt 3 lc rgb "#808080" title "with shear (Timoshenko)"
set title "Fluid load on the plate"
set ylabel "load [N/m]"
plot "postProcessing/structureForces/0/force.dat" using 1:(-$3) with lines lc rgb "#1f5fbf" title "-F_y", \
     weight with lines dt 2 lc rgb "black" title "weight of the water"
unset multiplot
