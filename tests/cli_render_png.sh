#!/bin/sh
# usage: cli_render_png.sh FULGUR SCENE
# fulgur render --png twice: the PNG exists, is a PNG with light in it, and
# the two runs give identical bytes; no temporary file is left.
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
# an unwritable PNG path: exit 1, no file
if "$fulgur" render "$scene" -o "$tmp/c.wav" --png "$tmp/missing/c.png"; then
    echo "an unwritable --png path was accepted"; exit 1
fi
[ ! -e "$tmp/missing" ] || exit 1
# --png-time without --png is a usage error
"$fulgur" render "$scene" -o "$tmp/d.wav" --png-time 1 2>/dev/null
[ $? -eq 2 ] || { echo "--png-time alone should exit 2"; exit 1; }
echo "PNG $(wc -c < "$tmp/a.png") bytes, identical over two runs"
