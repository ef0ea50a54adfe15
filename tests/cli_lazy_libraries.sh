#!/bin/sh
# usage: cli_lazy_libraries.sh FULGUR SCENE
# Issue 17: the libraries a WAV render does not call are opened on first
# use (host/common/lazy_library.h). A render of SCENE, --help and
# --version map no libsndfile, FFTW, libmysofa, libsamplerate or zlib
# (the list is every object the dynamic loader maps, dlopen included:
# glibc's LD_DEBUG=files); the controls: a binaural render maps FFTW,
# libmysofa and libsamplerate and writes the same WAV as a binaural
# render without the log, and analyze of a WAV maps libsndfile.
set -u
fulgur=$1
scene=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
lazy='libsndfile|libfftw3\.|libfftw3_threads|libmysofa|libsamplerate|libz\.'

. "$(dirname "$0")/loader_log.sh"
for args in "render $scene -o $tmp/a.wav" --help --version; do
    mapped "$fulgur" $args
    if grep -E "$lazy" "$tmp/log" >/dev/null; then
        echo "mapped by fulgur $args:"
        grep -E "$lazy" "$tmp/log" | sed 's/^[0-9]*: *//' | sort -u
        exit 1
    fi
    echo "none mapped: fulgur $args"
done
mapped "$fulgur" render "$scene" --layout binaural -o "$tmp/b.wav"
for lib in libfftw3.so libfftw3_threads libmysofa libsamplerate; do
    grep "$lib" "$tmp/log" >/dev/null || { echo "the control failed: no $lib"; exit 1; }
done
"$fulgur" render "$scene" --quiet --layout binaural -o "$tmp/c.wav" || exit 1
cmp -s "$tmp/b.wav" "$tmp/c.wav" || { echo "the binaural renders differ"; exit 1; }
echo "a binaural render opens FFTW, libmysofa and libsamplerate (the control)"
mapped "$fulgur" analyze "$tmp/a.wav"
grep libsndfile "$tmp/log" >/dev/null || { echo "the control failed: analyze, no libsndfile"; exit 1; }
echo "analyze opens libsndfile (the control)"
