#!/bin/sh
# usage: cli_render_in_cloud.sh FULGUR TESTS_DIR
# The lightning generator's "in_cloud" through `fulgur render`: 0 renders
# what a scene without the key renders, byte for byte; 10 km of in-cloud
# channel make the thunder last >= 10 s longer (in_cloud_check.py).
set -u
fulgur=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 "$dir/in_cloud_check.py" "$fulgur" "$dir/scenes/in_cloud_3km.json" "$tmp"
