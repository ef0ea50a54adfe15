#!/bin/sh
# usage: cli_flame.sh FULGUR
# fulgur flame: every bad option exits 2 with a message naming it and
# writes nothing (an older file at the output path stays as it was); a grid
# too large for memory is refused with its size; a small campfire (16^3,
# 0.25 s) writes one CSV row per step with a positive flux and a WAV of
# the sound.
set -u
fulgur=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
echo old >"$tmp/keep.csv"

# expect MESSAGE ARGS...: exit 2, MESSAGE on stderr, keep.csv untouched
bad() {
    message=$1
    shift
    "$fulgur" flame -o "$tmp/keep.csv" "$@" 2>"$tmp/stderr" >/dev/null
    rc=$?
    if [ "$rc" -ne 2 ]; then
        echo "flame $*: exit $rc, expected 2"; fail=1
    fi
    if ! grep -qF -- "$message" "$tmp/stderr"; then
        echo "flame $*: stderr lacks: $message"; echo "  got: $(cat "$tmp/stderr")"; fail=1
    fi
    [ "$(cat "$tmp/keep.csv")" = old ] || { echo "flame $*: changed the output file"; fail=1; }
}

bad "--cells 4: expected" --cells 4
bad "--cells 16.5: expected" --cells 16.5
bad "--fuel nan: expected" --fuel nan
bad "--fuel -1: expected" --fuel -1
bad "--seconds 0: expected" --seconds 0
bad "--emitter torch: expected source, jet or object" --emitter torch
bad "--at 1,2: expected X,Y,Z" --at 1,2
bad "--jet is required for --emitter jet" --emitter jet
bad "--jet must not be 0,0,0" --emitter jet --jet 0,0,0
bad "--jet applies to --emitter jet only" --jet 1,0,0
bad "--size is required for --shape box" --shape box
bad "--radius applies to --shape sphere only" --shape box --size 0.1,0.1,0.02 --radius 0.1
bad "--sample-rate applies with --wav only" --sample-rate 44100
bad "must lie inside the box, 0 .. 0.64 m" --cells 16 --at 0.7,0.3,0.1
bad "must lie inside the box, 0 .. 0.64 m" --cells 16 --emitter object --at 0.32,0.32,0.03
bad "200^3 cells would need 3" --cells 200
if "$fulgur" flame 2>/dev/null >/dev/null; then echo "flame without -o: exit 0"; fail=1; fi

"$fulgur" flame --cells 16 --seconds 0.25 -o "$tmp/flux.csv" --wav "$tmp/fire.wav" \
    >"$tmp/summary" 2>"$tmp/stderr" || { echo "flame run failed: $(cat "$tmp/stderr")"; fail=1; }
rows=$(tail -n +2 "$tmp/flux.csv" | wc -l)
[ "$rows" -eq 90 ] || { echo "flame: $rows rows, expected 90 (0.25 s at 360 Hz)"; fail=1; }
head -1 "$tmp/flux.csv" | grep -qx "t_s,flux_m3_s,expansion_m3_s,burning_m3_s,triangles" ||
    { echo "flame: CSV header: $(head -1 "$tmp/flux.csv")"; fail=1; }
# after 0.1 s the flame burns: flux within 20 % of the expansion integral
awk -F, 'NR > 37 { if ($2 <= 0 || $2 < 0.8 * $3 || $2 > 1.2 * $3) bad++ } END { exit bad > 0 }' \
    "$tmp/flux.csv" || { echo "flame: a flux off its expansion integral"; fail=1; }
frames=$(sed -n 's/.*; \([0-9]*\) frames of sound.*/\1/p' "$tmp/summary")
size=$(wc -c <"$tmp/fire.wav")
[ -n "$frames" ] && [ "$frames" -gt 11000 ] && [ "$size" -ge $((frames * 4 + 44)) ] ||
    { echo "flame: WAV of $size bytes for '$frames' frames: $(cat "$tmp/summary")"; fail=1; }
exit $fail
