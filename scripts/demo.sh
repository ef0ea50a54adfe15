#!/usr/bin/env bash
# Installs what is missing, builds (Release) into build-demo/ (the fulgur
# program, the libraries, the LV2 plugin and fulgur-lv2-render), and renders
# every scene in examples/ to out/NAME.wav, normalized to a -1 dBFS peak so
# that it plays without clipping (its calibration, the pascals of full
# scale, is in the WAV's comment), with its waveform/spectrogram plot
# out/NAME.png (in pascals) and a picture of its discharges
# out/NAME.picture.png (at the first return stroke; docs/picture.md) when
# gpu/ is built. Works from any directory. Exits non-zero if a scene failed
# (the others are still rendered).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
fulgur_install_deps

cmake -S . -B build-demo -DCMAKE_BUILD_TYPE=Release -DFULGUR_TESTS=OFF -DFULGUR_BENCH=OFF >/dev/null
cmake --build build-demo -j2 >/dev/null
fulgur=build-demo/host/fulgur

# The picture needs gpu/ (FULGUR_GPU, on by default) and a GL driver
# (Mesa's llvmpipe will do, headless).
picture=()
if grep -q '^FULGUR_GPU:BOOL=ON' build-demo/CMakeCache.txt; then
    picture=(--png)
else
    echo "gpu/ is not built: no pictures" >&2
fi

mkdir -p out
failed=()
for scene in examples/*.json; do
    name=$(basename "$scene" .json)
    png=()
    [ ${#picture[@]} -eq 0 ] || png=(--png "out/$name.picture.png")
    if ! "$fulgur" render "$scene" -o "out/$name.wav" --normalize -1 "${png[@]}" ||
       ! "$fulgur" analyze "out/$name.wav" --waveform "out/$name.wave.dat" \
                                           --spectrogram "out/$name.spec.dat" ||
       ! gnuplot -e "wave='out/$name.wave.dat'; spec='out/$name.spec.dat'; out='out/$name.png'; name='$name'" \
                 scripts/plot.gp; then
        failed+=("$name")
        continue
    fi
    echo "wrote out/$name.wav out/$name.png${png:+ out/$name.picture.png}"
done
if [ ${#failed[@]} -ne 0 ]; then
    echo "failed: ${failed[*]}" >&2
    exit 1
fi
