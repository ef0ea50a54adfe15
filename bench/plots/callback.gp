# Render-callback time percentiles against the block budget.
reset
set terminal pngcairo size 900,600 font "sans,11"
set output "bench/results/callback.png"
set datafile separator ","
set style data histograms
set style histogram cluster gap 1
set style fill solid 0.8 border -1
set logscale y
set grid y
set ylabel "share of the block's budget (%)"
set xlabel "block size (frames) and bolts sounding, with a 100/s spark stream"
set key top left
plot "bench/results/callback.csv" every ::1 using (100*$5/$7):xtic(sprintf("%d/%d", $1, $2)) title "p99", \
     "" every ::1 using (100*$4/$7) title "p50", \
     "" every ::1 using (100*$6/$7) title "max"
