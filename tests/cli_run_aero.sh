#!/bin/sh
# usage: cli_run_aero.sh FULGUR EXAMPLES_AERO_DIR SCENES_DIR
# fulgur run plays aero objects (examples/aero/) through its three
# threads, the frame thread driving each object's pose from the scene's
# motion, in lock-step (--audio wav:) so the numbers repeat: the wires'
# tone in the same 1/24-octave band as render's and their RMS within 1 dB
# of it (run sways the head a few centimetres: not the same samples); two
# runs byte-identical; the sword loudest at its fastest, which it reaches
# only if its poses are published; the report counting the objects and
# their poses; a scene whose motion is too fast refused with exit 2 and no
# WAV.
set -u
fulgur=$1
dir=$2
scenes=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

. "$(dirname "$0")/dominant_band.sh"
rms_of() {
    "$fulgur" analyze "$1" | sed -n 's/.*rms \([0-9.e+-]*\) Pa.*/\1/p'
}

"$fulgur" render "$dir/wind_wires.json" -o "$tmp/render.wav" --set duration=2 >/dev/null ||
    { echo "wind_wires: render failed"; fail=1; }
"$fulgur" run "$dir/wind_wires.json" --seconds 2 --audio "wav:$tmp/run.wav" \
    --report "$tmp/report.json" || { echo "wind_wires: run failed"; fail=1; }
"$fulgur" run "$dir/wind_wires.json" --seconds 2 --audio "wav:$tmp/again.wav" \
    --report "$tmp/again.json" || { echo "wind_wires: second run failed"; fail=1; }
cmp -s "$tmp/run.wav" "$tmp/again.wav" || { echo "wind_wires: two lock-step runs differ"; fail=1; }
"$fulgur" analyze "$tmp/render.wav" --spectrogram "$tmp/render.dat" >/dev/null
"$fulgur" analyze "$tmp/run.wav" --spectrogram "$tmp/run.dat" >/dev/null
awk -v a="$(dominant "$tmp/render.dat")" -v b="$(dominant "$tmp/run.dat")" \
    -v ra="$(rms_of "$tmp/render.wav")" -v rb="$(rms_of "$tmp/run.wav")" 'BEGIN {
    db = 20 * log(rb / ra) / log(10);
    printf "wires: run %.1f Hz, render %.1f Hz; rms run %.4g Pa, render %.4g Pa (%+.2f dB)\n",
           b, a, rb, ra, db;
    exit !(a == b && db > -1 && db < 1)}' || { echo "wind_wires: run and render disagree"; fail=1; }
# 3 objects, a pose each per 90 Hz tick of the 2 s (180, and the few
# ticks the frame thread runs ahead and at the start)
posted=$(grep -A2 '"aero_objects"' "$tmp/report.json" | sed -n 's/.*"count":[[:space:]]*\([0-9]*\).*/\1/p')
poses=$(grep -A2 '"aero_objects"' "$tmp/report.json" | sed -n 's/.*"poses_set":[[:space:]]*\([0-9]*\).*/\1/p')
awk -v n="${posted:-0}" -v p="${poses:-0}" 'BEGIN {printf "wires: %d objects posted, %d poses set\n", n, p;
    exit !(n == 3 && p >= 3 * 181 && p <= 3 * 185)}' ||
    { echo "wind_wires: the report's aero objects: $posted posted, $poses poses"; fail=1; }

# the swing is fastest halfway (0.2 + 0.125 s), 1.5 m away: loudest then
"$fulgur" run "$dir/sword_swing.json" --audio "wav:$tmp/sword.wav" --report "$tmp/sword.json" ||
    { echo "sword_swing: run failed"; fail=1; }
"$fulgur" analyze "$tmp/sword.wav" --waveform "$tmp/sword.dat" >/dev/null
awk '$1 !~ /#/ {a = $3 > -$2 ? $3 : -$2; if (a > m) {m = a; at = $1}}
     END {printf "sword_swing (run): loudest at %.4f s, peak %.4g Pa\n", at, m;
          exit !(at >= 0.30 && at <= 0.36 && m > 0)}' \
    "$tmp/sword.dat" || { echo "sword_swing: not loudest at the swing's fastest"; fail=1; }

# a motion too fast: refused, exit 2, nothing written
"$fulgur" run "$scenes/bad_aero_throw_fast.json" --audio "wav:$tmp/bad.wav" 2>"$tmp/bad.err"
rc=$?
if [ "$rc" -ne 2 ] || [ -e "$tmp/bad.wav" ] || ! grep -q "faster than 100 m/s" "$tmp/bad.err"; then
    echo "bad_aero_throw_fast: exit $rc, $(cat "$tmp/bad.err")"; fail=1
fi
exit $fail
