#!/bin/sh
# usage: cli_render_fire_sim.sh FULGUR EXAMPLES_DIR
# A scene fire driven by the flame simulation (fires[i].simulation): the
# campfire_sim example renders, is heard at a level between 0.001 and
# 0.05 Pa rms at the ears, and bad simulation entries exit 2 naming the field.
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
echo "ok"
