set terminal svg size 900,540 dynamic noenhanced font 'sans,12'
set output '../accuracy_hcw.svg'
set multiplot layout 1,3 title 'HCW: error vs step (7 days)'
set logscale xy
set format y '%.0e'
set xlabel 'step (min)'
set grid
set key bottom right font ',9'
set xrange [0.8:40]
set title 'Phi (one-step, rel.)'
plot 'accuracy_hcw.dat' index 0 using 1:2 with linespoints title 'exact_zoh', 'accuracy_hcw.dat' index 1 using 1:2 with linespoints title 'frozen_start', 'accuracy_hcw.dat' index 2 using 1:2 with linespoints title 'frozen_mid', 'accuracy_hcw.dat' index 3 using 1:2 with linespoints title 'hermite_simpson', 'accuracy_hcw.dat' index 4 using 1:2 with linespoints title 'rk4', 'accuracy_hcw.dat' index 5 using 1:2 with linespoints title 'trapezoid', 'accuracy_hcw.dat' index 6 using 1:2 with linespoints title 'euler'
set title 'Gamma (one-step, rel.)'
plot 'accuracy_hcw.dat' index 0 using 1:3 with linespoints title 'exact_zoh', 'accuracy_hcw.dat' index 1 using 1:3 with linespoints title 'frozen_start', 'accuracy_hcw.dat' index 2 using 1:3 with linespoints title 'frozen_mid', 'accuracy_hcw.dat' index 3 using 1:3 with linespoints title 'hermite_simpson', 'accuracy_hcw.dat' index 4 using 1:3 with linespoints title 'rk4', 'accuracy_hcw.dat' index 5 using 1:3 with linespoints title 'trapezoid', 'accuracy_hcw.dat' index 6 using 1:3 with linespoints title 'euler'
set title 'global (rel.)'
plot 'accuracy_hcw.dat' index 0 using 1:4 with linespoints title 'exact_zoh', 'accuracy_hcw.dat' index 1 using 1:4 with linespoints title 'frozen_start', 'accuracy_hcw.dat' index 2 using 1:4 with linespoints title 'frozen_mid', 'accuracy_hcw.dat' index 3 using 1:4 with linespoints title 'hermite_simpson', 'accuracy_hcw.dat' index 4 using 1:4 with linespoints title 'rk4', 'accuracy_hcw.dat' index 5 using 1:4 with linespoints title 'trapezoid', 'accuracy_hcw.dat' index 6 using 1:4 with linespoints title 'euler'
unset multiplot
