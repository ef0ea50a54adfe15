#!/bin/sh
# usage: cli_render_silence.sh FULGUR REPO
# fulgur render warns when its output would be mostly silence: a render of
# 1 s or more whose sound (samples above 20 uPa, 0 dB SPL) spans less than
# a tenth of it. A spark at 20 s of a 30 s scene sounds for 0.185 s from
# 20.003 s (1 m at 343 m/s): warned, with the span; a spark 3430 m away in
# a 2 s scene arrives after it ends: "silent"; --quiet says nothing; the
# examples, whose sound fills them, are not warned about.
set -u
fulgur=$1
repo=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
spark='"preset": "spark_balls", "tree": {"nodes": [[0, Y, 1.7, -1], [0, Y, 1.72, 0]]}'
printf '{"duration": 30, "discharges": [{"time": 20, %s}]}\n' "$spark" | sed 's/Y/1/g' > "$tmp/late.json"
printf '{"duration": 2, "discharges": [{"time": 0, %s}]}\n' "$spark" | sed 's/Y/3430/g' > "$tmp/far.json"

"$fulgur" render "$tmp/late.json" -o "$tmp/late.wav" >/dev/null 2>"$tmp/err" ||
    { echo "late: render failed: $(cat "$tmp/err")"; fail=1; }
grep -q "warning: $tmp/late.wav is mostly silence: its sound (above 20 uPa, 0 dB SPL) spans 0\.[0-9]* s (20\.00[0-9] to 20\.[0-9]* s) of its 30\.000 s" "$tmp/err" ||
    { echo "late: no mostly-silence warning with its span: $(cat "$tmp/err")"; fail=1; }
"$fulgur" render "$tmp/late.json" -o "$tmp/late.wav" --quiet >/dev/null 2>"$tmp/err"
[ -s "$tmp/err" ] && { echo "late --quiet: $(cat "$tmp/err")"; fail=1; }

"$fulgur" render "$tmp/far.json" -o "$tmp/far.wav" >/dev/null 2>"$tmp/err" ||
    { echo "far: render failed: $(cat "$tmp/err")"; fail=1; }
grep -q "warning: $tmp/far.wav is silent: no sample above 20 uPa (0 dB SPL) in its 2\.000 s" "$tmp/err" ||
    { echo "far: no silence warning: $(cat "$tmp/err")"; fail=1; }

for scene in "$repo"/examples/*.json; do
    "$fulgur" render "$scene" -o "$tmp/e.wav" >/dev/null 2>"$tmp/err"
    grep -q "silen" "$tmp/err" && { echo "$(basename "$scene"): $(cat "$tmp/err")"; fail=1; }
done
[ "$fail" -eq 0 ] && echo "render: mostly silent outputs are warned about"
exit "$fail"
