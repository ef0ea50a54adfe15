#!/bin/sh
# usage: whole_breakdown.sh FULGUR BENCH_WHOLE [SEGMENTS...]
# Where one `fulgur render` process spends its work, phase by phase, for
# explicit-tree scenes of SEGMENTS segments (default 9438 and 100000;
# bench_whole --scene writes them): instructions counted by callgrind
# (the same on a loaded machine as on an idle one), inclusive of what each
# phase calls. Phases: start-up (the dynamic loader and everything before
# main), parse (read, cJSON, checks: scene_load_with), engine creation,
# post, render (fg_engine_render), the sink (interleave, peak, WAV writes:
# write_block), and the rest of main (close, rename, free). Writes
# whole_breakdown.csv into FULGUR_RESULTS (default bench/results).
set -eu
fulgur=$1
bench_whole=$2
shift 2
[ $# -gt 0 ] || set -- 9438 100000
command -v valgrind >/dev/null || { echo "whole_breakdown: valgrind is not installed"; exit 1; }
out=${FULGUR_RESULTS:-bench/results}/whole_breakdown.csv
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The inclusive count of function $2 in annotation $1 (0 when absent).
count() {
    awk -v f=":$2 " 'index($0, f) { gsub(",", "", $1); print $1; found = 1; exit }
                     END { if (!found) print 0 }' "$1"
}
{
    echo "# callgrind instructions (millions), inclusive; $(uname -m); fulgur render of a synth_tree scene"
    echo "segments,total,startup,parse,engine_create,post,render,sink,rest"
} > "$out"
for n in "$@"; do
    "$bench_whole" --scene "$n" "$tmp/scene.json"
    valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" \
        "$fulgur" render "$tmp/scene.json" -o "$tmp/out.wav" >/dev/null 2>"$tmp/vg.log"
    callgrind_annotate --inclusive=yes --threshold=100 "$tmp/cg.out" > "$tmp/annotated" 2>/dev/null
    total=$(awk '/PROGRAM TOTALS/ { gsub(",", "", $1); print $1; exit }' "$tmp/annotated")
    main=$(count "$tmp/annotated" main)
    parse=$(count "$tmp/annotated" scene_load_with)
    create=$(count "$tmp/annotated" fg_engine_create)
    post=$(count "$tmp/annotated" fg_engine_post)
    render=$(count "$tmp/annotated" fg_engine_render)
    sink=$(count "$tmp/annotated" write_block)
    awk -v n="$n" -v t="$total" -v m="$main" -v p="$parse" -v c="$create" -v q="$post" \
        -v r="$render" -v s="$sink" 'BEGIN {
        M = 1e6
        printf "%d,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f\n", n, t / M, (t - m) / M, p / M,
               c / M, q / M, r / M, s / M, (m - p - c - q - r - s) / M }' >> "$out"
    tail -1 "$out"
done
echo "wrote $out"
