#!/bin/sh
# usage: merge_manifest.sh SWEEP.tsv OUT_DIR
#
# After every row of SWEEP.tsv has rendered into OUT_DIR (render_row.sh):
# OUT_DIR/manifest.jsonl with the rows' manifest lines in the sweep's
# order, then OUT_DIR/rows/ removed. A missing row stops it (exit 1,
# nothing written, rows/ kept).
set -eu
if [ $# -ne 2 ]; then
    echo "usage: $0 SWEEP.tsv OUT_DIR" >&2
    exit 2
fi
tail -n +2 "$1" | cut -f1 | while IFS= read -r name; do
    if [ ! -s "$2/rows/$name.jsonl" ]; then
        echo "$0: row $name has no manifest line ($2/rows/$name.jsonl)" >&2
        exit 1
    fi
    cat "$2/rows/$name.jsonl"
done > "$2/manifest.jsonl.part" || { rm -f "$2/manifest.jsonl.part"; exit 1; }
mv "$2/manifest.jsonl.part" "$2/manifest.jsonl"
rm -r "$2/rows"
