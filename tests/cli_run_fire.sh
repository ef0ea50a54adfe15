#!/bin/sh
# usage: cli_run_fire.sh FULGUR EXAMPLES_FIRE_DIR
# fulgur run plays fires (examples/fire/) through its three threads, the
# sim thread feeding each fire's sound and moving it, in lock-step
# (--audio wav:) so the numbers repeat: the campfire's RMS within 1 dB of
# render's (run sways the head a few centimetres: not the same samples);
# two runs byte-identical; the report counting the fire with no underrun;
# the torch carried past loudest as it passes, which it is only if its
# poses are published (held at its first point it would be as loud early
# as midway); the campfire at another rate than the scene's (--rate
# 44100) within 1 dB of it; the run's rate too low for the fire's
# flux rate refused with exit 2 and no WAV.
set -u
fulgur=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

rms_of() {
    "$fulgur" analyze "$1" | sed -n 's/.*rms \([0-9.e+-]*\) Pa.*/\1/p'
}
within_1db() { # label, rms a, rms b
    awk -v l="$1" -v a="$2" -v b="$3" 'BEGIN {db = 20 * log(b / a) / log(10);
        printf "%s: rms %.4g Pa against %.4g Pa (%+.2f dB)\n", l, b, a, db;
        exit !(a > 0 && db > -1 && db < 1)}'
}

"$fulgur" render "$dir/campfire.json" -o "$tmp/render.wav" --set duration=3 >/dev/null ||
    { echo "campfire: render failed"; fail=1; }
for name in run again; do
    "$fulgur" run "$dir/campfire.json" --seconds 3 --audio "wav:$tmp/$name.wav" \
        --report "$tmp/$name.json" || { echo "campfire: run ($name) failed"; fail=1; }
done
cmp -s "$tmp/run.wav" "$tmp/again.wav" || { echo "campfire: two lock-step runs differ"; fail=1; }
within_1db "campfire, run against render" "$(rms_of "$tmp/render.wav")" "$(rms_of "$tmp/run.wav")" ||
    { echo "campfire: run and render disagree"; fail=1; }
count=$(grep -A2 '"fires"' "$tmp/run.json" | sed -n 's/.*"count":[[:space:]]*\([0-9]*\).*/\1/p')
under=$(grep -A2 '"fires"' "$tmp/run.json" | sed -n 's/.*"underrun_frames":[[:space:]]*\([0-9]*\).*/\1/p')
[ "${count:-0}" = 1 ] && [ "${under:-x}" = 0 ] ||
    { echo "campfire: the report's fires: count '$count', underrun frames '$under'"; fail=1; }

"$fulgur" run "$dir/campfire.json" --seconds 3 --rate 44100 --audio "wav:$tmp/r44.wav" \
    --report "$tmp/r44.json" || { echo "campfire at 44.1 kHz: run failed"; fail=1; }
within_1db "campfire, run at 44.1 kHz against 48 kHz" "$(rms_of "$tmp/run.wav")" \
    "$(rms_of "$tmp/r44.wav")" || { echo "campfire: 44.1 kHz and 48 kHz disagree"; fail=1; }

# the torch passes 2 m in front at 4 s, 10 m away at 1 s and at 7 s
"$fulgur" run "$dir/torch.json" --audio "wav:$tmp/torch.wav" --report "$tmp/torch.json" ||
    { echo "torch: run failed"; fail=1; }
"$fulgur" analyze "$tmp/torch.wav" --waveform "$tmp/torch.dat" >/dev/null
awk '$1 !~ /#/ {a = ($3 - $2) ^ 2 + ($5 - $4) ^ 2
         if ($1 > 0.5 && $1 < 1.5) e += a; else if ($1 > 3.5 && $1 < 4.5) m += a
         else if ($1 > 6.5 && $1 < 7.5) l += a}
     END {de = 10 * log(m / e) / log(10); dl = 10 * log(m / l) / log(10)
          printf "torch (run): passing %+.1f dB over 1 s, %+.1f dB over 7 s\n", de, dl
          exit !(e > 0 && l > 0 && de > 6 && dl > 6)}' "$tmp/torch.dat" ||
    { echo "torch: not loudest as it passes"; fail=1; }

# a flux at 12 kHz needs a rate of 48 kHz (sim_rate <= rate / 4): the
# scene's is, a run at 44.1 kHz is not
cp "$dir/campfire.flux" "$tmp/"
cat >"$tmp/fast_flux.json" <<'JSON'
{"sample_rate": 48000, "listener": {"position": [0, 0, 1.2]},
 "fires": [{"position": [0, 3, 0.3], "flux": "campfire.flux", "sim_rate": 12000}]}
JSON
"$fulgur" run "$tmp/fast_flux.json" --rate 44100 --audio "wav:$tmp/bad.wav" 2>"$tmp/bad.err"
rc=$?
if [ "$rc" -ne 2 ] || [ -e "$tmp/bad.wav" ] || ! grep -q "fires\[0\]" "$tmp/bad.err"; then
    echo "a flux too fast for the run's rate: exit $rc, $(cat "$tmp/bad.err")"; fail=1
fi
exit $fail
