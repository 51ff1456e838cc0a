# Dam break: surge front Z = x/a against T = t sqrt(2 g/a)
set terminal pngcairo size 900,600 font ",11"
set output "front.png"
set title "Dam break, a = 0.146 m: surge front"
set xlabel "T = t (2 g/a)^{1/2}"
set ylabel "Z = x_{front}/a"
set key top left
set grid
set xrange [0:3.6]
set yrange [1:4.2]
plot "data/martinMoyce1952_surgeFront.dat" using 1:2 with points pt 7 ps 1.2 lc rgb "black" title "Martin \\& Moyce (1952)", \
     "front.dat" using 1:2 with lines lw 2 lc rgb "#1f5fbf" title "mpsFsiFoam (l0 = a/25)"
