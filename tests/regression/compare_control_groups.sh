#!/bin/sh
# ctest driver: a GA-controlled deck on 1 rank and on N ranks split into N control groups (one
# rank each, candidates shared out, the winner's state broadcast) must give the same run bit
# for bit: the same traces and the same chosen inputs, objectives and candidate counts.
#   compare_control_groups.sh GLOSSA DECK OUTDIR RANKS MPIEXEC [--set path=value ...]
set -e
glossa="$1"; deck="$2"; out="$3"; ranks="$4"; mpiexec="$5"
shift 5
rm -rf "$out"
"$glossa" run "$deck" --output "$out/1" --quiet "$@"
"$mpiexec" --allow-run-as-root --oversubscribe -np "$ranks" "$glossa" run "$deck" --output "$out/$ranks" --quiet \
  --control-groups "$ranks" "$@"
cmp "$out/1/traces.csv" "$out/$ranks/traces.csv"
cmp "$out/1/controls.csv" "$out/$ranks/controls.csv"
echo "identical traces and controls on 1 rank and on $ranks control groups"
