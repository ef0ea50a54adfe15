#!/bin/sh
# usage: cli_bad_scene.sh FULGUR SCENES_DIR
# Renders every SCENES_DIR/bad_*.json: each must exit 2, print its .err line
# (the JSON path and what is wrong) on stderr, and leave no file behind;
# a file already at the output path stays as it was.
set -u
fulgur=$1
dir=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
count=0
for scene in "$dir"/bad_*.json; do
    name=$(basename "$scene" .json)
    expected=$(cat "$dir/$name.err")
    mkdir "$tmp/$name"
    "$fulgur" render "$scene" -o "$tmp/$name/out.wav" 2>"$tmp/$name.stderr"
    rc=$?
    count=$((count + 1))
    if [ "$rc" -ne 2 ]; then
        echo "$name: exit $rc, expected 2"; fail=1
    fi
    if ! grep -qF "$expected" "$tmp/$name.stderr"; then
        echo "$name: stderr lacks: $expected"; echo "  got: $(cat "$tmp/$name.stderr")"; fail=1
    fi
    if [ -n "$(ls -A "$tmp/$name")" ]; then
        echo "$name: left files behind: $(ls -A "$tmp/$name")"; fail=1
    fi
done
[ "$count" -ge 5 ] || { echo "only $count bad scenes found in $dir"; fail=1; }

# an existing output survives a failed render untouched
echo old >"$tmp/keep.wav"
"$fulgur" render "$dir/bad_parent.json" -o "$tmp/keep.wav" 2>/dev/null
[ "$(cat "$tmp/keep.wav")" = old ] || { echo "a failed render changed an existing file"; fail=1; }

# usage errors exit 2 too
"$fulgur" render 2>/dev/null
[ $? -eq 2 ] || { echo "render without arguments: expected exit 2"; fail=1; }
"$fulgur" render "$dir/does_not_exist.json" -o "$tmp/x.wav" 2>/dev/null
[ $? -eq 2 ] || { echo "missing scene file: expected exit 2"; fail=1; }
[ ! -e "$tmp/x.wav" ] || { echo "missing scene file: output written"; fail=1; }
exit $fail
