#!/bin/sh
# usage: cli_render_sofa_dimensions.sh FULGUR SCENE
# fulgur render --layout binaural --sofa with small SimpleFreeFieldHRIR
# files written here by ncgen (netCDF-4, Debian's netcdf-bin): a well-formed
# one at 48 kHz and one at 44.1 kHz render two channels; files of the wrong
# shape (receivers, measurements, taps none or too many, sample rates out of
# range, differing or in other units, a NaN or an infinite tap) exit 2 with
# a message naming what is wrong, and write nothing. Exit 77 (skipped)
# without ncgen.
set -u
fulgur=$1
scene=$2
command -v ncgen >/dev/null 2>&1 || { echo "ncgen not found (apt-get install netcdf-bin)"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

. "$(dirname "$0")/sofa_cdl.sh" # sofa NAME M R N RATE [LAST [EDIT]]

accept() { # accept NAME: two channels
    "$fulgur" render "$scene" --quiet --layout binaural --sofa "$tmp/$1.sofa" -o "$tmp/$1.wav" ||
        { echo "$1: refused a well-formed file"; exit 1; }
    line=$("$fulgur" analyze "$tmp/$1.wav") || exit 1
    echo "$line" | grep -q ": 2 ch," || { echo "$1: not 2 channels: $line"; exit 1; }
    echo "$1: $line"
}
refuse() { # refuse NAME NAMED: exit 2, the file and NAMED in the message, no WAV
    "$fulgur" render "$scene" --quiet --layout binaural --sofa "$tmp/$1.sofa" \
        -o "$tmp/bad.wav" 2>"$tmp/err"
    rc=$?
    [ $rc -eq 2 ] || { echo "$1: exit $rc, want 2"; cat "$tmp/err"; exit 1; }
    grep -q -- "$1.sofa" "$tmp/err" || { echo "$1: the message does not name the file"; cat "$tmp/err"; exit 1; }
    grep -q -- "$2" "$tmp/err" || { echo "$1: the message does not say $2"; cat "$tmp/err"; exit 1; }
    [ ! -e "$tmp/bad.wav" ] || { echo "$1: wrote the WAV"; exit 1; }
    cat "$tmp/err"
}

sofa good 16 2 32 48000
accept good
sofa cd_rate 16 2 32 44100
accept cd_rate
sofa three_ears 16 3 32 48000
refuse three_ears "3 receivers (dimension R): expected 2"
sofa one_ear 16 1 32 48000
refuse one_ear "1 receivers (dimension R): expected 2"
sofa few 4 2 32 48000
refuse few "4 measurements (dimension M): expected 16"
sofa no_taps 16 2 UNLIMITED 48000
refuse no_taps "Data.IR has no taps (dimension N is 0)"
sofa long 16 2 9000 48000
refuse long "Data.IR of 9000 taps (dimension N) at 48000 Hz is 9000 taps at 48000 Hz: expected 1 to 8192"
# 7600 taps at 44.1 kHz are 8273 (8272.1 rounded up) at the engine's 48 kHz
sofa long_cd 16 2 7600 44100
refuse long_cd "is 8273 taps at 48000 Hz: expected 1 to 8192"
sofa rate_zero 16 2 32 0
refuse rate_zero "Data.SamplingRate 0 Hz: expected 1000 to 384000"
sofa rate_low 16 2 32 100
refuse rate_low "Data.SamplingRate 100 Hz"
sofa rates 16 2 32 "48000, 44100, 48000, 48000, 48000, 48000, 48000, 48000, 48000, 48000, 48000, 48000, 48000, 48000, 48000, 48000" "" \
    's/Data.SamplingRate(I)/Data.SamplingRate(M)/'
refuse rates "Data.SamplingRate holds 48000 and 44100 Hz: expected one rate"
sofa khz 16 2 32 48 "" 's/Units = "hertz"/Units = "kilohertz"/'
refuse khz 'Data.SamplingRate in "kilohertz": expected "hertz"'
sofa nan 16 2 32 48000 NaN
refuse nan "Data.IR value 1023 is not a finite number"
sofa inf 16 2 32 48000 -Infinity
refuse inf "Data.IR value 1023 is not a finite number"
echo "SOFA files of the wrong shape refused, naming what is wrong"
