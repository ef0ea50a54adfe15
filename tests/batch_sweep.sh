#!/bin/sh
# usage: batch_sweep.sh FULGUR SOURCE_DIR
# examples/sweep/thunder_sweep.tsv (50 rows) through GNU parallel
# (render_sweep.sh, 2 at once), checked against single renders:
#  - every WAV byte-identical to fulgur render of its row alone;
#  - the manifest: 50 lines in the sweep's order, each the single render's
#    line (scene, set, seed, frames, duration, peak, calibration) but for
#    the output path; nearer bolts are louder for every seed;
#  - six rows over --sshlogin on two stand-in nodes (ssh replaced by a
#    script that runs the command locally in the node's home; rsync real)
#    give the same files and manifest lines, and leave nothing on the nodes;
#  - the Slurm array script (sh -n; run here as task 7 would be) gives row
#    7's bytes; a bad row stops the sweep with no manifest.
set -u
fulgur=$(realpath "$1")
cd "$2" || exit 1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }
sweep=examples/sweep/thunder_sweep.tsv
rows=$(( $(wc -l < "$sweep") - 1 ))
[ "$rows" -eq 50 ] || bad "$sweep: 50 rows expected, $rows"
export FULGUR="$fulgur"

sh examples/sweep/render_sweep.sh "$sweep" "$tmp/par" -j2 || bad "render_sweep.sh failed"
[ ! -e "$tmp/par/rows" ] || bad "rows/ left after the merge"
[ "$(wc -l < "$tmp/par/manifest.jsonl")" -eq 50 ] || bad "manifest: 50 lines expected"

tab=$(printf '\t')
i=0
tail -n +2 "$sweep" | while IFS=$tab read -r name scene seed distance humidity; do
    i=$((i + 1))
    "$fulgur" render "$scene" --quiet --set "seed=$seed" \
        --set "discharges[0].offset[1]=$distance" --set "humidity=$humidity" \
        -o "$tmp/one.wav" --manifest "$tmp/one.jsonl" || { echo "FAIL: single $name"; continue; }
    cmp -s "$tmp/one.wav" "$tmp/par/$name.wav" || echo "FAIL: $name.wav differs from its single render"
    want=$(sed "s|\"output\":\"[^\"]*\"|\"output\":\"$tmp/par/$name.wav\"|" "$tmp/one.jsonl")
    got=$(sed -n "${i}p" "$tmp/par/manifest.jsonl")
    [ "$got" = "$want" ] || echo "FAIL: manifest line $i: $got, single: $want"
done > "$tmp/rows.log"
[ ! -s "$tmp/rows.log" ] || { cat "$tmp/rows.log"; fail=1; }
grep -q '"set":\["seed=3","discharges\[0\].offset\[1\]=500","humidity=90"\],' \
    "$tmp/par/manifest.jsonl" || bad "the manifest does not carry the row's settings"
grep -q '"gain":1,"pa_per_unit":1}$' "$tmp/par/manifest.jsonl" || bad "no calibration"

# for every seed, the bolt at 500 m peaks above the bolt at 5000 m
awk -F'[:,]' '{
    for (k = 1; k < NF; k++) {
        if ($k == "\"seed\"") seed = $(k + 1)
        if ($k == "\"peak\"") peak = $(k + 1)
        if ($k ~ /offset/) { split($k, d, "="); dist = d[2] + 0 }
    }
    if (dist == 500) near[seed] = peak
    if (dist == 5000) far[seed] = peak
} END {
    n = 0
    for (s in near) { n++; if (!(near[s] > far[s])) { print "seed " s ": " near[s] " <= " far[s]; bad = 1 } }
    exit bad || n != 5
}' "$tmp/par/manifest.jsonl" || bad "peaks do not fall from 500 m to 5000 m"

