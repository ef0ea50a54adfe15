#!/bin/sh
# usage: cli_render_batch.sh FULGUR EXAMPLES_DIR
# fulgur render with several scenes, -o a directory or a pattern, --set,
# --manifest, --quiet and the progress line:
#  - every file of a batch is byte-identical to the scene's single render;
#  - --set gives the bytes of the edited file; a bad --set names the path;
#  - a bad scene, two scenes on one file, or several scenes on one -o file
#    fail before anything is written (exit 2, no file);
#  - the manifest has one line per file; with "-" it is stdout;
#  - on a terminal (script(1)'s pty) work over 2 s shows the progress line,
#    and erases it; not on a terminal, or with --quiet, nothing.
set -u
fulgur=$1
ex=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }

a=$ex/explicit_tree.json
b=$ex/lightning_3km.json
"$fulgur" render "$a" -o "$tmp/a.wav" >/dev/null || bad "single render of $a"
"$fulgur" render "$b" -o "$tmp/b.wav" >"$tmp/b.out" || bad "single render of $b"

# a directory (made when it ends in /), then a pattern
"$fulgur" render "$a" "$b" -o "$tmp/dir/" --manifest "$tmp/m.jsonl" >"$tmp/out" 2>"$tmp/err" ||
    bad "batch into a directory: $(cat "$tmp/err")"
cmp -s "$tmp/dir/explicit_tree.wav" "$tmp/a.wav" || bad "dir/explicit_tree.wav differs"
cmp -s "$tmp/dir/lightning_3km.wav" "$tmp/b.wav" || bad "dir/lightning_3km.wav differs"
[ "$(grep -c 'late events' "$tmp/out")" -eq 2 ] || bad "two summary lines expected"
# (the examples are in pascals and clip: the level warning is the one line allowed)
! grep -qv 'a player clips it' "$tmp/err" || bad "stderr not empty off a terminal: $(cat "$tmp/err")"
[ "$(wc -l < "$tmp/m.jsonl")" -eq 2 ] || bad "manifest: two lines expected"
grep -q '"output":"'"$tmp"'/dir/lightning_3km.wav","seed":3,' "$tmp/m.jsonl" ||
    bad "manifest line: $(cat "$tmp/m.jsonl")"
"$fulgur" render "$b" "$a" -o "$tmp/{index}-{name}.wav" --manifest - --quiet >"$tmp/out" \
    2>"$tmp/err" || bad "batch with a pattern"
cmp -s "$tmp/1-lightning_3km.wav" "$tmp/b.wav" || bad "1-lightning_3km.wav differs"
cmp -s "$tmp/2-explicit_tree.wav" "$tmp/a.wav" || bad "2-explicit_tree.wav differs"
[ "$(wc -l < "$tmp/out")" -eq 2 ] && [ "$(cut -c1-9 "$tmp/out" | sort -u)" = '{"scene":' ] ||
    bad "--manifest -: two JSON lines on stdout expected, got $(cat "$tmp/out")"
[ ! -s "$tmp/err" ] || bad "--quiet: stderr not empty"

# --set against the edited file
sed 's/"seed": 11/"seed": 5/' "$a" > "$tmp/a5.json"
grep -q '"seed": 5' "$tmp/a5.json" || bad "the edit did not apply"
"$fulgur" render "$tmp/a5.json" -o "$tmp/a5.wav" >/dev/null || bad "render of the edit"
"$fulgur" render "$a" -o "$tmp/set.wav" --set seed=5 >/dev/null || bad "--set seed=5"
cmp -s "$tmp/set.wav" "$tmp/a5.wav" || bad "--set seed=5 differs from the edited scene"
cmp -s "$tmp/set.wav" "$tmp/a.wav" && bad "--set seed=5 changed nothing"
"$fulgur" render "$b" -o "$tmp/x.wav" --set 'discharges[3].time=1' 2>"$tmp/err"
[ $? -eq 2 ] || bad "bad --set: exit 2 expected"
grep -qF 'discharges[3]: past the end of discharges (1 elements), setting discharges[3].time' \
    "$tmp/err" || bad "bad --set message: $(cat "$tmp/err")"
