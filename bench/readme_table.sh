#!/bin/sh
# usage: readme_table.sh README.md RESULTS_DIR
# Rewrites the README's whole-process table (between its "whole-process
# table" markers) from RESULTS_DIR's startup.csv, whole_process.csv and
# whole_breakdown.csv; the rest of the README is left as it is.
set -eu
readme=$1
results=$2
tmp=$(mktemp)
trap 'rm -f "$tmp" "$tmp.table"' EXIT
begin='<!-- whole-process table: bench/readme_table.sh writes it from bench/results -->'
end='<!-- end of the whole-process table -->'
grep -qF "$begin" "$readme" || { echo "readme_table: no marker in $readme"; exit 1; }
table() {
    echo "| figure (whole \`fulgur\` process, CPU ms, medians) | fulgur | peer | fulgur / peer |"
    echo "|---|---|---|---|"
    awk -F, '!/^#/ && $1 == "help" { printf "| `fulgur --help` | %s ms, %s MiB peak | | |\n", $2, $4 }
             !/^#/ && $1 == "render_1_segment" { printf "| `fulgur render` of 1 segment | %s ms, %s MiB peak | | |\n", $2, $4 }
             !/^#/ && $1 == "bin_true" { printf "| `/bin/true` (the machine'"'"'s floor) | %s ms | | |\n", $2 }' \
        "$results/startup.csv"
    awk -F, '!/^#/ && $1 ~ /^[0-9]+$/ {
        printf "| %s segments, %s s of sound, whole process | %s | %s | %s |\n", $1, $2, $3, $4, $5
        printf "| %s segments, synthesis (post + render) | %s | %s | %s |\n", $1, $6, $7, $8 }' \
        "$results/whole_process.csv"
    echo
    echo "$(sed -n 1p "$results/whole_process.csv" | sed 's/^# //')."
    if [ -f "$results/whole_breakdown.csv" ]; then
        echo
        echo "| segments | instructions (M) | start-up | parse | engine creation | post | render | WAV sink | rest |"
        echo "|---|---|---|---|---|---|---|---|---|"
        awk -F, '!/^#/ && $1 ~ /^[0-9]+$/ { printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
                 $1, $2, $3, $4, $5, $6, $7, $8, $9 }' "$results/whole_breakdown.csv"
    fi
}
table > "$tmp.table"
awk -v b="$begin" -v e="$end" -v t="$tmp.table" '
    $0 == b { print; while ((getline line < t) > 0) print line; skip = 1; next }
    $0 == e { skip = 0 }
    !skip' "$readme" > "$tmp"
cat "$tmp" > "$readme"
