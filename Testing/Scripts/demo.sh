#!/usr/bin/env bash
# README command 1: installs what is missing, builds, and runs the demo on Data/:
# the cubic spline, the approximation and the shape analysis of the aorta centerline and the Akima
# data, written as .vtp files and PNG pictures into build/demo.
set -euo pipefail
cd "$(dirname "$0")/../.."
bash Testing/Scripts/setup.sh
bash Testing/Scripts/build.sh
xvfb-run -a pvpython Testing/Python/demo.py \
  --plugin "$PWD/build/lib/paraview-5.11/plugins/ShapeSplines/ShapeSplines.so" \
  --data "$PWD/Data" --output "$PWD/build/demo"
