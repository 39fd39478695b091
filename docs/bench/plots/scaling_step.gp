set terminal svg size 900,540 dynamic noenhanced font 'sans,12'
set output '../scaling_step.svg'
set title 'GEO week: time against step'
set logscale xy
set xlabel 'step (min)'
set ylabel 'seconds'
set grid
set key top right
plot 'scaling_step.dat' using 1:2 with linespoints title 'build', 'scaling_step.dat' using 1:3 with linespoints title 'solve (finished)', 'scaling_step.dat' using 1:4 with points pt 6 ps 1.5 title 'solve (time limit)'
