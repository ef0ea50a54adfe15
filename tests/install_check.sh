#!/bin/sh
# usage: install_check.sh BUILD_DIR SOURCE_DIR
# Installs the build into a temporary prefix and builds the programs of
# tests/install/ against it as an application would, four ways: C and C++
# through pkg-config (fulgur, fulgur-gpu), and C and C++ through the CMake
# package (find_package(fulgur) -> fulgur::fulgur, fulgur::gpu); each runs.
# Also checks the installed layout: headers, the SONAMEs, the pc files, the
# LV2 bundle, the program's GL module.
set -eu
build=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" > "$tmp/install.log" || { cat "$tmp/install.log"; exit 1; }
libdir=$(ls -d "$prefix"/lib*/ | head -1)
libdir=${libdir%/}
for f in include/fulgur/fulgur.h include/fulgur/version.h include/fulgur/gpu.h; do
    [ -f "$prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
for f in libfulgur.so libfulgur.a libfulgur_gpu.so pkgconfig/fulgur.pc pkgconfig/fulgur-gpu.pc \
         cmake/fulgur/fulgurConfig.cmake cmake/fulgur/fulgurConfigVersion.cmake; do
    [ -e "$libdir/$f" ] || { echo "not installed: ${libdir#$prefix/}/$f"; exit 1; }
done
grep -q "^prefix=$prefix\$" "$libdir/pkgconfig/fulgur.pc" ||
    { echo "fulgur.pc does not name the prefix installed to:"; cat "$libdir/pkgconfig/fulgur.pc"; exit 1; }
# the installed program finds its GL module (host/cli/gl_module.h), when built
if [ -e "$libdir/fulgur/fulgur-gl.so" ]; then
    "$prefix/bin/fulgur" view --help > "$tmp/view.txt" ||
        { echo "the installed fulgur cannot open its GL module"; exit 1; }
    grep -q "^usage: fulgur view" "$tmp/view.txt" || { cat "$tmp/view.txt"; exit 1; }
    echo "the installed fulgur opens ${libdir#$prefix/}/fulgur/fulgur-gl.so"
fi
export PKG_CONFIG_PATH=$libdir/pkgconfig
version=$(pkg-config --modversion fulgur)
echo "installed fulgur $version to $prefix"

cc=${CC:-cc}
cxx=${CXX:-c++}
# shellcheck disable=SC2046 # pkg-config's words are meant to split
"$cc" -std=c11 -Wall -Werror $(pkg-config --cflags fulgur) "$src/tests/install/consumer.c" \
    -o "$tmp/c_pc" $(pkg-config --libs fulgur) -lm -Wl,-rpath,"$libdir"
# shellcheck disable=SC2046
"$cxx" -std=c++11 -Wall -Wextra -Werror $(pkg-config --cflags fulgur-gpu) \
    "$src/tests/install/consumer.cpp" -o "$tmp/cpp_pc" $(pkg-config --libs fulgur-gpu) \
    -Wl,-rpath,"$libdir"
"$tmp/c_pc"
"$tmp/cpp_pc"

cmake -S "$src/tests/install" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx" > "$tmp/cmake.log" ||
    { cat "$tmp/cmake.log"; exit 1; }
cmake --build "$tmp/consumer" > "$tmp/build.log" || { cat "$tmp/build.log"; exit 1; }
"$tmp/consumer/consumer_c"
"$tmp/consumer/consumer_cpp"

# what the shared libraries and the plugin bundle look like once installed
soname=$(readelf -d "$libdir/libfulgur.so" | sed -n 's/.*SONAME.*\[\(.*\)\]/\1/p')
major=${version%%.*}
rest=${version#*.}
minor=${rest%%.*}
if [ "$major" = 0 ]; then want=libfulgur.so.0.$minor; else want=libfulgur.so.$major; fi
[ "$soname" = "$want" ] || { echo "SONAME $soname, the ABI policy wants $want"; exit 1; }
if readelf -d "$libdir/libfulgur_gpu.so" | grep -q -E 'NEEDED.*(OSMesa|libGL|libEGL)'; then
    echo "libfulgur_gpu links a GL library; it must open them when a context is made"
    exit 1
fi
echo "SONAMEs $soname and $(readelf -d "$libdir/libfulgur_gpu.so" | sed -n 's/.*SONAME.*\[\(.*\)\]/\1/p')"
echo ok
