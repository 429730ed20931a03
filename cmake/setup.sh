#!/usr/bin/env bash
# First command of the README: install what is missing, build, run the default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash cmake/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build --target glossa -j "$(nproc)"
build/glossa run inputs/verification/step44_block.xml --output results/step44_block
