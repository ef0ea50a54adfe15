#!/usr/bin/env bash
# Installs, when missing, the Debian 12 packages fulgur needs to build, test
# and plot. Sourced by demo.sh and test.sh; set FULGUR_DEPS_EXTRA to add more.
# Run on its own (bash scripts/deps.sh), it installs them.
fulgur_install_deps() {
  local pkgs=(cmake make gcc g++ pkg-config libcjson-dev libsndfile1-dev libsamplerate0-dev libmysofa-dev netcdf-bin libfftw3-dev
              libpng-dev zlib1g-dev gnuplot-nox libcmocka-dev clang-14 libfuzzer-14-dev
              libclang-rt-14-dev lv2-dev liblilv-dev sordi lilv-utils jalv
              libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev
              libglfw3-dev libfreetype-dev libfontconfig-dev fonts-dejavu-core xvfb xauth python3
              python3-cffi python3-numpy python3-pytest python3-venv python3-pip
              python3-setuptools python3-wheel parallel rsync
              jackd2 libjack-jackd2-dev portaudio19-dev alsa-utils
              valgrind git
              ${FULGUR_DEPS_EXTRA:-})
  local missing=()
  for p in "${pkgs[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "installing: ${missing[*]}"
  # jackd2 asks whether to enable real-time priority: no (the tests start
  # their own server and need none)
  echo "jackd2 jackd/tweak-rt-limits boolean false" | $sudo debconf-set-selections
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# run directly rather than sourced: install now
if [ "${BASH_SOURCE[0]}" = "$0" ]; then
  set -e
  fulgur_install_deps
fi
