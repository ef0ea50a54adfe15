#!/bin/sh
# usage: cli_render_twice.sh FULGUR SCENE
# Renders SCENE twice: the WAVs must be byte-identical and not silent.
set -u
fulgur=$1
scene=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$fulgur" render "$scene" -o "$tmp/a.wav" || exit 1
"$fulgur" render "$scene" -o "$tmp/b.wav" || exit 1
cmp "$tmp/a.wav" "$tmp/b.wav" || { echo "two renders differ"; exit 1; }
[ -z "$(ls "$tmp" | grep tmp-)" ] || { echo "temporary files left"; exit 1; }
# "... peak P Pa ..." from fulgur analyze: P must be clearly above zero
line=$("$fulgur" analyze "$tmp/a.wav") || exit 1
echo "$line"
echo "$line" | awk '{ for (i = 1; i < NF; i++) if ($i == "peak") exit !($(i + 1) > 1e-3); exit 1 }' ||
    { echo "the render is silent"; exit 1; }