"$fulgur" render "$b" -o "$tmp/x.wav" --set 'discharges[0].strokes=99' 2>"$tmp/err"
grep -qF 'discharges[0].strokes: ' "$tmp/err" || bad "the parser's path: $(cat "$tmp/err")"
[ ! -e "$tmp/x.wav" ] || bad "a refused --set wrote a file"

# nothing written when one of the scenes is bad, or two would share a file
mkdir "$tmp/none"
"$fulgur" render "$a" "$ex/../tests/scenes/bad_parent.json" -o "$tmp/none/" 2>"$tmp/err"
[ $? -eq 2 ] || bad "a bad scene in a batch: exit 2 expected"
grep -qF "bad_parent.json: discharges[1].tree.nodes[3]: parent 7 is not before node 3" "$tmp/err" ||
    bad "the bad scene's name and path: $(cat "$tmp/err")"
"$fulgur" render "$a" "$a" -o "$tmp/none/" 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "would both write" "$tmp/err" || bad "two scenes on one file"
"$fulgur" render "$a" "$b" -o "$tmp/none/one.wav" 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "need a directory or a pattern" "$tmp/err" || bad "several on one -o"
[ -z "$(ls -A "$tmp/none")" ] || bad "files left: $(ls -A "$tmp/none")"

# the progress line: enough copies of b for about 6 s of work, from the
# wall time of its single render (its summary line); doubled while the
# pty's run took under 3 s in all (a loaded machine measures b slow)
wall=$(sed -n 's/.* in \([0-9.]*\) s wall.*/\1/p' "$tmp/b.out")
n=$(awk -v w="$wall" 'BEGIN { n = int(6 / (w + 0.001)) + 1; print (n < 2 ? 2 : n > 200 ? 200 : n) }')
mkdir "$tmp/p"
tries=0
while :; do
    set --
    i=0
    while [ $i -lt $n ]; do set -- "$@" "$b"; i=$((i + 1)); done
    cmd="'$fulgur' render $* -o '$tmp/p/{index}.wav'"
    script -qfec "$cmd" /dev/null > "$tmp/tty" 2>&1 || bad "the batch on a pty"
    total=$(sed -n 's/.* in \([0-9.]*\) s wall.*/\1/p' "$tmp/tty" | awk '{ t += $1 } END { print t + 0 }')
    tries=$((tries + 1))
    awk -v t="$total" 'BEGIN { exit !(t < 3) }' && [ $tries -lt 4 ] && [ $n -lt 400 ] || break
    n=$((n * 2))
done
tr '\r' '\n' < "$tmp/tty" | grep -q "^fulgur: \[[0-9]*/$n\] .*lightning_3km.json: [0-9.]* s of sound" ||
    bad "no progress line on a terminal over $n renders ($total s): $(head -c 300 "$tmp/tty")"
[ "$(grep -c 'late events' "$tmp/tty")" -eq "$n" ] || bad "$n summary lines expected on the pty"
tr '\r' '~' < "$tmp/tty" > "$tmp/tty~"
grep -q "~  *~$tmp/p/[0-9]*.wav: " "$tmp/tty~" || bad "no progress line erased before a summary"
grep -q "fulgur: \[[^~]*~$tmp/p/" "$tmp/tty~" && bad "a summary written over a progress line"
cmp -s "$tmp/p/$n.wav" "$tmp/b.wav" || bad "the last of the batch differs"
script -qfec "$cmd --quiet" /dev/null > "$tmp/tty" 2>&1
[ ! -s "$tmp/tty" ] || bad "--quiet on a terminal wrote: $(head -c 200 "$tmp/tty")"
eval "$cmd" > /dev/null 2> "$tmp/err"
! grep -qv 'a player clips it' "$tmp/err" ||
    bad "off a terminal the progress line appeared: $(head -c 200 "$tmp/err")"
echo "batch checks done ($n renders for the progress line)"
exit $fail
