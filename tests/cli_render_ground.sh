#!/bin/sh
# usage: cli_render_ground.sh FULGUR TESTS_DIR
# A scene with "ground" renders through `fulgur render` (the engine is
# sized for the image's second copy of each segment), and the image's
# delay and level match the geometry (ground_image_check.py).
set -u
fulgur=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$fulgur" render "$dir/scenes/ground_image.json" -o "$tmp/out.wav" || exit 1
python3 "$dir/ground_image_check.py" "$dir/scenes/ground_image.json" "$tmp/out.wav"
