#!/usr/bin/env bash
# Second command of the README (and CI's): install what is missing, build everything, run the
# whole test suite (unit, integration with MPI, regression).
set -euo pipefail
cd "$(dirname "$0")/.."
bash cmake/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
cd build
# -LE full: the full-length runs (label full) are benchmarks, run on demand with ctest -L full.
# -j: as many tests at once as there are cores; the MPI tests take 2 (PROCESSORS).
ctest --output-on-failure --timeout 1200 -j "$(nproc)" -LE full
