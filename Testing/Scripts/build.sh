#!/usr/bin/env bash
# Configures and builds ShapeSplines in ./build (Release, Ninja). Idempotent.
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON
cmake --build build --parallel "$(nproc)"
