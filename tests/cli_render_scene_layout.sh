#!/bin/sh
# usage: cli_render_scene_layout.sh FULGUR SCENE
# The scene's "layout" key: ambisonics order 2 writes 9 channels, binaural
# 2, its "sofa" is read relative to the scene's folder and is the same
# render as --sofa naming the file; --layout overrides the key (stereo: 2
# channels, the same file as the scene without the key). A bad type, an
# order outside 1..3, an order or sofa for the wrong type, "channels" with a
# non-stereo layout and a missing layout.sofa exit 2 naming the key, and
# write nothing (fulgur run's layouts: cli_run_layout.sh).
set -u
fulgur=$1
scene=$2
kemar=/usr/share/libmysofa/MIT_KEMAR_normal_pinna.sofa
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
with() { # with NAME JSON: the scene (without its "channels") with JSON after its first "{" as $tmp/NAME.json
    grep -v "^ *\"channels\":" "$scene" | sed "1s|{|{$2,|" >"$tmp/$1.json"
}
channels() { # channels WAV: its channel count
    "$fulgur" analyze "$1" | sed -n 's/.*: \([0-9]*\) ch,.*/\1/p'
}
expect() { # expect WHAT WAV N
    n=$(channels "$2")
    [ "$n" = "$3" ] || { echo "$1: $n channels, want $3"; exit 1; }
}
with ambi '"layout": {"type": "ambisonics", "order": 2}'
"$fulgur" render "$tmp/ambi.json" --quiet -o "$tmp/ambi.wav" || exit 1
expect "ambisonics order 2" "$tmp/ambi.wav" 9
"$fulgur" render "$tmp/ambi.json" --quiet --layout stereo -o "$tmp/over.wav" || exit 1
"$fulgur" render "$scene" --quiet -o "$tmp/plain.wav" || exit 1
cmp -s "$tmp/over.wav" "$tmp/plain.wav" || { echo "--layout stereo over the key differs from the plain scene"; exit 1; }
"$fulgur" render "$tmp/ambi.json" --quiet --layout ambisonics:3 -o "$tmp/a3.wav" || exit 1
expect "--layout ambisonics:3 over order 2" "$tmp/a3.wav" 16
cp "$kemar" "$tmp/kemar.sofa"
with bin '"layout": {"type": "binaural", "sofa": "kemar.sofa"}'
"$fulgur" render "$tmp/bin.json" --quiet -o "$tmp/bin.wav" || exit 1
expect "binaural" "$tmp/bin.wav" 2
"$fulgur" render "$scene" --quiet --layout binaural --sofa "$kemar" -o "$tmp/flag.wav" || exit 1
cmp -s "$tmp/bin.wav" "$tmp/flag.wav" || { echo "layout.sofa differs from --sofa of the same file"; exit 1; }
refuse() { # refuse WHAT NAMED JSON [ARGS...]: exit 2, NAMED in the message, no WAV
    what=$1 named=$2
    with bad "$3"
    shift 3
    "$fulgur" render "$tmp/bad.json" --quiet "$@" -o "$tmp/bad.wav" 2>"$tmp/err"
    rc=$?
    [ $rc -eq 2 ] || { echo "$what: exit $rc, want 2"; cat "$tmp/err"; exit 1; }
    grep -q -- "$named" "$tmp/err" || { echo "$what: the message does not name $named"; cat "$tmp/err"; exit 1; }
    [ ! -e "$tmp/bad.wav" ] || { echo "$what: wrote the WAV"; exit 1; }
    cat "$tmp/err"
}
refuse "an unknown type" "layout.type" '"layout": {"type": "quad"}'
refuse "no type" "layout.type" '"layout": {"order": 2}'
refuse "order 4" "layout.order" '"layout": {"type": "ambisonics", "order": 4}'
refuse "order 0" "layout.order" '"layout": {"type": "ambisonics", "order": 0}'
refuse "order with binaural" "layout.order" '"layout": {"type": "binaural", "order": 1}'
refuse "sofa with stereo" "layout.sofa" '"layout": {"type": "stereo", "sofa": "kemar.sofa"}'
refuse "an unknown key" "layout" '"layout": {"type": "stereo", "gain": 1}'
refuse "not an object" "layout" '"layout": "binaural"'
refuse "channels with ambisonics" "channels" '"channels": 2, "layout": {"type": "ambisonics"}'
refuse "a missing layout.sofa" "layout.sofa" '"layout": {"type": "binaural", "sofa": "none.sofa"}'
refuse "--sofa over a stereo key" "--sofa" '"layout": {"type": "stereo"}' --sofa "$kemar"
echo "scene layout: 9, 16 and 2 channels as asked, --layout over the key, bad keys refused"
