#!/usr/bin/env bash
# README command 2: installs what is missing, builds, and runs the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/../.."
bash Testing/Scripts/setup.sh
bash Testing/Scripts/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
