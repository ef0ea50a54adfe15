#!/bin/sh
# usage: cli_view.sh FULGUR SCENE PNG_MEAN
# fulgur view headless (EGL on llvmpipe), driven by a script: the frames are
# written with the expected names and are valid PNGs; the frames after a
# discharge are brighter than before it; a hold glows on every frame while
# held; the WAV is silent before the discharge's sound and not after; two
# placed charges give a discharge of their own; bad --gl, a window without a
# display and a bad script fail cleanly.
set -u
fulgur=$1
scene=$2
mean="python3 $3"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "$@"; exit 1; }
run() { "$fulgur" view "$scene" --gl egl --size 160x90 --fps 60 "$@"; }

# space at frame 4 (emitted 50 ms later: frame 7 at 60 fps), H from 12 to 20
cat > "$tmp/script" <<'END'
# comments and blank lines are allowed

frame 4 key space
frame 12 key h
frame 20 key h
END
mkdir "$tmp/png"
run --frames 24 --png-dir "$tmp/png" --script "$tmp/script" --audio "wav:$tmp/v.wav" \
    > "$tmp/summary.json" || fail "the scripted run failed"
grep -q '"frames": 24, "requests": 3, "posted": 2' "$tmp/summary.json" ||
    fail "unexpected summary: $(cat "$tmp/summary.json")"
[ "$(ls "$tmp/png" | wc -l)" -eq 24 ] || fail "expected 24 frames: $(ls "$tmp/png")"
for k in 0000 0023; do [ -f "$tmp/png/frame_$k.png" ] || fail "no frame_$k.png"; done
$mean "$tmp/png"/*.png > "$tmp/means" || fail "an invalid PNG: $(tail -1 "$tmp/means")"
m() { awk -v f="frame_$1.png" 'index($1, f) { print $2 }' "$tmp/means"; }
before=$(m 0003)
awk -v b="$before" -v a="$(m 0008)" 'BEGIN { exit !(a > b + 0.5) }' ||
    fail "frame 8 ($(m 0008)) is not brighter than frame 3 ($before)"
for k in 0014 0016 0018 0019; do
    awk -v b="$before" -v a="$(m $k)" 'BEGIN { exit !(a > b + 0.5) }' ||
        fail "no glow at frame $k while held ($(m $k) against $before)"
done
# the sound: silent before the first emit (0.117 s), then not
python3 - "$tmp/v.wav" <<'END' || fail "the WAV is silent after the discharge, or not before"
import struct, sys
d = open(sys.argv[1], 'rb').read()
i = 12
while d[i:i + 4] != b'data':
    i += 8 + struct.unpack('<I', d[i + 4:i + 8])[0]
n = struct.unpack('<I', d[i + 4:i + 8])[0] // 4
x = struct.unpack('<%df' % n, d[i + 8:i + 8 + 4 * n])
cut = 2 * int(0.11 * 48000)
assert len(x) == 2 * 19200, len(x)  # 24 frames at 60 fps, 48 kHz, stereo
assert max(abs(v) for v in x[:cut]) == 0
assert max(abs(v) for v in x[cut:]) > 1e-3
END

# a positive charge above a negative one, then space: a leader between them
printf 'frame 1 click 0.5 0.3 left\nframe 2 click 0.5 0.7 right\nframe 3 key space\n' \
    > "$tmp/charges"
run --frames 12 --script "$tmp/charges" > "$tmp/charges.json" ||
    fail "the charges run failed"
grep -q '"posted": 1' "$tmp/charges.json" || fail "no discharge between the charges: $(cat "$tmp/charges.json")"

# errors: a clear message, the usage exit code or 1, never a crash
"$fulgur" view "$scene" --gl bogus 2> "$tmp/err"
[ $? -eq 2 ] || fail "--gl bogus: expected exit 2"
grep -q 'use egl, osmesa or window' "$tmp/err" || fail "--gl bogus: $(cat "$tmp/err")"
env -u DISPLAY -u WAYLAND_DISPLAY "$fulgur" view "$scene" --gl window --frames 2 2> "$tmp/err"
rc=$?
[ $rc -eq 1 ] || fail "--gl window without a display: exit $rc, expected 1: $(cat "$tmp/err")"
grep -q '^fulgur view: --gl window: ' "$tmp/err" || fail "--gl window: $(cat "$tmp/err")"
echo 'frame x key space' > "$tmp/bad"
run --frames 2 --script "$tmp/bad" 2> "$tmp/err"
[ $? -eq 2 ] || fail "a bad script: expected exit 2"
grep -q "bad:1: expected" "$tmp/err" || fail "a bad script: $(cat "$tmp/err")"
echo "the scripted frames, the glow, the sound and the errors are as expected"
