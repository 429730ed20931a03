#!/bin/sh
# ctest driver: the same deck on 1 rank and on N ranks must give the same trace.
#   compare_ranks.sh GLOSSA COMPARE DECK OUTDIR TOLERANCE RANKS MPIEXEC [--set path=value ...]
set -e
glossa="$1"; compare="$2"; deck="$3"; out="$4"; tolerance="$5"; ranks="$6"; mpiexec="$7"
shift 7
rm -rf "$out"
"$glossa" run "$deck" --output "$out/1" --quiet "$@"
"$mpiexec" --allow-run-as-root --oversubscribe -np "$ranks" "$glossa" run "$deck" --output "$out/$ranks" --quiet "$@"
exec "$compare" "$out/1/traces.csv" "$out/$ranks" --tolerance "$tolerance"
