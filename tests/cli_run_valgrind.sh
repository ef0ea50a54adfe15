#!/bin/sh
# usage: cli_run_valgrind.sh FULGUR SCENE SANITIZERS
# fulgur run stopped at 0.5 s, with the bolt still sounding, in every driver: valgrind finds no leak and no error. Skipped (77) without
# valgrind or in a sanitizer build, which valgrind cannot run.
set -u
fulgur=$1
scene=$2
if [ -n "$3" ]; then
    echo "skipped: built with -fsanitize=$3, which valgrind cannot run"
    exit 77
fi
command -v valgrind >/dev/null || { echo "skipped: valgrind is not installed"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for audio in null "wav:$tmp/v.wav" raw:-; do
    valgrind -q --leak-check=full --errors-for-leak-kinds=all --error-exitcode=1 \
        --suppressions="$(dirname "$0")/valgrind.supp" \
        "$fulgur" run "$scene" --seconds 0.5 --audio "$audio" --report "$tmp/r.json" >/dev/null ||
        { echo "valgrind failed with --audio $audio"; exit 1; }
    # the bolt (at 3 km, heard from 8.7 s) is still sounding at the end. In
    # lock-step that is certain; the paced null device runs on the wall
    # clock, and under valgrind on a loaded machine the sim thread may not
    # have generated and posted the bolt within the 0.5 s: there the count
    # only has to balance.
    posted=$(sed -n 's/.*"posted":[[:space:]]*\([0-9]*\).*/\1/p' "$tmp/r.json")
    rendered=$(sed -n 's/.*"rendered":[[:space:]]*\([0-9]*\).*/\1/p' "$tmp/r.json")
    [ -n "$posted" ] && [ -n "$rendered" ] || { echo "no counts in the report"; exit 1; }
    if [ "$audio" = null ]; then
        [ "$posted" -ge "$rendered" ] ||
            { echo "more voices rendered than posted"; cat "$tmp/r.json"; exit 1; }
    else
        [ "$posted" -gt "$rendered" ] ||
            { echo "expected voices still sounding at the end"; cat "$tmp/r.json"; exit 1; }
    fi
done
echo "no leak or error in the null, wav and raw drivers"
