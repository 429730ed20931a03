#!/bin/sh
# ctest driver of a regression test: runs a deck (optionally under mpiexec) into a scratch
# directory and compares its traces with the stored reference.
#   run_and_compare.sh GLOSSA COMPARE DECK REFERENCE OUTDIR TOLERANCE MAX_DILATATION [MPIEXEC ARGS...]
set -e
glossa="$1"; compare="$2"; deck="$3"; reference="$4"; out="$5"; tolerance="$6"; dilatation="$7"
shift 7
rm -rf "$out"
"$@" "$glossa" run "$deck" --output "$out" --quiet
exec "$compare" "$reference" "$out" --tolerance "$tolerance" --max-dilatation "$dilatation"
