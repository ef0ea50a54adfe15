#!/bin/sh
# fulgur-lv2-render on a one-note MIDI file: exit 0, one discharge, a WAV
# whose peak `fulgur analyze` reads; the same with LV2_PATH relative to the
# working directory (lilv alone crashes on that); on a file that is not MIDI:
# exit 2, the message, no WAV. Every layout's plugin (--layout): binaural
# two channels unlike stereo's, beginning where stereo's does (its latency
# compensated), --sofa naming the same KEMAR set by its
# other name the same bytes, ambisonics:2 nine channels; a --sofa the plugin
# refuses, or without binaural: exit 2, the message, no WAV.
# usage: cli_lv2_render.sh FULGUR_LV2_RENDER FULGUR
set -u
render=$1 fulgur=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# format 0, 480 ticks per quarter, 120 bpm: note 60 on at 0, off at 0.5 s
printf 'MThd\000\000\000\006\000\000\000\001\001\340MTrk\000\000\000\023\000\377\121\003\007\241\040\000\220\074\144\203\140\074\000\000\377\057\000' > "$dir/one.mid"
out=$("$render" "$dir/one.mid" -o "$dir/one.wav" -t 1 distance=5 gain=-30) || { echo "render failed: $out"; exit 1; }
echo "$out"
echo "$out" | grep -q "^1.500 s, 1 discharges$" || { echo "expected 1.5 s and 1 discharge"; exit 1; }
info=$("$fulgur" analyze "$dir/one.wav") || exit 1
echo "$info"
# a spark 5 m away peaks near 60 Pa; -30 dB makes that about 2
echo "$info" | awk '{for (i = 1; i < NF; i++) if ($i == "peak") p = $(i + 1)} END {exit !(p > 0.5 && p < 10)}' ||
    { echo "peak out of range"; exit 1; }
# LV2_PATH relative: a ../-path from a folder beside it, and an entry that is not there
mkdir "$dir/cwd"
relative=$(cd "$dir/cwd" && realpath --relative-to=. "$LV2_PATH")
(cd "$dir/cwd" && LV2_PATH="nowhere:$relative" "$render" ../one.mid -o ../rel.wav -t 1 distance=5 gain=-30) ||
    { echo "render with a relative LV2_PATH ($relative) failed"; exit 1; }
cmp "$dir/one.wav" "$dir/rel.wav" || { echo "a relative LV2_PATH rendered other bytes"; exit 1; }
printf 'not midi' > "$dir/bad.mid"
"$render" "$dir/bad.mid" -o "$dir/bad.wav" 2> "$dir/err"
rc=$?
cat "$dir/err"
[ $rc -eq 2 ] || { echo "expected exit 2, got $rc"; exit 1; }
grep -q "not a Standard MIDI File" "$dir/err" || exit 1
[ ! -e "$dir/bad.wav" ] || { echo "a WAV was left behind"; exit 1; }
# 40 bytes naming a note 4.5e9 s ahead (1 tick per quarter, a 16.8 s quarter,
# a delta of 0x0FFFFFFF): once 8.6 GB of WAV in 20 s; now exit 2 at once
printf 'MThd\000\000\000\006\000\000\000\001\000\001MTrk\000\000\000\022\000\377\121\003\377\377\377\377\377\377\177\220\074\144\000\377\057\000' > "$dir/far.mid"
"$render" "$dir/far.mid" -o "$dir/far.wav" 2> "$dir/err"
rc=$?
cat "$dir/err"
[ $rc -eq 2 ] || { echo "far future: expected exit 2, got $rc"; exit 1; }
grep -q "after the 3600 s a render may reach" "$dir/err" || exit 1
[ -z "$(ls -A "$dir" | grep far.wav)" ] || { echo "far future: a WAV was left behind"; exit 1; }
# the layouts
"$render" "$dir/one.mid" -o "$dir/bin.wav" -t 1 distance=5 gain=-30 --layout binaural ||
    { echo "binaural render failed"; exit 1; }
