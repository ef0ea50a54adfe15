#!/bin/sh
# usage: cli_render_levels.sh FULGUR EXAMPLES_DIR
# fulgur render's levels: by default pascals, no calibration written, and a
# warning above 0 dBFS; --gain-db and --normalize scale the samples by what
# they say, write the calibration into the WAV's LIST/INFO comment (read
# here from the RIFF chunks themselves, not through libsndfile) and
# fulgur analyze turns the samples back into the same pascals; both at once,
# or --normalize on a silent scene, fail and leave no file.
set -u
fulgur=$1
examples=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
# field N of "... peak P Pa ...; peak D dBFS, full scale = F Pa ..." from analyze
field() { awk -v want="$2" '{for (i = 1; i < NF; i++) {
    if ($i == "peak" && $(i + 2) == "Pa") pa = $(i + 1);
    if ($i == "peak" && $(i + 2) == "dBFS,") db = $(i + 1);
    if ($i == "scale" && $(i + 1) == "=") fs = $(i + 2) }}
    END {print (want == "pa" ? pa : want == "db" ? db : fs)}' "$1"; }
# the ICMT text of a WAV's LIST/INFO chunk, or nothing
icmt() { python3 - "$1" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read()
pos = 12
while pos + 8 <= len(data):
    cid, size = data[pos:pos + 4], struct.unpack("<I", data[pos + 4:pos + 8])[0]
    body = data[pos + 8:pos + 8 + size]
    if cid == b"LIST" and body[:4] == b"INFO":
        p = 4
        while p + 8 <= len(body):
            sid, ssize = body[p:p + 4], struct.unpack("<I", body[p + 4:p + 8])[0]
            if sid == b"ICMT":
                print(body[p + 8:p + 8 + ssize].rstrip(b"\0").decode())
            p += 8 + ssize + (ssize & 1)
    pos += 8 + size + (size & 1)
PY
}
scene=$examples/spark_balls.json

"$fulgur" render "$scene" -o "$tmp/pa.wav" > "$tmp/pa.out" 2> "$tmp/pa.err" || fail "default render"
cat "$tmp/pa.out" "$tmp/pa.err"
grep -q "full scale = 1 Pa (pascals)" "$tmp/pa.out" || fail "the default is not reported as pascals"
grep -q "warning: .* peaks at +[0-9.]* dBFS" "$tmp/pa.err" || fail "no warning above 0 dBFS"
[ -z "$(icmt "$tmp/pa.wav")" ] || fail "a default render carries a calibration"
"$fulgur" analyze "$tmp/pa.wav" > "$tmp/pa.txt" || fail "analyze"
pa=$(field "$tmp/pa.txt" pa)
db=$(field "$tmp/pa.txt" db)
echo "default: peak $pa Pa, $db dBFS"

# --normalize -1: the peak at -1.0 dBFS, the same pascals, no warning
"$fulgur" render "$scene" -o "$tmp/n.wav" --normalize -1 > "$tmp/n.out" 2> "$tmp/n.err" || fail "--normalize"
cat "$tmp/n.out"
[ ! -s "$tmp/n.err" ] || { cat "$tmp/n.err"; fail "--normalize -1 warned"; }
comment=$(icmt "$tmp/n.wav")
echo "ICMT: $comment"
echo "$comment" | grep -q "^fulgur calibration: full scale = [0-9.e+]* Pa$" || fail "no calibration comment"
"$fulgur" analyze "$tmp/n.wav" > "$tmp/n.txt" || fail "analyze"
cat "$tmp/n.txt"
awk -v a="$(field "$tmp/n.txt" db)" 'BEGIN {exit !(a == -1.0)}' || fail "normalized peak is not -1.0 dBFS"
awk -v a="$(field "$tmp/n.txt" pa)" -v b="$pa" 'BEGIN {exit !(a / b > 0.99999 && a / b < 1.00001)}' ||
    fail "normalized file reads back $(field "$tmp/n.txt" pa) Pa, not $pa"
# the comment's full scale is peak pascals / 10^(-1/20)
awk -v fs="$(field "$tmp/n.txt" fs)" -v p="$pa" 'BEGIN {r = fs / (p / 10 ^ (-1 / 20)); exit !(r > 0.99999 && r < 1.00001)}' ||
    fail "full scale $(field "$tmp/n.txt" fs) Pa is not the peak over -1 dBFS"

# --gain-db -60: 60 dB down, the same pascals
"$fulgur" render "$scene" -o "$tmp/g.wav" --gain-db -60 > /dev/null 2>&1 || fail "--gain-db"
"$fulgur" analyze "$tmp/g.wav" > "$tmp/g.txt" || fail "analyze"
cat "$tmp/g.txt"
awk -v a="$(field "$tmp/g.txt" db)" -v b="$db" 'BEGIN {d = b - a; exit !(d > 59.95 && d < 60.05)}' ||
    fail "--gain-db -60 is not 60 dB down"
awk -v a="$(field "$tmp/g.txt" pa)" -v b="$pa" 'BEGIN {exit !(a / b > 0.99999 && a / b < 1.00001)}' ||
    fail "--gain-db file reads back other pascals"
awk -v fs="$(field "$tmp/g.txt" fs)" 'BEGIN {exit !(fs > 999.99 && fs < 1000.01)}' ||
    fail "--gain-db -60: full scale should be 1000 Pa"

# both at once: exit 2, no file
"$fulgur" render "$scene" -o "$tmp/both.wav" --gain-db -6 --normalize -1 2> "$tmp/both.err"
[ $? -eq 2 ] || fail "--gain-db with --normalize: expected exit 2"
grep -q "give one" "$tmp/both.err" || fail "no message for both"
[ ! -e "$tmp/both.wav" ] || fail "a file was left"
# a silent scene cannot be normalized: exit 1, no file
# (a spark 1 km away: its sound arrives after the file ends, at 0.1 s)
printf '{"sample_rate": 48000, "channels": 2, "duration": 0.1,\n "listener": {"position": [0, 0, 1.7], "forward": [0, 1, 0], "up": [0, 0, 1]},\n "discharges": [{"time": 0, "preset": "spark_balls", "tree": {"nodes": [[0, 1000, 1.7, -1], [0, 1000, 1.71, 0]]}}]}\n' > "$tmp/silent.json"
"$fulgur" render "$tmp/silent.json" -o "$tmp/silent.wav" --normalize -1 2> "$tmp/silent.err"
rc=$?
cat "$tmp/silent.err"
[ $rc -eq 1 ] || fail "--normalize on silence: expected exit 1, got $rc"
grep -q "silent" "$tmp/silent.err" || fail "no message for silence"
[ ! -e "$tmp/silent.wav" ] || fail "a file was left"
echo ok
