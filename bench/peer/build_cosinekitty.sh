#!/bin/sh
# usage: build_cosinekitty.sh [PEER_GIT] [WORKDIR]
# Clones cosinekitty/thunder (MIT) into WORKDIR (default /tmp/fulgur-peer)
# and builds the measuring driver cosinekitty_driver.cpp against its
# headers there, -O3 as the peer's own build script; prints the binary's
# path. The peer's code stays in WORKDIR: nothing of it enters this tree.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
repo=${1:-https://github.com/cosinekitty/thunder}
work=${2:-/tmp/fulgur-peer}
rm -rf "$work"
mkdir -p "$work"
# the peer's large recordings are not needed: only its headers are used
git clone -q --no-checkout "$repo" "$work/thunder"
git -C "$work/thunder" checkout -q HEAD -- src/lightning.hpp src/wavefile.hpp src/audio_buffer.hpp
${CXX:-g++} -std=c++11 -O3 -Wall -I"$work/thunder/src" -o "$work/peer" "$here/cosinekitty_driver.cpp"
echo "$work/peer"
