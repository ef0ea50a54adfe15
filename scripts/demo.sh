#!/usr/bin/env bash
# Installs what is missing, builds (Release) into build-demo/, and renders
# every scene in examples/ to out/NAME.wav with its waveform/spectrogram
# plot out/NAME.png. Works from any directory. Exits non-zero if a scene
# failed (the others are still rendered).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
fulgur_install_deps

cmake -S . -B build-demo -DCMAKE_BUILD_TYPE=Release -DFULGUR_TESTS=OFF -DFULGUR_BENCH=OFF >/dev/null
cmake --build build-demo --target fulgur -j2 >/dev/null
fulgur=build-demo/host/fulgur

mkdir -p out
failed=()
for scene in examples/*.json; do
    name=$(basename "$scene" .json)
    if ! "$fulgur" render "$scene" -o "out/$name.wav" ||
       ! "$fulgur" analyze "out/$name.wav" --waveform "out/$name.wave.dat" \
                                           --spectrogram "out/$name.spec.dat" ||
       ! gnuplot -e "wave='out/$name.wave.dat'; spec='out/$name.spec.dat'; out='out/$name.png'; name='$name'" \
                 scripts/plot.gp; then
        failed+=("$name")
        continue
    fi
    echo "wrote out/$name.wav out/$name.png"
done
if [ ${#failed[@]} -ne 0 ]; then
    echo "failed: ${failed[*]}" >&2
    exit 1
fi
