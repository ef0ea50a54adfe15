# Late events against the source's distance, through fulgur run.
reset
set terminal pngcairo size 900,520 font "sans,11"
set output "bench/results/latency.png"
set datafile separator ","
set logscale x
set grid
set xlabel "distance from the listener (m)"
set ylabel "late events per run (mean of 3)"
set title "fulgur run, paced null device, 128-frame blocks: sound already past the ear at adoption"
plot "< grep '^spark' bench/results/latency.csv" using 2:4 with linespoints pt 7 title "spark balls (about 70 segments)", \
     "< grep '^lightning' bench/results/latency.csv" using 2:4 with linespoints pt 5 title "300 m bolt (thousands of segments)"