"$fulgur" analyze "$dir/bin.wav" | grep -q ": 2 ch, 48000 Hz, 1.500 s" || { echo "binaural: not 2 channels"; exit 1; }
cmp -s "$dir/one.wav" "$dir/bin.wav" && { echo "binaural rendered the stereo bytes"; exit 1; }
# the binaural plugin's 128 frames of latency compensated: its spark begins
# where the stereo plugin's does, but for the way around the head (0.75 ms
# in the envelope's rows here; 3.75 ms without the compensation)
onset() {
    "$fulgur" analyze "$1" --waveform "$dir/env.dat" > /dev/null &&
        awk 'NR > 1 { m = 0; for (i = 2; i <= NF; i++) { v = $i < 0 ? -$i : $i; if (v > m) m = v }
                      t[NR] = $1; a[NR] = m; if (m > peak) peak = m }
             END { for (i = 2; i <= NR; i++) if (a[i] > 0.1 * peak) { print t[i]; exit } }' "$dir/env.dat"
}
st=$(onset "$dir/one.wav") bin=$(onset "$dir/bin.wav")
echo "onsets: stereo $st s, binaural $bin s"
awk -v s="$st" -v b="$bin" 'BEGIN { exit !(s > 0 && b - s >= 0 && b - s < 0.002) }' ||
    { echo "binaural begins $st -> $bin s: the plugin's latency not compensated"; exit 1; }
"$render" "$dir/one.mid" -o "$dir/kemar.wav" -t 1 distance=5 gain=-30 --layout binaural \
    --sofa /usr/share/libmysofa/default.sofa || { echo "--sofa default.sofa failed"; exit 1; }
cmp "$dir/bin.wav" "$dir/kemar.wav" || { echo "the same SOFA set by another name rendered other bytes"; exit 1; }
"$render" "$dir/one.mid" -o "$dir/amb.wav" -t 1 distance=5 gain=-30 --layout ambisonics:2 ||
    { echo "ambisonics render failed"; exit 1; }
"$fulgur" analyze "$dir/amb.wav" | grep -q ": 9 ch, 48000 Hz" || { echo "ambisonics:2: not 9 channels"; exit 1; }
"$render" "$dir/one.mid" -o "$dir/nosofa.wav" --layout binaural --sofa "$dir/one.mid" 2> "$dir/err"
rc=$?
cat "$dir/err"
[ $rc -eq 2 ] || { echo "a MIDI file as --sofa: expected exit 2, got $rc"; exit 1; }
grep -q "sofa: $dir/one.mid: not a SOFA file" "$dir/err" || exit 1
grep -q -- "--sofa $dir/one.mid: the plugin refused it" "$dir/err" || exit 1
[ ! -e "$dir/nosofa.wav" ] || { echo "a refused --sofa left a WAV"; exit 1; }
"$render" "$dir/one.mid" -o "$dir/nosofa.wav" --sofa /usr/share/libmysofa/default.sofa 2> "$dir/err"
rc=$?
[ $rc -eq 2 ] && grep -q "only with --layout binaural" "$dir/err" || { echo "--sofa without binaural: rc $rc"; cat "$dir/err"; exit 1; }
# another SOFA set (16 directions, a pulse in each ear, written by ncgen):
# two channels, not KEMAR's
if command -v ncgen >/dev/null 2>&1; then
    tmp=$dir
    . "$(dirname "$0")/sofa_cdl.sh"
    sofa pulses 16 2 32 48000
    "$render" "$dir/one.mid" -o "$dir/pulses.wav" -t 1 distance=5 gain=-30 --layout binaural \
        --sofa "$dir/pulses.sofa" || { echo "--sofa pulses.sofa failed"; exit 1; }
    "$fulgur" analyze "$dir/pulses.wav" | grep -q ": 2 ch, 48000 Hz, 1.500 s" || exit 1
    cmp -s "$dir/bin.wav" "$dir/pulses.wav" && { echo "another SOFA set rendered KEMAR's bytes"; exit 1; }
else
    echo "ncgen not found (netcdf-bin): another SOFA set not tried"
fi
echo ok
