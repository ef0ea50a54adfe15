#!/bin/sh
# usage: cli_render_png.sh FULGUR SCENE
# fulgur render --png twice: the PNG exists, is a PNG with light in it, and
# the two runs give identical bytes; no temporary file is left; the PNG's
# mode follows the umask as the WAV's does (it was 0600 from mkstemp). --size
# is honoured; a --png-time before anything is lit warns; the usage errors.
set -u
fulgur=$1
scene=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$fulgur" render "$scene" -o "$tmp/a.wav" --png "$tmp/a.png" || exit 1
"$fulgur" render "$scene" -o "$tmp/b.wav" --png "$tmp/b.png" || exit 1
[ -s "$tmp/a.png" ] || { echo "no PNG written"; exit 1; }
[ "$(head -c 8 "$tmp/a.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] ||
    { echo "not a PNG"; exit 1; }
[ "$(wc -c < "$tmp/a.png")" -gt 2000 ] || { echo "the PNG is suspiciously small (black?)"; exit 1; }
cmp "$tmp/a.png" "$tmp/b.png" || { echo "two pictures differ"; exit 1; }
[ -z "$(ls "$tmp" | grep tmp-)" ] || { echo "temporary files left"; exit 1; }
for mask in 022 077; do
    (umask $mask && "$fulgur" render "$scene" -o "$tmp/m.wav" --png "$tmp/m.png" >/dev/null) || exit 1
    want=$(printf '%o' $((0666 & ~0$mask)))
    [ "$(stat -c %a "$tmp/m.png")" = "$want" ] && [ "$(stat -c %a "$tmp/m.wav")" = "$want" ] ||
        { echo "umask $mask: PNG mode $(stat -c %a "$tmp/m.png"), WAV $(stat -c %a "$tmp/m.wav"), not $want"; exit 1; }
    rm -f "$tmp/m.png" "$tmp/m.wav"
done
# an unwritable PNG path: exit 1, no file
if "$fulgur" render "$scene" -o "$tmp/c.wav" --png "$tmp/missing/c.png"; then
    echo "an unwritable --png path was accepted"; exit 1
fi
[ ! -e "$tmp/missing" ] || exit 1
# --png-time and --size without --png are usage errors
"$fulgur" render "$scene" -o "$tmp/d.wav" --png-time 1 2>/dev/null
[ $? -eq 2 ] || { echo "--png-time alone should exit 2"; exit 1; }
"$fulgur" render "$scene" -o "$tmp/d.wav" --size 320x200 2>/dev/null
[ $? -eq 2 ] || { echo "--size alone should exit 2"; exit 1; }
"$fulgur" render "$scene" -o "$tmp/d.wav" --png "$tmp/d.png" --size 8x8 2>/dev/null
[ $? -eq 2 ] || { echo "--size 8x8 should exit 2"; exit 1; }
# --size: the PNG's header says 320 x 200 (IHDR's width and height)
"$fulgur" render "$scene" -o "$tmp/e.wav" --png "$tmp/e.png" --size 320x200 > "$tmp/e.out" || exit 1
[ "$(od -An -tx1 -j16 -N8 "$tmp/e.png" | tr -d ' \n')" = "00000140000000c8" ] ||
    { echo "--size 320x200 gave another size"; exit 1; }
grep -q "(320 x 200)" "$tmp/e.out" || { echo "unexpected: $(cat "$tmp/e.out")"; exit 1; }
# before the first leader (at 0.02 s): a warning naming the times, still a picture
"$fulgur" render "$scene" -o "$tmp/f.wav" --png "$tmp/f.png" --png-time 0 2> "$tmp/f.err" > /dev/null ||
    { echo "--png-time 0 failed"; exit 1; }
grep -q "warning: --png-time 0 s is before anything is lit: the first leader starts at 0.02 s" \
    "$tmp/f.err" || { echo "no warning before the first leader: $(cat "$tmp/f.err")"; exit 1; }
[ -s "$tmp/f.png" ] || { echo "no picture with the warning"; exit 1; }
"$fulgur" render "$scene" -o "$tmp/g.wav" --png "$tmp/g.png" 2> "$tmp/g.err" > /dev/null || exit 1
! grep -qv 'a player clips it' "$tmp/g.err" || { echo "a warning at the first return stroke: $(cat "$tmp/g.err")"; exit 1; }
echo "PNG $(wc -c < "$tmp/a.png") bytes, identical over two runs"
