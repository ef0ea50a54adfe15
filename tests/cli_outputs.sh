#!/bin/sh
# usage: cli_outputs.sh FULGUR SCENES_DIR GPU(ON|OFF) [FULGUR_LV2_RENDER]
# Output safety (issue 14): an output path that names a device (a node made
# with mknod here, never the system's own), a FIFO, a directory or the
# command's own input is refused with exit 2 and left as it was; a 254-byte
# file name works; the outputs of one command are committed together (a
# --report or --png that cannot be written leaves no WAV); SIGTERM leaves
# no temporary file.
set -u
fulgur=$1
scenes=$2
gpu=$3
lv2render=${4:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
cp "$scenes/run_storm.json" "$tmp/s.json"
cp "$tmp/s.json" "$tmp/s.orig"

# expect_refused WHAT CMD...: exit 2 and a "refusing" message
expect_refused() {
    what=$1
    shift
    "$@" >/dev/null 2>"$tmp/err"
    rc=$?
    if [ "$rc" -ne 2 ] || ! grep -q "refusing" "$tmp/err"; then
        echo "$what: exit $rc, expected 2 with a refusal; stderr: $(cat "$tmp/err")"
        fail=1
    fi
}

if mknod "$tmp/dev" c 1 3 2>/dev/null; then
    expect_refused "render -o a device" "$fulgur" render "$tmp/s.json" -o "$tmp/dev"
    expect_refused "run --audio wav:a device" "$fulgur" run "$tmp/s.json" --seconds 0.1 \
        --audio "wav:$tmp/dev" --report "$tmp/r.json"
    [ -c "$tmp/dev" ] || { echo "the device node was replaced"; fail=1; }
else
    echo "(not root: the device-node case is skipped)"
fi
mkfifo "$tmp/fifo"
expect_refused "render -o a FIFO" "$fulgur" render "$tmp/s.json" -o "$tmp/fifo"
[ -p "$tmp/fifo" ] || { echo "the FIFO was replaced"; fail=1; }
# -o naming a directory writes SCENE's NAME.wav into it (docs/batch.md);
# the directory itself is never replaced
mkdir "$tmp/dir"
"$fulgur" render "$tmp/s.json" -o "$tmp/dir" >/dev/null 2>&1 ||
    { echo "render -o a directory failed"; fail=1; }
[ -d "$tmp/dir" ] && [ -s "$tmp/dir/s.wav" ] ||
    { echo "render -o a directory: not the directory with s.wav in it"; fail=1; }
mkdir "$tmp/dir/s.wav.d" && rm -f "$tmp/dir/s.wav" && mv "$tmp/dir/s.wav.d" "$tmp/dir/s.wav"
expect_refused "render -o a directory whose NAME.wav is a directory" "$fulgur" render \
    "$tmp/s.json" -o "$tmp/dir"
[ -d "$tmp/dir/s.wav" ] || { echo "the directory s.wav was replaced"; fail=1; }

expect_refused "render s.json -o s.json" "$fulgur" render "$tmp/s.json" -o "$tmp/s.json"
ln -s s.json "$tmp/link.json"
expect_refused "render through a link to the input" "$fulgur" render "$tmp/s.json" \
    -o "$tmp/link.json"
expect_refused "run --report s.json" "$fulgur" run "$tmp/s.json" --seconds 0.1 \
    --audio "wav:$tmp/run.wav" --report "$tmp/s.json"
cmp -s "$tmp/s.json" "$tmp/s.orig" || { echo "the input scene was changed"; fail=1; }
[ ! -e "$tmp/run.wav" ] || { echo "a refused run left its WAV"; fail=1; }

"$fulgur" run "$tmp/s.json" --seconds 0.1 --audio "wav:$tmp/a.wav" --report "$tmp/r.json" \
    >/dev/null || { echo "run into a.wav failed"; fail=1; }
cp "$tmp/a.wav" "$tmp/a.orig"
expect_refused "analyze a.wav --waveform a.wav" "$fulgur" analyze "$tmp/a.wav" \
    --waveform "$tmp/a.wav"
cmp -s "$tmp/a.wav" "$tmp/a.orig" || { echo "analyze changed its input"; fail=1; }
if [ -n "$lv2render" ]; then
    printf 'MThd' > "$tmp/m.mid"
    expect_refused "fulgur-lv2-render m.mid -o m.mid" "$lv2render" "$tmp/m.mid" -o "$tmp/m.mid"
    [ "$(cat "$tmp/m.mid")" = MThd ] || { echo "fulgur-lv2-render changed its input"; fail=1; }
fi

# 254 bytes: the longest name that leaves room for nothing after it
long=$(printf '%0250d' 0).wav
"$fulgur" run "$tmp/s.json" --seconds 0.1 --audio "wav:$tmp/$long" --report "$tmp/r.json" \
    >/dev/null || { echo "a 254-byte output name failed"; fail=1; }
[ -s "$tmp/$long" ] || { echo "no WAV under the 254-byte name"; fail=1; }
rm -f "$tmp/$long"

# the outputs of one command together: a report that cannot be written
mkdir "$tmp/together"
"$fulgur" run "$tmp/s.json" --seconds 0.1 --audio "wav:$tmp/together/o.wav" \
    --report "$tmp/together/missing/r.json" >/dev/null 2>&1 &&
    { echo "run --report into a missing directory succeeded"; fail=1; }
if [ "$gpu" = ON ]; then
    "$fulgur" render "$tmp/s.json" -o "$tmp/together/o.wav" \
        --png "$tmp/together/missing/p.png" >/dev/null 2>&1 &&
        { echo "render --png into a missing directory succeeded"; fail=1; }
fi
[ -z "$(ls -A "$tmp/together")" ] ||
    { echo "a failed command left: $(ls -A "$tmp/together")"; fail=1; }

# SIGTERM mid-run: no temporary, no WAV
mkdir "$tmp/term"
"$fulgur" run "$tmp/s.json" --seconds 3000 --audio "wav:$tmp/term/o.wav" \
    --report "$tmp/term/r.json" >/dev/null 2>&1 &
pid=$!
for _ in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20; do
    [ -n "$(ls -A "$tmp/term")" ] && break
    sleep 0.1
done
[ -n "$(ls -A "$tmp/term")" ] || { echo "the run made no temporary to test"; fail=1; }
kill -TERM "$pid"
wait "$pid"
rc=$?
[ "$rc" -eq 143 ] || { echo "SIGTERM: exit $rc, expected 143"; fail=1; }
[ -z "$(ls -A "$tmp/term")" ] || { echo "SIGTERM left: $(ls -A "$tmp/term")"; fail=1; }

[ "$fail" -eq 0 ] && echo "output safety: all cases hold"
exit "$fail"
