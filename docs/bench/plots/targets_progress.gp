set terminal svg size 900,540 dynamic noenhanced font 'sans,12'
set output '../targets_progress.svg'
set multiplot layout 1,2 title 'Solve targets: incumbent (solid) and bound (dashed) against time, every repeat'
set xlabel 'wall time (s)'
set ylabel 'objective (m/s, L1)'
set grid
set key bottom right font ',9'
set datafile separator ','
set datafile missing 'NaN'
set title 'hcw_table42_t1_2d, 1 thread(s)'
set yrange [1.70:1.73]
plot '../runs/targets-hcw_table42_t1_2d-1thread-r0.trace.csv' using 1:2 with steps lw 2 title 'run 0 incumbent', '../runs/targets-hcw_table42_t1_2d-1thread-r0.trace.csv' using 1:3 with steps dt 2 title 'run 0 bound', '../runs/targets-hcw_table42_t1_2d-1thread-r1.trace.csv' using 1:2 with steps lw 2 title 'run 1 incumbent', '../runs/targets-hcw_table42_t1_2d-1thread-r1.trace.csv' using 1:3 with steps dt 2 title 'run 1 bound', '../runs/targets-hcw_table42_t1_2d-1thread-r2.trace.csv' using 1:2 with steps lw 2 title 'run 2 incumbent', '../runs/targets-hcw_table42_t1_2d-1thread-r2.trace.csv' using 1:3 with steps dt 2 title 'run 2 bound'
set title 'geo_week_anzel4, 2 thread(s)'
set autoscale y
plot '../runs/targets-geo_week_anzel4-2threads-r0.trace.csv' using 1:2 with steps lw 2 title 'run 0 incumbent', '../runs/targets-geo_week_anzel4-2threads-r0.trace.csv' using 1:3 with steps dt 2 title 'run 0 bound', '../runs/targets-geo_week_anzel4-2threads-r1.trace.csv' using 1:2 with steps lw 2 title 'run 1 incumbent', '../runs/targets-geo_week_anzel4-2threads-r1.trace.csv' using 1:3 with steps dt 2 title 'run 1 bound', '../runs/targets-geo_week_anzel4-2threads-r2.trace.csv' using 1:2 with steps lw 2 title 'run 2 incumbent', '../runs/targets-geo_week_anzel4-2threads-r2.trace.csv' using 1:3 with steps dt 2 title 'run 2 bound'
unset multiplot
