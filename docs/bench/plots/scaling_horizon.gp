set terminal svg size 900,540 dynamic noenhanced font 'sans,12'
set output '../scaling_horizon.svg'
set title 'GEO, 5-min step: time against horizon'
set logscale xy
set xlabel 'horizon (days)'
set ylabel 'seconds'
set grid
set key top left
plot 'scaling_horizon_sparse.dat' using 1:2 with linespoints title 'build, sparse', 'scaling_horizon_sparse.dat' using 1:3 with linespoints title 'solve, sparse (finished)', 'scaling_horizon_sparse.dat' using 1:4 with points pt 6 ps 1.5 title 'solve, sparse (time limit)', 'scaling_horizon_condensed.dat' using 1:2 with linespoints title 'build, condensed'
