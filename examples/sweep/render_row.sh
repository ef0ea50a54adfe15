#!/bin/sh
# usage: render_row.sh OUT_DIR NAME SCENE SEED DISTANCE_M HUMIDITY
#
# One row of a sweep file (render_sweep.sh, slurm_array.sh): SCENE with
# seed SEED, its first discharge's ground point DISTANCE_M ahead of the
# listener (discharges[0].offset[1]) and the air's HUMIDITY (%), into
# OUT_DIR/NAME.wav, its manifest line (fulgur render --manifest) into
# OUT_DIR/rows/NAME.jsonl. FULGUR names the fulgur program (default:
# fulgur on PATH). Exit: fulgur render's.
set -eu
if [ $# -ne 6 ]; then
    echo "usage: $0 OUT_DIR NAME SCENE SEED DISTANCE_M HUMIDITY" >&2
    exit 2
fi
mkdir -p "$1/rows"
exec "${FULGUR:-fulgur}" render "$3" --quiet \
    --set "seed=$4" --set "discharges[0].offset[1]=$5" --set "humidity=$6" \
    -o "$1/$2.wav" --manifest "$1/rows/$2.jsonl"
