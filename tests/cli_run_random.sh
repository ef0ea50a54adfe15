#!/bin/sh
# usage: cli_run_random.sh FULGUR SCENE
# The scene's "random" discharges (4 Hz over 5 s, seeded): fulgur run posts
# a count inside the Poisson process's 4-sigma band around 20, the same count
# and the same samples twice, and another seed gives other times.
set -u
fulgur=$1
scene=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
posted() { sed -n 's/.*"posted":[[:space:]]*\([0-9]*\).*/\1/p' "$1"; }
scheduled() { sed -n 's/.*"scheduled":[[:space:]]*\([0-9]*\).*/\1/p' "$1"; }
for k in 1 2; do
    "$fulgur" run "$scene" --audio "wav:$tmp/$k.wav" --report "$tmp/$k.json" ||
        { echo "run $k failed"; exit 1; }
done
n=$(posted "$tmp/1.json")
s=$(scheduled "$tmp/1.json")
[ -n "$n" ] && [ "$n" -ge 3 ] && [ "$n" -le 38 ] ||
    { echo "posted $n random discharges, expected 20 +- 4 sigma"; cat "$tmp/1.json"; exit 1; }
[ "$n" = "$s" ] || { echo "posted $n of $s scheduled"; exit 1; }
[ "$n" = "$(posted "$tmp/2.json")" ] || { echo "the count differs between runs"; exit 1; }
cmp -s "$tmp/1.wav" "$tmp/2.wav" || { echo "the samples differ between runs"; exit 1; }
sed 's/"seed": 11/"seed": 12/' "$scene" > "$tmp/other.json"
"$fulgur" run "$tmp/other.json" --audio "wav:$tmp/3.wav" --report "$tmp/3.json" ||
    { echo "run with another seed failed"; exit 1; }
cmp -s "$tmp/1.wav" "$tmp/3.wav" && { echo "another seed gave the same samples"; exit 1; }
# a scene without an end for them is refused, naming the field
sed 's/"duration": 5.5,//; s/"end": 5, //' "$scene" > "$tmp/noend.json"
"$fulgur" run "$tmp/noend.json" --audio null 2> "$tmp/err" && { echo "no end accepted"; exit 1; }
grep -q '^fulgur: random.end: required' "$tmp/err" || { echo "wrong message:"; cat "$tmp/err"; exit 1; }
echo "posted $n of the random discharges, reproducibly"
