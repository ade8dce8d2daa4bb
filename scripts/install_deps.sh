#!/usr/bin/env bash
# Installs every build, test and runtime dependency of opgraph from Debian packages.
set -euo pipefail
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq \
  build-essential cmake ninja-build ccache pkg-config \
  libceres-dev libeigen3-dev libgflags-dev libgoogle-glog-dev \
  libosd-dev libopenmesh-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev \
  nlohmann-json3-dev libnanoflann-dev \
  libgtest-dev libgmock-dev libbenchmark-dev \
  blender python3 python3-numpy python3-matplotlib chromium \
  pybind11-dev python3-pybind11 python3-dev \
  clang libclang-rt-14-dev >/dev/null  # clang and libFuzzer: the fuzz harnesses (scripts/fuzz.sh)
# Input formats: Assimp for meshes, PCL for point clouds (their recommends pull VTK and Qt, unused).
$SUDO apt-get install -y -qq --no-install-recommends libassimp-dev libpcl-dev >/dev/null
