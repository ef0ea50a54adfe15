#!/bin/sh
# usage: cli_render_fire_sim.sh FULGUR EXAMPLES_DIR
# A scene fire driven by the flame simulation (fires[i].simulation): the
# campfire_sim example renders, is heard at a level between 0.001 and
# 0.05 Pa rms at the ears; the same simulation run live (stepped as the
# fire sounds, "live": true) gives the offline run's bytes, in fulgur
# render and, in lock-step, in fulgur run (which then ends a block later at
# most: the samples they share are compared); bad simulation entries exit
# 2 naming the field.
set -u
fulgur=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$fulgur" render "$dir/campfire_sim.json" -o "$tmp/c.wav" > /dev/null || fail "render"
rms=$("$fulgur" analyze "$tmp/c.wav" | sed -n 's/.*rms \([0-9.e+-]*\) Pa.*/\1/p')
echo "campfire_sim rms $rms Pa"
awk -v r="$rms" 'BEGIN { exit !(r > 0.001 && r < 0.05) }' || fail "rms $rms Pa outside 0.001 .. 0.05"

# 12^3, 2 s: the live and the offline simulation, render and run
small='--set fires[0].simulation.cells=12 --set fires[0].simulation.seconds=2'
# shellcheck disable=SC2086
"$fulgur" render "$dir/campfire_sim.json" $small -o "$tmp/off.wav" --quiet || fail "render offline"
# shellcheck disable=SC2086
"$fulgur" render "$dir/campfire_sim.json" $small --set fires[0].simulation.live=true \
    -o "$tmp/live.wav" --quiet || fail "render live"
cmp -s "$tmp/off.wav" "$tmp/live.wav" || fail "the live simulation's render differs from the offline one's"
sed 's/"cells": 16, "seconds": 4,/"cells": 12, "seconds": 2,/' "$dir/campfire_sim.json" >"$tmp/off.json"
sed 's/"cells": 16, "seconds": 4,/"cells": 12, "seconds": 2, "live": true,/' "$dir/campfire_sim.json" \
    >"$tmp/live.json"
grep -q '"live": true' "$tmp/live.json" || fail "campfire_sim.json no longer has cells 16, seconds 4"
"$fulgur" run "$tmp/off.json" --audio "wav:$tmp/run_off.wav" --report "$tmp/off.rep" ||
    fail "run offline"
"$fulgur" run "$tmp/live.json" --audio "wav:$tmp/run_live.wav" --report "$tmp/live.rep" ||
    fail "run live"
grep -A2 '"fires"' "$tmp/live.rep" | grep -q '"underrun_frames":[[:space:]]*0' ||
    fail "the live run's fire ran dry in lock-step"
# the same header layout (sizes aside: bytes 5-8, the fact chunk's 45-48,
# the data chunk's 85-88) and the same samples as far as the shorter goes
cmp -l "$tmp/run_off.wav" "$tmp/run_live.wav" 2>/dev/null |
    awk '!($1 <= 8 || ($1 >= 45 && $1 <= 48) || ($1 >= 85 && $1 <= 88)) {bad++}
         END {printf "live and offline runs: %d bytes differ beyond the sizes\n", bad; exit bad > 0}' ||
    fail "the live simulation's run differs from the offline one's"

bad() { # json, expected words
    printf '{"sample_rate": 48000, "listener": {"position": [0,0,1]}, "fires": [%s]}' "$1" > "$tmp/b.json"
    "$fulgur" render "$tmp/b.json" -o "$tmp/b.wav" 2> "$tmp/err" > /dev/null
    rc=$?
    [ "$rc" -eq 2 ] || fail "$1: exit $rc, not 2"
    grep -q "$2" "$tmp/err" || fail "$1: message lacks '$2': $(cat "$tmp/err")"
    [ ! -e "$tmp/b.wav" ] || fail "$1: wrote a file"
}
bad '{"position": [0,2,0], "flux": "x.flux", "simulation": {"emitter": "torch"}}' 'not both'
bad '{"position": [0,2,0], "simulation": {"emitter": "candle"}}' 'fires\[0\].simulation.emitter'
bad '{"position": [0,2,0], "simulation": {"emitter": "torch", "cells": 64}}' 'fires\[0\].simulation.cells'
bad '{"position": [0,2,0], "simulation": {"cells": 16}}' 'required'
bad '{"position": [0,2,0], "simulation": {"emitter": "torch", "colour": 1}}' 'colour'
bad '{"position": [0,2,0], "simulation": {"emitter": "torch", "live": 1}}' 'fires\[0\].simulation.live'
echo "ok"
