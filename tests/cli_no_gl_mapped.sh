#!/bin/sh
# usage: cli_no_gl_mapped.sh FULGUR SCENE GPU_SCENE
# Issue 16 item 6: the processes that need no GL map none of its libraries.
# A WAV render of SCENE, --help, --version and analyze of that WAV must
# load no libGL, libEGL, libOpenGL, libGLX, libglfw, libX11, libxcb,
# libepoxy, libOSMesa, libLLVM, libgbm, libdrm, FreeType or fontconfig, nor
# fulgur's GL module; the list is every object the dynamic loader maps,
# dlopen included (glibc's LD_DEBUG=files). The control: --png of
# GPU_SCENE does load the module and epoxy, so the check can see them; a
# copy of the program without its module says so and writes nothing.
set -u
fulgur=$1
scene=$2
gpu_scene=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
gl='libGL\.|libEGL|libOpenGL|libGLX|libglfw|libX11|libxcb|libepoxy|libOSMesa|libLLVM|libgbm|libdrm|libfreetype|libfontconfig|fulgur-gl\.so'

. "$(dirname "$0")/loader_log.sh"
check() {
    mapped "$@"
    if grep 'file=' "$tmp/log" | grep -E "$gl" >/dev/null; then
        echo "GL libraries mapped by: $*"
        grep 'file=' "$tmp/log" | grep -E "$gl" | sed 's/^[0-9]*: *//' | sort -u
        exit 1
    fi
    echo "no GL library mapped: $*"
}
check "$fulgur" render "$scene" -o "$tmp/a.wav"
check "$fulgur" --help
check "$fulgur" --version
check "$fulgur" analyze "$tmp/a.wav"
if [ -n "$gpu_scene" ]; then
    mapped "$fulgur" render "$gpu_scene" -o "$tmp/b.wav" --png "$tmp/b.png"
    for lib in fulgur-gl.so libepoxy; do
        grep 'file=' "$tmp/log" | grep "$lib" >/dev/null ||
            { echo "the control failed: --png did not load $lib"; exit 1; }
    done
    echo "--png loads the GL module and epoxy (the control)"
fi
if [ -n "$gpu_scene" ]; then
    mkdir "$tmp/alone"
    cp "$fulgur" "$tmp/alone/fulgur"
    if "$tmp/alone/fulgur" render "$gpu_scene" -o "$tmp/alone/c.wav" --png "$tmp/alone/c.png" \
        2>"$tmp/err"; then
        echo "--png without the GL module succeeded"; exit 1
    fi
    grep -q "cannot open fulgur's GL module.*fulgur-gl.so: absent" "$tmp/err" ||
        { cat "$tmp/err"; echo "no message naming the missing module"; exit 1; }
    [ "$(ls "$tmp/alone")" = fulgur ] || { ls "$tmp/alone"; echo "files left behind"; exit 1; }
    echo "without its module: $(cat "$tmp/err")"
fi
