# Draws `fulgur analyze` output as one PNG: the waveform envelope on top,
# the spectrogram below.
#   gnuplot -e "wave='w.dat'; spec='s.dat'; out='x.png'; name='title'" scripts/plot.gp
if (!exists("name")) name = out

if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1200,900 font "sans,10"
} else {
    set terminal png size 1200,900
}
set output out
set multiplot layout 2,1 title name noenhanced
# the same horizontal margins, so the two time axes line up
set lmargin at screen 0.08
set rmargin at screen 0.86

# the envelope: columns time_s, min0, max0 [, min1, max1]
stats wave using 1 nooutput
set xrange [STATS_min:STATS_max] writeback
set xlabel "time (s)"
set ylabel "pressure (Pa)"
set grid
set key top right
plot wave using 1:2:3 with filledcurves lc rgb "#1f77b4" title "channel 0 (min/max)"

# the spectrogram: time_s freq_hz level_db, one block per slice
unset grid
set view map
stats spec using 2 nooutput
set logscale y
set yrange [STATS_min:STATS_max]
set ylabel "frequency (Hz)"
set cblabel "level (dB re 20 uPa)"
set palette defined (0 "black", 1 "#3b0f70", 2 "#b73779", 3 "#fc8961", 4 "#fcfdbf")
unset key
set xrange restore
splot spec using 1:2:3 with pm3d
unset multiplot
