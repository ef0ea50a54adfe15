#!/bin/sh
# usage: cli_render_layout.sh FULGUR SCENE
# fulgur render --layout: ambisonics:1..3 write 4, 9, 16 channels whose W
# (ACN 0) is the one-ear render of the same scene (same peak) and whose
# total energy is order + 1 times it (SN3D); stereo
# writes 2; a bad order or an unknown layout exits 2, naming the option,
# and writes nothing.
set -u
fulgur=$1
scene=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
field() { # field NAME LINE: the word after NAME in LINE
    echo "$2" | awk -v k="$1" '{ for (i = 1; i < NF; i++) if ($i == k) { print $(i + 1); exit } }'
}
"$fulgur" render "$scene" --quiet --set channels=1 -o "$tmp/mono.wav" || exit 1
mono=$("$fulgur" analyze "$tmp/mono.wav") || exit 1
want=$(field peak "$mono")
for order in 1 2 3; do
    "$fulgur" render "$scene" --quiet --layout "ambisonics:$order" -o "$tmp/a$order.wav" || exit 1
    line=$("$fulgur" analyze "$tmp/a$order.wav") || exit 1
    echo "$line"
    ch=$(echo "$line" | sed -n 's/.*: \([0-9]*\) ch,.*/\1/p')
    [ "$ch" = $(( (order + 1) * (order + 1) )) ] || { echo "order $order: $ch channels"; exit 1; }
    [ "$(field peak "$line")" = "$want" ] || { echo "order $order: peak $(field peak "$line"), W should peak at $want"; exit 1; }
    # SN3D: each order adds the energy of W, so the total is order + 1 times
    # the one-ear render's (within 0.1 dB)
    awk -v r="$(field rms "$line")" -v m="$(field rms "$mono")" -v c="$ch" -v n="$order" \
        'BEGIN { db = 10 * log(r * r * c / (m * m * (n + 1))) / log(10); exit !(db < 0.1 && db > -0.1) }' ||
        { echo "order $order: total energy is not $((order + 1)) times W's"; exit 1; }
done
"$fulgur" render "$scene" --quiet --layout stereo --set channels=1 -o "$tmp/s.wav" || exit 1
"$fulgur" analyze "$tmp/s.wav" | grep -q ": 2 ch," || { echo "stereo: not 2 channels"; exit 1; }
for bad in ambisonics:0 ambisonics:4 ambisonics: binaural5 ""; do
    "$fulgur" render "$scene" --quiet --layout "$bad" -o "$tmp/bad.wav" 2>"$tmp/err"
    rc=$?
    [ $rc -eq 2 ] || { echo "--layout '$bad': exit $rc, want 2"; exit 1; }
    grep -q -- "--layout" "$tmp/err" || { echo "--layout '$bad': the message does not name it"; cat "$tmp/err"; exit 1; }
    [ ! -e "$tmp/bad.wav" ] || { echo "--layout '$bad': wrote the WAV"; exit 1; }
done
echo "layouts: 4, 9, 16 channels with W = the one-ear render; bad layouts refused"
