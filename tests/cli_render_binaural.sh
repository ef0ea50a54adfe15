#!/bin/sh
# usage: cli_render_binaural.sh FULGUR SCENE
# fulgur render --layout binaural: two channels through the default MIT
# KEMAR SOFA set, ending in silence (the filters rung out: the last
# envelope row below 1e-6 of the peak), the same with --sofa naming it; a
# missing file, a file
# that is not SOFA and --sofa without --layout binaural exit 2 with a
# message naming the file or option, and write nothing.
set -u
fulgur=$1
scene=$2
kemar=/usr/share/libmysofa/MIT_KEMAR_normal_pinna.sofa
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$fulgur" render "$scene" --quiet --layout binaural -o "$tmp/b.wav" || exit 1
line=$("$fulgur" analyze "$tmp/b.wav") || exit 1
echo "$line"
echo "$line" | grep -q ": 2 ch," || { echo "binaural: not 2 channels"; exit 1; }
"$fulgur" analyze "$tmp/b.wav" --waveform "$tmp/w.dat" >/dev/null || exit 1
awk '!/^#/ { for (i = 2; i <= NF; i++) { v = $i < 0 ? -$i : $i; if (v > peak) peak = v; last[i] = v } n = NF }
     END { end = 0; for (i = 2; i <= n; i++) if (last[i] > end) end = last[i];
           printf "binaural: the last envelope row at %g of the peak\n", end / peak;
           exit !(peak > 0 && end <= 1e-6 * peak) }' "$tmp/w.dat" ||
    { echo "binaural: the render ends while its filters still sound"; exit 1; }
"$fulgur" render "$scene" --quiet --layout binaural --sofa "$kemar" -o "$tmp/k.wav" || exit 1
cmp -s "$tmp/b.wav" "$tmp/k.wav" || { echo "--sofa $kemar differs from the default"; exit 1; }
printf 'not a SOFA file\n' >"$tmp/text.sofa"
refuse() { # refuse WHAT NAMED ARGS...: exit 2, NAMED in the message, no WAV
    what=$1 named=$2
    shift 2
    "$fulgur" render "$scene" --quiet "$@" -o "$tmp/bad.wav" 2>"$tmp/err"
    rc=$?
    [ $rc -eq 2 ] || { echo "$what: exit $rc, want 2"; cat "$tmp/err"; exit 1; }
    grep -q -- "$named" "$tmp/err" || { echo "$what: the message does not name $named"; cat "$tmp/err"; exit 1; }
    [ ! -e "$tmp/bad.wav" ] || { echo "$what: wrote the WAV"; exit 1; }
    cat "$tmp/err"
}
refuse "a missing file" "$tmp/none.sofa" --layout binaural --sofa "$tmp/none.sofa"
refuse "a text file" "$tmp/text.sofa" --layout binaural --sofa "$tmp/text.sofa"
refuse "--sofa without binaural" "--sofa" --sofa "$kemar"
echo "binaural: 2 channels through KEMAR; bad SOFA files and options refused"
