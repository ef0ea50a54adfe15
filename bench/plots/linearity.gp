# Time to synthesize a whole discharge against its segment count, with the
# least-squares line (Matsuyama fig. 14). Reads bench/results/linearity*.
reset
set terminal pngcairo size 900,600 font "sans,11"
set output "bench/results/linearity.png"
set datafile separator ","
set key top left
set logscale xy
set grid
set xlabel "segments"
set ylabel "time to synthesize the whole sound (ms)"
slope = real(system("awk '/slope/{print $2}' bench/results/linearity_fit.txt")) * 1e-6
intercept = real(system("awk '/intercept/{print $2}' bench/results/linearity_fit.txt"))
r2 = real(system("awk '/r2/{print $2}' bench/results/linearity_fit.txt"))
fit_line(x) = slope * x + intercept
set title sprintf("fulgur: %.0f ns per segment, R^2 = %.4f (post + render, one thread)", slope * 1e6, r2)
plot "bench/results/linearity.csv" using 1:4 every ::1 with points pt 7 ps 1.3 title "post + render", \
     "" using 1:2 every ::1 with linespoints pt 6 title "post (prepare + sort)", \
     "" using 1:3 every ::1 with linespoints pt 4 title "render", \
     [1000:1e6] fit_line(x) with lines lw 2 dt 2 title "least-squares line"
