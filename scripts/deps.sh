#!/bin/bash
# Installs the Debian packages rollviz needs that are missing; idempotent. Says what it installs.
# Usage: scripts/deps.sh [build|test]   (test also installs the test tools: X server, xdotool, ffmpeg, python)
set -euo pipefail
BUILD_PKGS=(cmake g++ pkg-config ninja-build ccache
  libvtk9-dev qt6-base-dev libqt6opengl6-dev libeigen3-dev
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
  libegl-dev libgl1-mesa-dri libosmesa6-dev
  nlohmann-json3-dev libcli11-dev libfmt-dev libfftw3-dev
  libopenmpi-dev openmpi-bin pybind11-dev python3-dev
  libjs-three)
TEST_PKGS=(libgtest-dev libgmock-dev libbenchmark-dev libboost-dev
  xvfb xauth xdotool x11-apps ffmpeg python3 python3-numpy python3-pil python3-pytest python3-vtk9 python3-matplotlib
  clang-14 libfuzzer-14-dev clang-tidy poppler-utils librsvg2-bin
  python3-sphinx python3-myst-parser python3-pandas python3-xarray python3-nbclient python3-ipykernel mypy
  chromium chromium-driver python3-selenium)
want=("${BUILD_PKGS[@]}")
[ "${1:-build}" = test ] && want+=("${TEST_PKGS[@]}")
missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "rollviz: installing missing Debian packages: ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "rollviz: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q >&2
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
