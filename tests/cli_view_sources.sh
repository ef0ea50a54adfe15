#!/bin/sh
# usage: cli_view_sources.sh FULGUR EXAMPLES_DIR PNG_CHECK
# fulgur view headless (EGL on llvmpipe) plays and draws a scene's fires
# and aero objects, which it refused (no discharge) or left silent: the
# torch carried past (examples/fire/torch.json, 2 s at 30 frames a
# second) sounds as render's within 0.5 dB, its flame drawn left of the
# middle at the first frame and nearer the middle at the last; two runs
# give the same samples (the frame thread waits for the sim thread to
# have fed the fires and published their poses before the audio renders a
# frame); the sword swing (examples/aero/sword_swing.json) within 1 dB of
# render's, its blade drawn left of the middle as it passes in front
# (0.25 s) and right of it where the swing ends (0.98 s). And the viewer's layouts: --layout ambisonics:2 writes 9
# channels within 1 dB of render's RMS in that layout (the campfire),
# binaural 2; ambisonics in a window, on a live device, is refused
# naming the layout, exit 2.
set -u
fulgur=$1
dir=$2
check=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
rms_of() { "$fulgur" analyze "$1" | sed -n 's/.*rms \([0-9.e+-]*\) Pa.*/\1/p'; }
within() { # within LABEL DB A B
    awk -v l="$1" -v lim="$2" -v a="$3" -v b="$4" 'BEGIN {d = 20 * log(b / a) / log(10);
        printf "%s: view rms %.4g Pa, render %.4g Pa (%+.2f dB)\n", l, b, a, d;
        exit !(a > 0 && d > -lim && d < lim)}'
}
same_samples() { # the data chunks of two WAVs (their PEAK chunks carry a time stamp)
    /usr/bin/python3 - "$1" "$2" <<'END'
import struct, sys
def data(path):
    b = open(path, 'rb').read()
    i = 12
    while i < len(b):
        n = struct.unpack('<I', b[i + 4:i + 8])[0]
        if b[i:i + 4] == b'data':
            return b[i + 8:i + 8 + n]
        i += 8 + n + (n & 1)
sys.exit(data(sys.argv[1]) != data(sys.argv[2]))
END
}

for n in 1 2; do
    mkdir "$tmp/torch$n"
    "$fulgur" view "$dir/fire/torch.json" --gl egl --size 160x90 --fps 30 --frames 60 \
        --png-dir "$tmp/torch$n" --audio "wav:$tmp/torch$n.wav" >"$tmp/torch$n.json" ||
        { echo "torch: view $n failed"; fail=1; }
done
"$fulgur" render "$dir/fire/torch.json" -o "$tmp/torch_render.wav" --set duration=2 --quiet
within torch 0.5 "$(rms_of "$tmp/torch_render.wav")" "$(rms_of "$tmp/torch1.wav")" ||
    { echo "torch: view and render disagree"; fail=1; }
same_samples "$tmp/torch1.wav" "$tmp/torch2.wav" || { echo "torch: two headless views differ"; fail=1; }
awk -v a="$(/usr/bin/python3 "$check" region "$tmp/torch1/frame_0000.png" 0 0 40 90)" \
    -v b="$(/usr/bin/python3 "$check" region "$tmp/torch1/frame_0059.png" 0 0 40 90)" \
    'BEGIN {printf "torch: the frame'"'"'s left quarter %.4f at 0 s, %.4f at 2 s\n", a, b
            exit !(a > 2 * b + 0.005)}' || { echo "torch: the flame does not move with the fire"; fail=1; }

mkdir "$tmp/sword"
"$fulgur" view "$dir/aero/sword_swing.json" --gl egl --size 160x90 --fps 60 --frames 60 \
    --png-dir "$tmp/sword" --audio "wav:$tmp/sword.wav" >/dev/null ||
    { echo "sword_swing: view failed"; fail=1; }
"$fulgur" render "$dir/aero/sword_swing.json" -o "$tmp/sword_render.wav" --quiet
within sword_swing 1 "$(rms_of "$tmp/sword_render.wav")" "$(rms_of "$tmp/sword.wav")" ||
    { echo "sword_swing: view and render disagree"; fail=1; }
halves() { # the left and the right half's mean of a 160 x 90 frame
    echo "$(/usr/bin/python3 "$check" region "$1" 0 0 80 90)" \
        "$(/usr/bin/python3 "$check" region "$1" 80 0 160 90)"
}
echo "$(halves "$tmp/sword/frame_0015.png") $(halves "$tmp/sword/frame_0059.png")" |
    awk '{printf "sword_swing: the blade at 0.25 s left %.4f, right %.4f; at 0.98 s left %.4f, " \
                 "right %.4f\n", $1, $2, $3, $4
          exit !($1 > $2 + 0.01 && $4 > $3 + 0.01)}' ||
    { echo "sword_swing: the blade is not drawn where the swing has it"; fail=1; }
for layout in ambisonics:2 binaural; do
    "$fulgur" view "$dir/fire/campfire.json" --gl egl --size 160x90 --fps 30 --frames 30 \
        --layout "$layout" --audio "wav:$tmp/l.wav" >/dev/null || { echo "$layout: view failed"; fail=1; }
    "$fulgur" render "$dir/fire/campfire.json" --layout "$layout" --set duration=1 \
        -o "$tmp/l_render.wav" --quiet
    want=2
    [ "$layout" = binaural ] || want=9
    ch=$("$fulgur" analyze "$tmp/l.wav" | sed -n 's/.*: \([0-9]*\) ch,.*/\1/p')
    [ "$ch" = "$want" ] || { echo "$layout: $ch channels, want $want"; fail=1; }
    within "campfire, $layout" 1 "$(rms_of "$tmp/l_render.wav")" "$(rms_of "$tmp/l.wav")" ||
        { echo "$layout: view and render disagree"; fail=1; }
done
"$fulgur" view "$dir/fire/campfire.json" --gl window --frames 2 --layout ambisonics:1 2>"$tmp/err"
rc=$?
[ "$rc" -eq 2 ] && grep -q "layout: ambisonics" "$tmp/err" ||
    { echo "ambisonics in a window: exit $rc, $(cat "$tmp/err")"; fail=1; }
exit $fail
