#!/usr/bin/env bash
# Installs the Debian 12 packages Glossa needs that are not installed yet (nothing else is
# downloaded, ever). Safe to run again: it does nothing when everything is there.
set -euo pipefail
packages=(
  build-essential cmake ccache ninja-build              # Ninja: the CI build's generator (cmake/test.sh)
  trilinos-all-dev libscotch-dev libptscotch-dev   # Trilinos' link lists name the scotch libraries
  libopenmpi-dev openmpi-bin libhdf5-openmpi-dev
  libeigen3-dev libgtest-dev nlohmann-json3-dev hdf5-tools
  libmumps-dev libopenblas0-serial                 # the direct solver, and an optimised BLAS for its dense fronts (4x on the s7.1 block)
  python3-numpy python3-matplotlib                 # plots and reference-table scripts (/usr/bin/python3)
  paraview xvfb                                    # the ParaView reader test (pvpython under xvfb-run)
  gmsh                                             # the import tests run the real Gmsh (else they are skipped)
  libcgal-dev                                      # the AABB tree of the contact search (header-only; src/contact/TriangulatedObstacle.cpp)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo=sudo; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
fi
