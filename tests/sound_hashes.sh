#!/bin/sh
# usage: sound_hashes.sh FULGUR REPO [--update]
# The sound regression guard: renders every scene in examples/ and
# tests/scenes/sound/ with `fulgur render` (and two of them through
# `fulgur run --audio wav:` in lock-step, at block sizes other than the
# scene's) and compares each WAV's SHA-256 with tests/sound_hashes.txt.
# A refactor or an optimisation that must not change the sound keeps every
# line; a change that means to change the sound regenerates the list with
# --update and says so in its commit.
set -u
fulgur=$1
repo=$2
list=$repo/tests/sound_hashes.txt
update=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for scene in "$repo"/examples/*.json "$repo"/tests/scenes/sound/*.json; do
    name=render:$(basename "$(dirname "$scene")")/$(basename "$scene" .json)
    "$fulgur" render "$scene" -o "$tmp/out.wav" >/dev/null || { echo "$name: render failed"; exit 1; }
    echo "$(sha256sum < "$tmp/out.wav" | cut -c1-64) $name" >> "$tmp/got"
done
for spec in "examples/spark_balls.json 64" "tests/scenes/sound/air_effects.json 512"; do
    set -- $spec
    name=run:$(basename "$(dirname "$1")")/$(basename "$1" .json)@$2
    "$fulgur" run "$repo/$1" --audio "wav:$tmp/out.wav" --block "$2" --report "$tmp/report.json" \
        >/dev/null || { echo "$name: run failed"; exit 1; }
    echo "$(sha256sum < "$tmp/out.wav" | cut -c1-64) $name" >> "$tmp/got"
done

if [ "$update" = "--update" ]; then
    cp "$tmp/got" "$list"
    echo "wrote $list"
    exit 0
fi
diff "$list" "$tmp/got" > "$tmp/diff" && { echo "all $(wc -l < "$list") renders match"; exit 0; }
echo "renders differ from tests/sound_hashes.txt (< stored, > now):"
cat "$tmp/diff"
exit 1
