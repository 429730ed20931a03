#!/usr/bin/env bash
# Second command of the README (and CI's): install what is missing, build everything, run the
# whole test suite (unit, integration with MPI, regression).
set -euo pipefail
cd "$(dirname "$0")/.."
bash cmake/install-deps.sh
# A fresh build directory is generated for Ninja: it starts a unit as soon as its own inputs are
# there, where make waits for every target a target depends on, and keeps both cores busy through
# a cold build (doc/developing.md, "Build time"). An existing build directory keeps its generator.
generator=()
if [ ! -f build/CMakeCache.txt ] && command -v ninja > /dev/null; then generator=(-G Ninja); fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${generator[@]}"
cmake --build build -j "$(nproc)"
cd build
# Open MPI's start-up is most of a short test's time (about 0.85 s of a 0.9 s `glossa validate`): a
# lone process (no mpiexec) starts a helper daemon in case it spawns ranks, which Glossa never
# does, and UCX probes the machine's network devices. Without both it starts in about 0.35 s;
# ob1 over shared memory (vader) is Open MPI's own transport between ranks of one machine, so
# the 2-rank tests still exchange the same messages. Over 800 tests, each its own process,
# this is minutes of a CI run (doc/developing.md, "Tests").
export OMPI_MCA_ess_singleton_isolated=1 OMPI_MCA_pml=ob1 OMPI_MCA_osc=^ucx
# -LE full: the full-length runs (label full) are benchmarks, run on demand with ctest -L full.
# -j: as many tests at once as there are cores; the MPI tests take 2 (PROCESSORS).
ctest --output-on-failure --timeout 1200 -j "$(nproc)" -LE full
