#!/usr/bin/env bash
# Builds the benchmarks (Release) and runs them all, writing CSV and plots
# to bench/results/. Takes a few minutes on 2 cores, and bench_aero (the
# sound-texture precompute times) about 8 CPU minutes more (13 min wall on
# a shared 2-core machine); FULGUR_BENCH_SKIP=aero leaves it out.
#
# usage: scripts/bench.sh [PEER]
# PEER: a peer's program for bench_whole's comparison (bench/whole_process.c
# says what it must do; bench/peer/build_cosinekitty.sh builds the driver
# of cosinekitty/thunder outside this tree and prints its path). Without
# it whole_process.csv has fulgur's figures only.
set -euo pipefail
cd "$(dirname "$0")/.."
peer=${1:-}
if [ -n "$peer" ]; then
  peer=$(cd "$(dirname "$peer")" && pwd)/$(basename "$peer")
  [ -x "$peer" ] || { echo "bench.sh: $peer is not an executable"; exit 2; }
fi
source scripts/deps.sh
fulgur_install_deps
cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DFULGUR_TESTS=OFF >/dev/null
cmake --build build-bench -j2 >/dev/null
mkdir -p bench/results
for b in build-bench/bench/bench_*; do
  case " ${FULGUR_BENCH_SKIP:-} " in *" ${b##*/bench_} "*) continue ;; esac
  echo "== ${b##*/}"
  case ${b##*/} in
    bench_startup) "$b" build-bench/host/fulgur bench/scenes/one_segment.json ;;
    bench_whole)
      "$b" build-bench/host/fulgur "$peer"
      sh bench/whole_breakdown.sh build-bench/host/fulgur "$b"
      ;;
    *) "$b" ;;
  esac
done
echo "== python_render"
PYTHONPATH=build-bench/python python3 bench/python_render.py build-bench/host/fulgur
for p in bench/plots/*.gp; do
  gnuplot "$p"
done
sh bench/readme_table.sh README.md bench/results
echo "results in bench/results/:"
ls bench/results/
