#!/bin/sh
# ctest driver of a regression test: runs a deck (optionally under mpiexec) into a scratch
# directory and compares its traces with the stored reference.
#   run_and_compare.sh GLOSSA COMPARE DECK REFERENCE OUTDIR TOLERANCE MAX_DILATATION "OVERRIDES" [MPIEXEC ARGS...]
# OVERRIDES: "--set;path=value;--set;..." (a CMake list), or "-" for none.
set -e
glossa="$1"; compare="$2"; deck="$3"; reference="$4"; out="$5"; tolerance="$6"; dilatation="$7"; overrides="$8"
shift 8
[ "$overrides" = "-" ] && overrides=""
rm -rf "$out"
run_glossa() {
  old_ifs="$IFS"; IFS=';'
  # shellcheck disable=SC2086
  set -- "$@" $overrides
  IFS="$old_ifs"
  "$@"
}
run_glossa "$@" "$glossa" run "$deck" --output "$out" --quiet
exec "$compare" "$reference" "$out" --tolerance "$tolerance" --max-dilatation "$dilatation"
