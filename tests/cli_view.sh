#!/bin/sh
# usage: cli_view.sh FULGUR TIMED_SCENE KEYS_SCENE PNG_CHECK
# fulgur view headless (EGL on llvmpipe):
#  - TIMED_SCENE (examples/spark_balls.json, a spark at 0.1 s) with no key:
#    the scene's own discharge is played, the frames after it are brighter
#    than before, the WAV is silent before its sound and not after, the
#    PNGs have the --size asked for, OSMesa draws the same frames as EGL;
#  - KEYS_SCENE (whose own discharge comes after the frames), driven by a
#    script: the frames with the expected names, brighter after space, a
#    hold glowing while held; the overlay (F1) over the top left corner;
#  - two placed charges: their markers where they were clicked, and a
#    discharge of their own;
#  - bad --gl, a window without a display and a bad script fail cleanly.
set -u
fulgur=$1
timed=$2
keys=$3
png="python3 $4"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "$@"; exit 1; }
run() { scene=$1; shift; "$fulgur" view "$scene" --gl egl --size 160x90 --fps 60 "$@"; }
brighter() { awk -v b="$1" -v a="$2" 'BEGIN { exit !(a > b + 0.5) }'; }
# silent_until WAV SECONDS [SAMPLES]: the 48 kHz stereo float WAV is silent
# before SECONDS and not after (and holds SAMPLES samples when given)
silent_until() {
    python3 - "$@" <<'END'
import struct, sys
d = open(sys.argv[1], 'rb').read()
i = 12
while d[i:i + 4] != b'data':
    i += 8 + struct.unpack('<I', d[i + 4:i + 8])[0]
n = struct.unpack('<I', d[i + 4:i + 8])[0] // 4
x = struct.unpack('<%df' % n, d[i + 8:i + 8 + 4 * n])
if len(sys.argv) > 3:
    assert len(x) == int(sys.argv[3]), len(x)
cut = 2 * int(float(sys.argv[2]) * 48000)
assert max(abs(v) for v in x[:cut]) == 0
assert max(abs(v) for v in x[cut:]) > 1e-3
END
}

# the scene's own spark at 0.1 s (frame 6): no key, no script
mkdir "$tmp/timed"
run "$timed" --frames 12 --png-dir "$tmp/timed" --audio "wav:$tmp/t.wav" > "$tmp/timed.json" ||
    fail "the run without keys failed"
grep -q '"frames": 12, "requests": 1, "posted": 1' "$tmp/timed.json" ||
    fail "the scene's timed discharge was not played: $(cat "$tmp/timed.json")"
