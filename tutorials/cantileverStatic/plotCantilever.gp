# Strain gauges and tip deflection of the damped cantilever against
# Euler-Bernoulli (E' = E/(1 - nu^2), plane strain)
q = 100; L = 0.3; H = 0.002; E = 68e9; nu = 0.3
Ep = E/(1 - nu**2); I = H**3/12
eps(x) = q*(L - x)**2/2*(H/2)/(Ep*I)
tipEB = q*L**4/(8*Ep*I)

set terminal pngcairo size 900,600 noenhanced
set output 'strain.png'
set xlabel 't [s]'
set ylabel 'axial strain [-]'
set key outside right
set grid
plot 'postProcessing/strainProbes/0/strain.dat' u 1:2 w l lw 2 t 'top, 30 mm', \
     '' u 1:3 w l lw 2 t 'bottom, 30 mm', \
     '' u 1:4 w l lw 2 t 'top, 120 mm', \
     '' u 1:5 w l lw 2 t 'bottom, 120 mm', \
     eps(0.03) w l dt 2 lc rgb 'black' t 'Euler-Bernoulli 30 mm', \
     -eps(0.03) w l dt 2 lc rgb 'black' notitle, \
     eps(0.12) w l dt 3 lc rgb 'gray30' t 'Euler-Bernoulli 120 mm', \
     -eps(0.12) w l dt 3 lc rgb 'gray30' notitle

set output 'tip.png'
set ylabel 'tip deflection [mm]'
plot 'postProcessing/tip/0/displacement.dat' u 1:($3*1e3) w l lw 2 t 'tip_y', \
     -tipEB*1e3 w l dt 2 lc rgb 'black' t 'Euler-Bernoulli'
