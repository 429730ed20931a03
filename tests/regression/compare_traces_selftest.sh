#!/bin/sh
# compare_traces must tell a matching run from a wrong one: a reference of two steps against runs
# whose times or displacements are moved just inside and just outside the tolerance.
#   compare_traces_selftest.sh COMPARE SCRATCH
set -e
compare="$1"; dir="$2"
rm -rf "$dir"; mkdir -p "$dir"
header='time [s],point,ux [m],uy [m],uz [m]'
printf '%s\n0.5,tip,1.0e-3,0,0\n1,tip,2.0e-3,0,-1e-4\n' "$header" > "$dir/reference.csv"
# expect NAME STATUS TRACE: the run's traces.csv is TRACE; compare_traces (tolerance 1e-6) must exit with STATUS.
expect() {
  mkdir -p "$dir/$1"
  printf '%s\n%s' "$header" "$3" > "$dir/$1/traces.csv"
  status=0
  "$compare" "$dir/reference.csv" "$dir/$1" --tolerance 1e-6 > "$dir/$1/out.txt" || status=$?
  if [ "$status" -ne "$2" ]; then
    echo "$1: exit $status, expected $2"; cat "$dir/$1/out.txt"; exit 1
  fi
  echo "$1: exit $status as expected"
}
expect identical 0 '0.5,tip,1.0e-3,0,0
1,tip,2.0e-3,0,-1e-4
'
# An arc-length run's times are results: 1e-12 s apart (the round-off of a kernel change) matches.
expect time_round_off 0 '0.50000000000100002,tip,1.0e-3,0,0
1,tip,2.0e-3,0,-1e-4
'
expect time_outside_tolerance 1 '0.500002,tip,1.0e-3,0,0
1,tip,2.0e-3,0,-1e-4
'
expect displacement_inside_tolerance 0 '0.5,tip,1.0000015e-3,0,0
1,tip,2.0e-3,0,-1e-4
'
expect displacement_outside_tolerance 1 '0.5,tip,1.0e-3,0,0
1,tip,2.0e-3,0,-1.00003e-4
'
expect wrong_point 1 '0.5,tail,1.0e-3,0,0
1,tip,2.0e-3,0,-1e-4
'
expect extra_row 1 '0.5,tip,1.0e-3,0,0
0.75,tip,1.5e-3,0,0
1,tip,2.0e-3,0,-1e-4
'