$png mean "$tmp/timed"/*.png > "$tmp/timed.means" || fail "an invalid PNG: $(tail -1 "$tmp/timed.means")"
tm() { awk -v f="frame_$1.png" 'index($1, f) { print $2 }' "$tmp/timed.means"; }
for k in 0007 0008; do
    brighter "$(tm 0003)" "$(tm $k)" ||
        fail "frame $k ($(tm $k)) after the scene's spark is not brighter than frame 3 ($(tm 0003))"
done
[ "$($png size "$tmp/timed/frame_0000.png")" = 160x90 ] ||
    fail "--size 160x90 gave $($png size "$tmp/timed/frame_0000.png")"
# the sound: silent before the spark's emit (0.1 s), then not
silent_until "$tmp/t.wav" 0.1 || fail "the WAV is silent after the scene's spark, or not before"
# the same shaders on OSMesa: the same frames, byte for byte (when built)
mkdir "$tmp/osmesa"
if "$fulgur" view "$timed" --gl osmesa --size 160x90 --fps 60 --frames 9 --png-dir "$tmp/osmesa" \
    > /dev/null 2> "$tmp/osmesa.err"; then
    for k in 0003 0008; do
        cmp -s "$tmp/osmesa/frame_$k.png" "$tmp/timed/frame_$k.png" ||
            fail "frame $k on OSMesa differs from EGL's"
    done
elif grep -q "backend was not built" "$tmp/osmesa.err"; then
    echo "(no OSMesa in this build: $(cat "$tmp/osmesa.err"))"
else
    fail "the OSMesa run failed: $(cat "$tmp/osmesa.err")"
fi

# space at frame 4 (emitted 50 ms later: frame 7 at 60 fps), H from 12 to 20
# (its glow from 0.25 s: frame 15)
cat > "$tmp/script" <<'END'
# comments and blank lines are allowed

frame 4 key space
frame 12 key h
frame 20 key h
END
mkdir "$tmp/png"
run "$keys" --frames 24 --png-dir "$tmp/png" --script "$tmp/script" --audio "wav:$tmp/v.wav" \
    > "$tmp/summary.json" || fail "the scripted run failed"
grep -q '"frames": 24, "requests": 3, "posted": 2' "$tmp/summary.json" ||
    fail "unexpected summary: $(cat "$tmp/summary.json")"
[ "$(ls "$tmp/png" | wc -l)" -eq 24 ] || fail "expected 24 frames: $(ls "$tmp/png")"
for k in 0000 0023; do [ -f "$tmp/png/frame_$k.png" ] || fail "no frame_$k.png"; done
$png mean "$tmp/png"/*.png > "$tmp/means" || fail "an invalid PNG: $(tail -1 "$tmp/means")"
m() { awk -v f="frame_$1.png" 'index($1, f) { print $2 }' "$tmp/means"; }
before=$(m 0003)
brighter "$before" "$(m 0008)" || fail "frame 8 ($(m 0008)) is not brighter than frame 3 ($before)"
for k in 0015 0016 0018 0019; do
    brighter "$before" "$(m $k)" || fail "no glow at frame $k while held ($(m $k) against $before)"
done
# 24 frames at 60 fps, 48 kHz, stereo
silent_until "$tmp/v.wav" 0.11 38400 || fail "the WAV is silent after space, or not before"

# F1 shows the overlay (when this fulgur has its font) over the top left
printf 'frame 2 key f1\n' > "$tmp/f1"
mkdir "$tmp/f1png"
"$fulgur" view "$keys" --gl egl --size 640x360 --frames 4 --png-dir "$tmp/f1png" \
    --script "$tmp/f1" > /dev/null 2> "$tmp/f1.err" || fail "the overlay run failed: $(cat "$tmp/f1.err")"
if grep -q "no overlay" "$tmp/f1.err"; then
    echo "(no overlay in this build: $(cat "$tmp/f1.err"))"
else
    a=$($png region "$tmp/f1png/frame_0001.png" 0 0 320 60)
    b=$($png region "$tmp/f1png/frame_0003.png" 0 0 320 60)
    awk -v a="$a" -v b="$b" 'BEGIN { exit !(b > a + 8) }' ||
        fail "F1: the top left is not brighter with the overlay ($b against $a)"
fi

# a positive charge above a negative one: their markers where they were
# clicked (160x90: x 80, y 27 and 63), then space: a leader between them
printf 'frame 1 click 0.5 0.3 left\nframe 2 click 0.5 0.7 right\nframe 3 key space\n' \
    > "$tmp/charges"
mkdir "$tmp/charges.png"
run "$keys" --frames 12 --script "$tmp/charges" --png-dir "$tmp/charges.png" \
    > "$tmp/charges.json" || fail "the charges run failed"
grep -q '"posted": 1' "$tmp/charges.json" || fail "no discharge between the charges: $(cat "$tmp/charges.json")"
for marker in "red 80 27" "blue 80 63"; do
    set -- $marker
    got=$($png marker "$tmp/charges.png/frame_0002.png" "$1")
    echo "$got" | awk -v x="$2" -v y="$3" '{ exit !($1 >= 20 && ($2 - x)^2 < 1 && ($3 - y)^2 < 1) }' ||
        fail "the $1 marker is not where it was clicked ($2, $3): $got (count, centroid)"
done
[ "$($png marker "$tmp/charges.png/frame_0000.png" red | cut -d' ' -f1)" -eq 0 ] ||
    fail "a marker before any click"

# errors: a clear message, the usage exit code or 1, never a crash
"$fulgur" view "$keys" --gl bogus 2> "$tmp/err"
[ $? -eq 2 ] || fail "--gl bogus: expected exit 2"
grep -q 'use egl, osmesa or window' "$tmp/err" || fail "--gl bogus: $(cat "$tmp/err")"
env -u DISPLAY -u WAYLAND_DISPLAY "$fulgur" view "$keys" --gl window --frames 2 2> "$tmp/err"
rc=$?
[ $rc -eq 1 ] || fail "--gl window without a display: exit $rc, expected 1: $(cat "$tmp/err")"
grep -q '^fulgur view: --gl window: ' "$tmp/err" || fail "--gl window: $(cat "$tmp/err")"
echo 'frame x key space' > "$tmp/bad"
run "$keys" --frames 2 --script "$tmp/bad" 2> "$tmp/err"
[ $? -eq 2 ] || fail "a bad script: expected exit 2"
grep -q "bad:1: expected" "$tmp/err" || fail "a bad script: $(cat "$tmp/err")"
echo "the timed discharge, the scripted frames, the glow, the sound, the overlay, the markers" \
     "and the errors are as expected"
