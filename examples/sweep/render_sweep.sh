#!/bin/sh
# usage: examples/sweep/render_sweep.sh SWEEP.tsv OUT_DIR [GNU parallel options...]
#
# Renders every row of a sweep file through GNU parallel, one fulgur render
# per row (render_row.sh), on this machine (-j N: N at once; default one
# per core) or on many (--sshlogin and the options in docs/batch.md), then
# writes OUT_DIR/manifest.jsonl in the sweep's order (merge_manifest.sh).
# The sweep file is tab-separated with the header line
#   name  scene  seed  distance_m  humidity
# A failed row stops the sweep (exit 1) and leaves no manifest. (-q: the
# words reach render_row.sh as written, spaces in paths included.)
set -eu
if [ $# -lt 2 ]; then
    echo "usage: $0 SWEEP.tsv OUT_DIR [GNU parallel options...]" >&2
    exit 2
fi
here=$(dirname "$0")
sweep=$1
out=$2
shift 2
parallel -q --colsep '\t' --header : --halt now,fail=1 "$@" \
    sh "$here/render_row.sh" "$out" {name} {scene} {seed} {distance_m} {humidity} :::: "$sweep"
sh "$here/merge_manifest.sh" "$sweep" "$out"
