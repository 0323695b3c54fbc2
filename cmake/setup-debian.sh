#!/bin/sh
# Installs what voxref needs from Debian 12 packages (what is already there stays as it is) and
# builds it into build/. Run from anywhere; as root, or as a user with sudo.
set -eu
cd "$(dirname "$0")/.."
if [ "$(id -u)" -eq 0 ]; then SUDO=""; else SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  build-essential cmake ninja-build pkg-config \
  libglm-dev libosmesa6-dev libegl-dev libgl1-mesa-dri mesa-vulkan-drivers \
  libopenexr-dev libopenimageio-dev libembree-dev \
  libgtest-dev libgmock-dev clang clang-format libclang-rt-14-dev libcli11-dev nlohmann-json3-dev libtomlplusplus-dev zlib1g-dev libzstd-dev liblzma-dev libssl-dev \
  chromium gnuplot-nox \
  > /dev/null
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j 2
