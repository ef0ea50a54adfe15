# Field solve time against grid size: the GPU solver (on the device the CSV
# names; llvmpipe where no GPU was lent) next to the CPU MGPCG, same run.
reset
set terminal pngcairo size 900,520 font "sans,11"
set output "bench/results/field_gpu.png"
set datafile separator ","
set logscale xy
set grid
set xtics ("33^3" 33, "65^3" 65, "129^3" 129, "257^3" 257)
set xlabel "grid"
set ylabel "solve time, median (ms)"
device = system("sed -n 's/^# GPU device (GL_RENDERER): \\([^,]*\\),.*/\\1/p' bench/results/field_gpu.csv")
set title "Laplace solve to 1e-5, spark-ball scene; GPU = ".device
set key top left
plot "< grep ',cpu-mgpcg,cold,' bench/results/field_gpu.csv" using 1:5 with linespoints pt 7 title "CPU MGPCG, cold (1 thread)", \
     "< grep ',cpu-mgpcg,warm,' bench/results/field_gpu.csv" using 1:5 with linespoints pt 6 title "CPU MGPCG, warm", \
     "< grep ',gpu,cold,' bench/results/field_gpu.csv" using 1:5 with linespoints pt 5 title "GPU V-cycles + MGPCG, cold", \
     "< grep ',gpu,warm,' bench/results/field_gpu.csv" using 1:5 with linespoints pt 4 title "GPU, warm"
