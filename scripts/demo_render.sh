#!/usr/bin/env bash
# usage: demo_render.sh BUILD_DIR OUT_DIR
# The demo's renders (scripts/demo.sh builds, then runs this): every scene
# in examples/ to OUT_DIR/NAME.wav, normalized to a -1 dBFS peak so that it
# plays without clipping (its calibration, the pascals of full scale, is in
# the WAV's comment), with its waveform/spectrogram plot OUT_DIR/NAME.png
# (in pascals) and a picture of its discharges OUT_DIR/NAME.picture.png (at
# the first return stroke; docs/picture.md) when BUILD_DIR has gpu/ built.
# Exits non-zero if a scene failed (the others are still rendered). The
# README's test runs it on its own build (tests/readme_commands.py).
set -euo pipefail
[ $# -eq 2 ] || { sed -n 2p "$0" >&2; exit 2; }
build=$1 out=$2
repo=$(dirname "${BASH_SOURCE[0]}")/..
fulgur=$build/host/fulgur

# The picture needs gpu/ (FULGUR_GPU, on by default) and a GL driver
# (Mesa's llvmpipe will do, headless).
picture=()
if grep -q '^FULGUR_GPU:BOOL=ON' "$build/CMakeCache.txt"; then
    picture=(--png)
else
    echo "gpu/ is not built: no pictures" >&2
fi

mkdir -p "$out"
failed=()
for scene in "$repo"/examples/*.json; do
    name=$(basename "$scene" .json)
    png=()
    [ ${#picture[@]} -eq 0 ] || png=(--png "$out/$name.picture.png")
    if ! "$fulgur" render "$scene" -o "$out/$name.wav" --normalize -1 "${png[@]}" ||
       ! "$fulgur" analyze "$out/$name.wav" --waveform "$out/$name.wave.dat" \
                                            --spectrogram "$out/$name.spec.dat" ||
       ! gnuplot -e "wave='$out/$name.wave.dat'; spec='$out/$name.spec.dat'; out='$out/$name.png'; name='$name'" \
                 "$repo/scripts/plot.gp"; then
        failed+=("$name")
        continue
    fi
    echo "wrote $out/$name.wav $out/$name.png${png:+ $out/$name.picture.png}"
done
if [ ${#failed[@]} -ne 0 ]; then
    echo "failed: ${failed[*]}" >&2
    exit 1
fi
