#!/bin/sh
# usage: cli_run_raw.sh FULGUR SCENE
# fulgur run in raw mode writes exactly the samples of the WAV mode: the raw
# bytes are the WAV's data chunk (its last bytes). Lock-step runs repeat,
# and the sound is not silence.
set -u
fulgur=$1
scene=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$fulgur" run "$scene" --seconds 2 --audio raw:- 2>"$tmp/raw.json" >"$tmp/a.raw" || exit 1
"$fulgur" run "$scene" --seconds 2 --audio "wav:$tmp/a.wav" >"$tmp/wav.json" || exit 1
"$fulgur" run "$scene" --seconds 2 --audio "wav:$tmp/b.wav" >/dev/null || exit 1
size=$(wc -c <"$tmp/a.raw")
# 2 s, 48 kHz, 2 channels, 4 bytes
[ "$size" -eq 768000 ] || { echo "raw output is $size bytes, not 768000"; exit 1; }
tail -c "$size" "$tmp/a.wav" | cmp - "$tmp/a.raw" || { echo "raw differs from the WAV's samples"; exit 1; }
cmp "$tmp/a.wav" "$tmp/b.wav" || { echo "two lock-step runs differ"; exit 1; }
grep -q '"audio":[[:space:]]*"raw"' "$tmp/raw.json" || { echo "no report on stderr in raw mode"; exit 1; }
line=$("$fulgur" analyze "$tmp/a.wav") || exit 1
echo "$line"
echo "$line" | awk '{ for (i = 1; i < NF; i++) if ($i == "peak") exit !($(i + 1) > 1e-3); exit 1 }' ||
    { echo "the run is silent"; exit 1; }
# a reader that stops early (a player that failed): exit 1 with the message,
# not a silent death by SIGPIPE (141)
rc=$( { "$fulgur" run "$scene" --audio raw:- --seconds 4 2> "$tmp/pipe.err"; echo $? > "$tmp/pipe.rc"; } | head -c 1000 > /dev/null; cat "$tmp/pipe.rc")
cat "$tmp/pipe.err"
[ "$rc" = 1 ] || { echo "a closed pipe gave exit $rc, expected 1"; exit 1; }
grep -q "closed the pipe" "$tmp/pipe.err" || { echo "no message for the closed pipe"; exit 1; }
