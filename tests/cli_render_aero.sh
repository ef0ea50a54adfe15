#!/bin/sh
# usage: cli_render_aero.sh FULGUR EXAMPLES_AERO_DIR
# fulgur render of the aero examples (examples/aero/), with numbers that
# can fail: the wires' aeolian tone at Strouhal's f = St v / D (the
# texture's shedding frequency times v / v0), the thrown stick silent
# until its emission has had time to arrive, the sword loudest at its
# fastest, the fence's bars before the bolt's thunder and the thunder
# after, and every example's peak within the range a body of its size
# and speed gives; and the same bytes whatever the render's block.
set -u
fulgur=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

. "$(dirname "$0")/dominant_band.sh"
. "$(dirname "$0")/same_at_blocks.sh"

# wires in a steady 9 m/s wind: the texture's frequency at 10 m/s, x 0.9
"$fulgur" render "$dir/wind_wires.json" -o "$tmp/wires.wav" --set wind.gust=0 --set duration=1 \
    >/dev/null || { echo "wind_wires: render failed"; fail=1; }
"$fulgur" analyze "$tmp/wires.wav" --spectrogram "$tmp/wires.dat" >/dev/null
f_tex=$("$fulgur" aerotex --info "$dir/wire_4mm.aerotex" | awk '$1 == "0.000" {print $2}')
f_peak=$(dominant "$tmp/wires.dat")
awk -v f="$f_peak" -v t="$f_tex" 'BEGIN {want = 0.9 * t; d = f - want; if (d < 0) d = -d;
    printf "wires: dominant band %.1f Hz, St v / D = %.1f Hz\n", f, want; exit !(d <= 24)}' ||
    { echo "wind_wires: the tone is not at 0.9 x $f_tex Hz"; fail=1; }

# the stick sounds from 0.1 s; it is at least 4.9 m away: nothing before 0.114 s
"$fulgur" render "$dir/thrown_stick.json" -o "$tmp/stick.wav" >/dev/null ||
    { echo "thrown_stick: render failed"; fail=1; }
"$fulgur" analyze "$tmp/stick.wav" --waveform "$tmp/stick.dat" >"$tmp/stick.txt"
first=$(awk '$1 !~ /#/ && ($2 != 0 || $3 != 0) {print $1; exit}' "$tmp/stick.dat")
awk -v t="$first" 'BEGIN {printf "stick: first sound at %s s\n", t; exit !(t >= 0.114 && t < 0.2)}' ||
    { echo "thrown_stick: first sound at $first s, expected 0.114 .. 0.2 s"; fail=1; }

# peaks, dB SPL: ranges for the sizes, speeds and distances of each scene
check_peak() { # name lo hi
    "$fulgur" render "$dir/$1.json" -o "$tmp/$1.wav" >/dev/null || { echo "$1: render failed"; fail=1; return; }
    spl=$("$fulgur" analyze "$tmp/$1.wav" | sed -n 's/.*peak [^ ]* Pa (\([-0-9.]*\) dB SPL).*/\1/p')
    awk -v s="$spl" -v lo="$2" -v hi="$3" -v n="$1" \
        'BEGIN {printf "%s: peak %s dB SPL (%s..%s)\n", n, s, lo, hi; exit !(s >= lo && s <= hi)}' ||
        { echo "$1: peak $spl dB SPL outside $2..$3"; fail=1; }
}
check_peak thrown_stick 40 80
check_peak wind_wires 50 95
check_peak sword_swing 40 90

# the swing is fastest halfway (0.2 + 0.125 s), 1.5 m away: loudest then
"$fulgur" analyze "$tmp/sword_swing.wav" --waveform "$tmp/sword.dat" >/dev/null
awk '$1 !~ /#/ {a = $3 > -$2 ? $3 : -$2; if (a > m) {m = a; at = $1}}
     END {printf "sword_swing: loudest at %.4f s\n", at; exit !(at >= 0.30 && at <= 0.36)}' \
    "$tmp/sword.dat" || { echo "sword_swing: not loudest at the swing's fastest"; fail=1; }

# the fence and the bolt in one engine: the bars' whistle before the
# thunder can arrive (the strike 1 km away at 0.5 s; its nearest branches
# are heard from 2.75 s on), the thunder after
"$fulgur" render "$dir/fence_storm.json" -o "$tmp/fence.wav" >/dev/null 2>&1 ||
    { echo "fence_storm: render failed"; fail=1; }
"$fulgur" analyze "$tmp/fence.wav" --waveform "$tmp/fence.dat" >/dev/null
awk '$1 !~ /#/ {a = $3 > -$2 ? $3 : -$2; if ($1 < 2.5) {if (a > w) w = a} else if (a > t) t = a}
     END {w = 20 * log(w / 2e-5) / log(10); t = 20 * log(t / 2e-5) / log(10);
          printf "fence_storm: bars %.1f dB SPL before 2.5 s, thunder %.1f dB SPL after\n", w, t;
          exit !(w >= 60 && w <= 105 && t > w + 10)}' "$tmp/fence.dat" ||
    { echo "fence_storm: the bars or the thunder out of range"; fail=1; }
# the swinging sword and the nine bars (posted in one block, more than the
# engine adopts in one by default)
same_at_blocks "$dir/sword_swing.json" sword_swing
same_at_blocks "$dir/fence_storm.json" fence_storm
exit $fail
