#!/bin/sh
#SBATCH --job-name=fulgur-sweep
#SBATCH --cpus-per-task=1
#SBATCH --time=00:15:00
#SBATCH --output=fulgur-sweep-%A_%a.log
# usage (from the repository, fulgur on PATH or FULGUR set):
#   rows=$(( $(wc -l < SWEEP.tsv) - 1 ))
#   job=$(sbatch --parsable --array=1-$rows examples/sweep/slurm_array.sh SWEEP.tsv OUT_DIR)
#   sbatch --dependency=afterok:$job --wrap "sh examples/sweep/merge_manifest.sh SWEEP.tsv OUT_DIR"
#
# A Slurm array job over a sweep file (render_sweep.sh's format): task N
# renders row N (the N-th line after the header) with render_row.sh;
# OUT_DIR must be on a file system that every node sees. The second sbatch
# writes OUT_DIR/manifest.jsonl once every task has succeeded.
set -eu
if [ $# -ne 2 ] || [ -z "${SLURM_ARRAY_TASK_ID:-}" ]; then
    echo "usage: sbatch --array=1-ROWS $0 SWEEP.tsv OUT_DIR" >&2
    exit 2
fi
# Slurm runs a copy of this script: render_row.sh is found from where
# sbatch was called (the repository), or from FULGUR_SWEEP_DIR.
here=${FULGUR_SWEEP_DIR:-${SLURM_SUBMIT_DIR:-.}/examples/sweep}
row=$(awk -v n="$SLURM_ARRAY_TASK_ID" 'NR == n + 1' "$1")
if [ -z "$row" ]; then
    echo "$0: $1 has no row $SLURM_ARRAY_TASK_ID" >&2
    exit 2
fi
tab=$(printf '\t')
IFS=$tab read -r name scene seed distance humidity <<ROW
$row
ROW
exec sh "$here/render_row.sh" "$2" "$name" "$scene" "$seed" "$distance" "$humidity"
