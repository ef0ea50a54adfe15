#!/bin/sh
# usage: cli_render_png_sources.sh FULGUR EXAMPLES_DIR PNG_CHECK
# fulgur render --png of scenes without discharges (it crashed on them:
# the framing read discharges[0]): the campfire's flame glows in the middle
# of the frame and the corners stay dark, without a warning; the torch
# carried past is left of the middle at 0 s and right of it at 8 s (the
# flame follows the fire's path); the sword swing's picture is written,
# with the warning that nothing in it glows.
set -u
fulgur=$1
dir=$2
check=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
png() { # png NAME SCENE TIME: a 320 x 180 picture, stderr in NAME.err
    "$fulgur" render "$2" -o "$tmp/$1.wav" --png "$tmp/$1.png" --png-time "$3" --size 320x180 \
        --quiet 2>"$tmp/$1.err" || { echo "$1: exit $?, $(cat "$tmp/$1.err")"; fail=1; }
}
region() { /usr/bin/python3 "$check" region "$@"; }

png campfire "$dir/fire/campfire.json" 1
awk -v c="$(region "$tmp/campfire.png" 140 60 180 120)" -v k="$(region "$tmp/campfire.png" 0 0 40 40)" \
    'BEGIN {printf "campfire: middle %.1f, corner %.1f of 255\n", c, k; exit !(c > 40 && k < 5)}' ||
    { echo "campfire: no flame in the middle"; fail=1; }
[ ! -s "$tmp/campfire.err" ] || { echo "campfire: $(cat "$tmp/campfire.err")"; fail=1; }
for t in 0 8; do
    png "torch$t" "$dir/fire/torch.json" "$t"
    awk -v t="$t" -v l="$(region "$tmp/torch$t.png" 0 0 160 180)" \
        -v r="$(region "$tmp/torch$t.png" 160 0 320 180)" \
        'BEGIN {printf "torch at %s s: left %.4f, right %.4f\n", t, l, r
                exit !(t == 0 ? l > 2 * r + 0.01 : r > 2 * l + 0.01)}' ||
        { echo "torch at $t s: the flame is not where the fire is"; fail=1; }
done
png sword "$dir/aero/sword_swing.json" 0.33
[ -s "$tmp/sword.png" ] || { echo "sword_swing: no picture"; fail=1; }
grep -q "no discharge and no fire" "$tmp/sword.err" ||
    { echo "sword_swing: no warning that nothing glows: $(cat "$tmp/sword.err")"; fail=1; }
exit $fail
