#!/bin/sh
# usage: cli_run_layout.sh FULGUR SCENE
# fulgur run in every layout, in lock-step (--audio wav:): the scene's
# "layout" key (ambisonics order 2) gives 9 channels, within 1 dB of
# render's RMS (run sways the head: not the same samples), two runs
# byte-identical, the report naming the layout; --layout over the key
# (binaural: 2 channels through the HRIRs, not the stereo run's samples;
# ambisonics:3: 16). Refused with exit 2, the option or key named and
# nothing written: ambisonics on a live device (1 or 2 channels), --sofa
# with a layout other than binaural, a SOFA file that is not there.
set -u
fulgur=$1
scene=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
grep -v '^ *"channels":' "$scene" | sed '1s|{|{"layout": {"type": "ambisonics", "order": 2},|' \
    >"$tmp/ambi.json"
channels() { "$fulgur" analyze "$1" | sed -n 's/.*: \([0-9]*\) ch,.*/\1/p'; }
rms_of() { "$fulgur" analyze "$1" | sed -n 's/.*rms \([0-9.e+-]*\) Pa.*/\1/p'; }

"$fulgur" render "$tmp/ambi.json" -o "$tmp/render.wav" --set duration=1 --quiet ||
    { echo "render of the ambisonic scene failed"; fail=1; }
for name in run again; do
    "$fulgur" run "$tmp/ambi.json" --seconds 1 --audio "wav:$tmp/$name.wav" \
        --report "$tmp/$name.json" || { echo "run ($name) of the ambisonic scene failed"; fail=1; }
done
[ "$(channels "$tmp/run.wav")" = 9 ] || { echo "run: $(channels "$tmp/run.wav") channels, want 9"; fail=1; }
cmp -s "$tmp/run.wav" "$tmp/again.wav" || { echo "two lock-step ambisonic runs differ"; fail=1; }
awk -v a="$(rms_of "$tmp/render.wav")" -v b="$(rms_of "$tmp/run.wav")" 'BEGIN {
    db = 20 * log(b / a) / log(10);
    printf "ambisonics:2: run rms %.4g Pa, render %.4g Pa (%+.2f dB)\n", b, a, db;
    exit !(a > 0 && db > -1 && db < 1)}' || { echo "ambisonic run and render disagree"; fail=1; }
grep -A3 '"layout"' "$tmp/run.json" | tr -d ' \t\n' | grep -q '"type":"ambisonics","order":2,"channels":9' ||
    { echo "the report does not name the layout"; fail=1; }

"$fulgur" run "$scene" --seconds 1 --layout binaural --audio "wav:$tmp/bin.wav" \
    --report "$tmp/bin.json" || { echo "run --layout binaural failed"; fail=1; }
"$fulgur" run "$scene" --seconds 1 --layout stereo --audio "wav:$tmp/st.wav" \
    --report "$tmp/st.json" || { echo "run --layout stereo failed"; fail=1; }
[ "$(channels "$tmp/bin.wav")" = 2 ] || { echo "binaural: $(channels "$tmp/bin.wav") channels"; fail=1; }
! cmp -s "$tmp/bin.wav" "$tmp/st.wav" || { echo "binaural run gave the stereo samples"; fail=1; }
"$fulgur" run "$tmp/ambi.json" --seconds 1 --layout ambisonics:3 --audio "wav:$tmp/a3.wav" \
    --report "$tmp/a3.json" || { echo "run --layout ambisonics:3 failed"; fail=1; }
[ "$(channels "$tmp/a3.wav")" = 16 ] || { echo "ambisonics:3: $(channels "$tmp/a3.wav") channels"; fail=1; }

refuse() { # refuse LABEL WORD ARGS...: exit 2, WORD in the message, no WAV
    label=$1 word=$2
    shift 2
    rm -f "$tmp/bad.wav"
    "$fulgur" run "$@" 2>"$tmp/err"
    rc=$?
    if [ "$rc" -ne 2 ] || ! grep -q -- "$word" "$tmp/err" || [ -e "$tmp/bad.wav" ]; then
        echo "$label: exit $rc, $(cat "$tmp/err")"; fail=1
    fi
}
refuse "ambisonics on JACK" "layout" "$tmp/ambi.json" --audio jack
refuse "--sofa with stereo" "--sofa" "$scene" --sofa /usr/share/libmysofa/MIT_KEMAR_normal_pinna.sofa \
    --audio "wav:$tmp/bad.wav"
refuse "a SOFA file not there" "none.sofa" "$scene" --layout binaural --sofa "$tmp/none.sofa" \
    --audio "wav:$tmp/bad.wav"
exit $fail
