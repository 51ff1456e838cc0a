# Hydrostatic tank: probe pressure (mean and spread over 1 s <= t <= 2 s)
# against rho g (H - y), and the probe histories
set terminal pngcairo size 1300,550 font ",11"
set output "pressure.png"
rho = 1000; g = 9.81; H = 0.3
set multiplot layout 1,2
set title "Pressure on x = 0.1 m, mean over 1-2 s"
set xlabel "p [Pa]"
set ylabel "y [m]"
set key bottom left
set xrange [0:3500]
set yrange [0:0.32]
set parametric
set trange [0:H]
plot rho*g*(H - t), t title "rho g (H - y)" lc rgb "black", \
     "probes_mean.dat" using 2:1:3 with xerrorbars pt 7 lc rgb "#1f5fbf" title "particleProbes (mean, rms)"
unset parametric
set title "Probe pressure against time"
set xlabel "t [s]"
set ylabel "p [Pa]"
set xrange [0:2]
set yrange [0:4000]
set key top right
plot for [i=2:6] "postProcessing/probes/0/p.dat" using 1:i every 5 with lines title sprintf("probe %d", i-2)
unset multiplot
