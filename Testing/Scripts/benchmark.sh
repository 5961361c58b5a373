#!/usr/bin/env bash
# The benchmark from one command: set-up and build as the README's commands do,
# then speed, cost growth, memory and accuracy against vtkSplineFilter, SciPy and
# finite differences, measured in one run; tables on stdout, plots in build/benchmark/.
set -euo pipefail
cd "$(dirname "$0")/../.."
bash Testing/Scripts/setup.sh
bash Testing/Scripts/build.sh
xvfb-run -a -s "-screen 0 1280x1024x24" pvpython Testing/Benchmarks/benchmark.py \
  --plugin build/lib/paraview-5.11/plugins/ShapeSplines/ShapeSplines.so --output build/benchmark "$@"
