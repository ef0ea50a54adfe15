# The validation report's plots (bench/results/validation.md).
reset
set terminal pngcairo size 900,520 font "sans,11"
set datafile separator ","
set grid

set output "bench/results/validation_spectra.png"
set logscale x
set xrange [10:10000]
set xlabel "frequency (Hz)"
set ylabel "power (dB, arbitrary reference)"
set title "A 5 km bolt heard at 1 km and at 8 km (the lightning preset, T0 = 2.5 ms, storm atmosphere)"
plot "bench/results/validation_spectra.csv" every ::1 using 1:2 with lines lw 1.5 title "1 km", \
     "" every ::1 using 1:3 with lines lw 1.5 title "8 km"

set output "bench/results/validation_sparks.png"
set xrange [100:24000]
set title "Spark scale at 1 m, free air"
plot "bench/results/validation_sparks.csv" every ::1 using 1:2 with lines lw 1.5 title "spark balls", \
     "" every ::1 using 1:3 with lines lw 1.5 title "plasma ball"

set output "bench/results/validation_shadow.png"
unset logscale x
set xrange [0:150]
set yrange [0:1.05]
set xlabel "source height (m)"
set ylabel "level with refraction / straight rays"
set title "Shadow zone: ear 1.7 m up, 3 km away, R = 55 km (tangent ray h = 59.9 m)"
set arrow from 59.9, graph 0 to 59.9, graph 1 nohead dt 2
# the model: 10^(-beta x / 20), x = D - sqrt(2 R z_ear) - sqrt(2 R z), beta at 50 Hz
R = 55000.0
beta = 8.686 * 1.018793 * sqrt(3.0) / 2.0 * (2.0 * pi * 50.0 / 343.0 / (2.0 * R * R))**(1.0 / 3.0)
depth(z) = 3000.0 - sqrt(2.0 * R * 1.7) - sqrt(2.0 * R * z)
model(z) = depth(z) > 0 ? 10**(-beta * depth(z) / 20.0) : 1.0
plot "bench/results/validation_shadow.csv" every ::1 using 1:2 with points pt 7 title "measured per segment", \
     model(x) with lines lw 1.5 title "tangent ray + creeping wave (Pierce's first mode)"
