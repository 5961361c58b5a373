#!/usr/bin/env bash
# Installs the Debian 12 packages ShapeSplines needs (idempotent, no prompts).
# Needs root (or sudo) and apt-get. find_package(ParaView) fails on the first
# -dev package of ParaView's dependencies that is missing, hence the long list;
# libvtk9-dev and python3-vtk9 would conflict with python3-paraview.
set -euo pipefail

packages=(
  # compiler and build
  build-essential cmake ninja-build pkg-config git
  # ParaView 5.11 SDK with its own VTK 9.2 (do NOT add libvtk9-dev / python3-vtk9)
  paraview paraview-dev python3-paraview
  # what find_package(ParaView) needs from its dependencies
  qtbase5-dev qttools5-dev libqt5svg5-dev libqt5opengl5-dev qtxmlpatterns5-dev-tools
  libopenmpi-dev mpi-default-dev libhdf5-openmpi-dev libnetcdf-dev libgdal-dev
  libutfcpp-dev python3-mpi4py libdouble-conversion-dev libtiff-dev libtheora-dev
  python3-dev libpng-dev libgl-dev libxml2-dev liblzma-dev liblz4-dev libjpeg-dev
  libglew-dev libgl2ps-dev libfreetype-dev libavcodec-dev libavformat-dev
  libswscale-dev libavutil-dev libexpat1-dev libboost-dev libx11-dev
  # our own dependencies
  libeigen3-dev googletest libgtest-dev
  # headless rendering and the independent reference implementation in tests
  xvfb xauth python3-scipy python3-numpy
  # mpirun for the distributed pvbatch test
  openmpi-bin
  # the libFuzzer target of the math core (clang with its fuzzer runtime)
  clang libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} Debian packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${#missing[@]} missing Debian packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends "${missing[@]}"
