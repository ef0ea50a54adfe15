#!/usr/bin/env bash
# Installs what is missing, builds (Release) into build-demo/ (the fulgur
# program, the libraries, the LV2 plugin and fulgur-lv2-render), and renders
# every scene in examples/ to out/ (scripts/demo_render.sh: NAME.wav at a
# -1 dBFS peak, NAME.png, NAME.picture.png). Works from any directory. Exits
# non-zero if a scene failed (the others are still rendered).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
fulgur_install_deps

cmake -S . -B build-demo -DCMAKE_BUILD_TYPE=Release -DFULGUR_TESTS=OFF -DFULGUR_BENCH=OFF >/dev/null
cmake --build build-demo -j2 >/dev/null
bash scripts/demo_render.sh build-demo out
