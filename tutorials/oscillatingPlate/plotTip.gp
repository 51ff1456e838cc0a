# Tip deflection of the oscillating plate against the linear
# (Euler-Bernoulli) first mode: amplitude V_f c0/omega, omega = 24.73 rad/s
E = 2e6; nu = 0.3975; rho = 1000; Vf = 0.001
c0 = sqrt(E/(3*(1 - 2*nu))/rho); w = 2*pi/0.2541

set terminal pngcairo size 900,500 noenhanced
set output 'tip.png'
set xlabel 't [s]'
set ylabel 'tip deflection [mm]'
set key outside right
set grid
set samples 500
plot 'postProcessing/tip/0/displacement.dat' u 1:($3*1e3) w l lw 2 t 'tip_y', \
     [0:0.6] Vf*c0/w*sin(w*x)*1e3 w l dt 2 lc rgb 'black' t 'Euler-Bernoulli, T = 0.2541 s'