# many machines: --sshlogin over two "nodes" through a stand-in for ssh
# that runs each command here, in the node's own home ($tmp/nodes/NODE),
# with the login environment sshd gives (HOME, SHELL: GNU parallel's
# remote worker runs each job with $SHELL, unset where CI runs),
# with the options docs/batch.md gives: the row script, the scene sent, the
# files and manifest lines returned (rsync), the nodes' copies removed
mkdir -p "$tmp/work/examples/sweep" "$tmp/bin"
cp examples/sweep/*.sh examples/sweep/thunder.json "$tmp/work/examples/sweep/"
head -7 "$sweep" > "$tmp/work/six.tsv"
ln -s "$fulgur" "$tmp/bin/fulgur"
cat > "$tmp/ssh" <<'SSH'
#!/bin/sh
while [ $# -gt 0 ]; do
    case $1 in
        -o|-p|-l|-i|-S|-O|-F) shift 2 ;;
        -*) shift ;;
        *) break ;;
    esac
done
node=$1
shift
[ "${1:-}" = "--" ] && shift
echo "$node" >> "$NODES/calls"
mkdir -p "$NODES/$node" && cd "$NODES/$node" && HOME=$NODES/$node SHELL=/bin/sh exec sh -c "$*"
SSH
mkdir "$tmp/nodes"
(cd "$tmp/work" && env -u FULGUR NODES="$tmp/nodes" PATH="$tmp/bin:$PATH" \
    sh examples/sweep/render_sweep.sh six.tsv out --ssh "sh $tmp/ssh" \
    --sshlogin 1/node1,1/node2 --basefile examples/sweep/render_row.sh \
    --transferfile {scene} --return out/{name}.wav --return out/rows/{name}.jsonl --cleanup) \
    > "$tmp/ssh.log" 2>&1 || bad "the sweep over --sshlogin: $(cat "$tmp/ssh.log")"
for node in node1 node2; do
    grep -qx "$node" "$tmp/nodes/calls" || bad "--sshlogin: nothing ran on $node"
    [ -z "$(find "$tmp/nodes/$node" -type f)" ] ||
        bad "--cleanup left files on $node: $(find "$tmp/nodes/$node" -type f)"
done
tail -n +2 "$tmp/work/six.tsv" | cut -f1 | while IFS= read -r name; do
    cmp -s "$tmp/work/out/$name.wav" "$tmp/par/$name.wav" ||
        echo "FAIL: --sshlogin: $name.wav differs from the local sweep's"
done > "$tmp/ssh_rows.log"
[ ! -s "$tmp/ssh_rows.log" ] || { cat "$tmp/ssh_rows.log"; fail=1; }
sed "s|\"output\":\"$tmp/par/|\"output\":\"out/|" "$tmp/par/manifest.jsonl" | head -6 |
    cmp -s - "$tmp/work/out/manifest.jsonl" || bad "--sshlogin: the manifest differs"

# the Slurm array script, as task 7 runs it
sh -n examples/sweep/slurm_array.sh || bad "slurm_array.sh: syntax"
SLURM_ARRAY_TASK_ID=7 SLURM_SUBMIT_DIR=$(pwd) sh examples/sweep/slurm_array.sh "$sweep" "$tmp/slurm" ||
    bad "slurm_array.sh as task 7"
name7=$(sed -n 8p "$sweep" | cut -f1)
cmp -s "$tmp/slurm/$name7.wav" "$tmp/par/$name7.wav" || bad "task 7: $name7.wav differs"
sed -n 7p "$tmp/par/manifest.jsonl" | sed "s|$tmp/par/|$tmp/slurm/|" |
    cmp -s - "$tmp/slurm/rows/$name7.jsonl" || bad "task 7: its manifest line differs"
SLURM_ARRAY_TASK_ID=51 sh examples/sweep/slurm_array.sh "$sweep" "$tmp/slurm" 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "has no row 51" "$tmp/err" || bad "task 51: $(cat "$tmp/err")"

# a bad row: the sweep stops, no manifest
{ head -3 "$sweep"; printf 'wet\texamples/sweep/thunder.json\t1\t800\t150\n'; } > "$tmp/bad.tsv"
sh examples/sweep/render_sweep.sh "$tmp/bad.tsv" "$tmp/bad" -j2 2>"$tmp/err" &&
    bad "a sweep with humidity 150 succeeded"
grep -q "humidity" "$tmp/err" || bad "the bad row's message: $(cat "$tmp/err")"
[ ! -e "$tmp/bad/manifest.jsonl" ] || bad "a failed sweep wrote a manifest"
[ ! -e "$tmp/bad/wet.wav" ] || bad "the bad row wrote a file"
echo "sweep checks done ($rows rows)"
exit $fail
