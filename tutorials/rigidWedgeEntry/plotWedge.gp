# Rigid wedge entry at V = 4 m/s against Wagner (1932) and von Karman
# (1929) theory; Allrun gives deadrise, and the speed V (a free drop's
# initial one: then the theory holds while the wedge has not slowed), the
# panels' length L and the keel's x (gnuplot -e "deadrise = 30; V = 4;
# L = 0.3; xKeel = 0.8; similarity = 1"); similarity 0 (a free drop)
# draws no similarity plot.
# Wagner: wetted half-width c = (pi/2) V t/tan(b), force per unit depth
# F = rho pi c dc/dt V = rho pi^3 V^3 t/(4 tan^2 b); von Karman (no pile-up):
# c = V t/tan(b), F = rho pi V^3 t/tan^2 b. Both hold until the spray root
# reaches the chine (half-width 0.3 cos b).
rho = 1000.0
if (!exists("V")) V = 4.0
if (!exists("L")) L = 0.3
if (!exists("xKeel")) xKeel = 0.8
if (!exists("similarity")) similarity = 1
b = deadrise*pi/180
cdot = pi*V/(2*tan(b))
tW = L*cos(b)/cdot
tK = L*cos(b)*tan(b)/V
FW(t) = t <= tW ? rho*pi**3*V**3*t/(4*tan(b)**2) : 1/0
FK(t) = t <= tK ? rho*pi*V**3*t/tan(b)**2 : 1/0

set terminal pngcairo size 900,600 font ",11"
set output "force.png"
set title sprintf("Rigid wedge, deadrise %g deg, V = %g m/s%s: vertical force", \
    deadrise, V, similarity ? "" : " (free drop, theory at the initial speed)")
set xlabel "t [s]"
set ylabel "F_y [kN/m]"
set key top left
set grid
# interFoam's 1 ms means (data/interFoam_rigidWedge_force.dat: 30 deg,
# 4 m/s, a 1 mm mesh; drawn at 30 deg only), through the chine
set xrange [0:*]
interFoam = deadrise == 30 && V == 4 && L == 0.3 && similarity
plot "postProcessing/structureForces/0/force.dat" u 1:($3/1e3) w l lw 1.5 lc rgb "#1f77b4" t "mpsFsiFoam", \
     FW(x)/1e3 w l lw 2 dt 2 lc rgb "black" t "Wagner", \
     FK(x)/1e3 w l lw 2 dt 3 lc rgb "#d62728" t "von Karman", \
     "data/interFoam_rigidWedge_force.dat" u 1:(interFoam ? $2/1e3 : 1/0) \
         w lp pt 5 ps 1 lw 1.5 lc rgb "#2ca02c" t (interFoam ? "interFoam, 1 mm mesh (1 ms means)" : "")
set xrange [*:*]

# Pressure along the wall at three times: Wagner's outer solution
#   p = rho V c cdot/sqrt(c^2 - x^2) - rho V^2 x^2/(2 (c^2 - x^2)),
# up to its spray-root peak rho cdot^2/2 (59 kPa at 30 deg)
pmax = 0.5*rho*cdot**2
c(t) = cdot*t
pW(x, t) = (abs(x) < c(t)) ? \
    (rho*V*c(t)*cdot/sqrt(c(t)**2 - x**2) - 0.5*rho*V**2*x**2/(c(t)**2 - x**2)) : 1/0
pWc(x, t) = abs(x) >= c(t) ? 1/0 : (pW(x, t) > pmax ? pmax : (pW(x, t) < 0 ? 0 : pW(x, t)))

set output "pressure.png"
set title sprintf("Pressure on the wedge's wall particles (deadrise %g deg)", deadrise)
set xlabel "x - x_{keel} [m]"
set ylabel "p [kPa]"
set key top right
set xrange [-L:L]
set samples 1000
plot for [t in "0.005 0.01 0.015"] "postProcessing/wallPressure/".t."/wallPressure.dat" \
         u ($1 - xKeel):($3/1e3) w p pt 7 ps 0.6 t "t = ".t." s", \
     for [t in "0.005 0.01 0.015"] pWc(x, t + 0)/1e3 w l lw 1.5 dt 2 t "Wagner, ".t." s"

# The same pressure in Wagner's similarity variables: Cp = p/(rho V^2/2)
# against x/c(t), every written time from 4 ms until the spray root is 0.9
# of the way to the chine (grey), and their mean over bins of 0.05 in
# |x|/c (bin/wedgePressureSimilarity). Wagner's outer solution
#   Cp = 2 (cdot/V)/sqrt(1 - xi^2) - xi^2/(1 - xi^2), xi = x/c,
# up to the spray-root peak (cdot/V)^2 (7.40 at 30 deg); the exact
# similarity solution (data/wedgeSimilarity/profile_<deadrise>.dat, by the
# utility wedgeSimilarity, at 10, 20, 30 and 45 deg) peaks lower (6.89 at
# 30 deg) and nearer the keel.
if (!similarity) exit
k = cdot/V
CpW(xi) = abs(xi) >= 1 ? 1/0 : \
    ((2*k/sqrt(1 - xi**2) - xi**2/(1 - xi**2)) > k**2 ? k**2 : \
     (2*k/sqrt(1 - xi**2) - xi**2/(1 - xi**2)))
set output "pressureSimilarity.png"
set title sprintf("Wall pressure in similarity variables (deadrise %g deg, V = %g m/s)", deadrise, V)
set xlabel "|x - x_{keel}| / c(t),  c = ({/Symbol p}/2) V t / tan {/Symbol b}"
set ylabel "C_p = p / ({/Symbol r} V^2/2)"
simFile = sprintf("data/wedgeSimilarity/profile_%g.dat", deadrise)
hasSim = system("test -f ".simFile." && echo 1 || echo 0") + 0
set xrange [0:2]
set yrange [-2:(k**2 > 20 ? 1.25*k**2 : 25)]
set key top right
plot "postProcessing/wallPressure/wallPressureSimilarity.dat" u (abs($1)):2 w p pt 7 ps 0.3 lc rgb "#c0c0c0" t "wall particles, 4 ms to 0.9 t_{chine}", \
     "postProcessing/wallPressure/pressureSimilarity.dat" u 1:2:3 w yerrorlines pt 7 ps 0.8 lw 1.5 lc rgb "#1f77b4" t "mpsFsiFoam, bin mean +- std. dev.", \
     CpW(x) w l lw 2 dt 2 lc rgb "black" t "Wagner (outer solution, capped at its peak)", \
     (hasSim ? simFile : "/dev/null") index 0 u ($1/k):3 w l lw 2 lc rgb "#d62728" \
         t "similarity solution (Dobrovol'skaya 1969; wedgeSimilarity)"
