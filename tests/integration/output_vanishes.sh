#!/usr/bin/env bash
# output_vanishes.sh OUTDIR COMMAND...: starts COMMAND (a glossa run into OUTDIR under mpiexec),
# deletes OUTDIR once summary.json exists, and passes when the job then ends on every rank
# within 30 s with exit status 4 (an output file could not be written) and says so on stderr.
out=$1
shift
rm -rf "$out"
"$@" >"$out.stdout" 2>"$out.stderr" &
pid=$!
for _ in $(seq 1 600); do [ -e "$out/summary.json" ] && break; sleep 0.1; done
# The run keeps writing while rm walks the tree: a step file written into results_steps after rm
# emptied it leaves the directory standing ("Directory not empty"). Delete until it is gone.
for _ in $(seq 1 100); do rm -rf "$out" 2>/dev/null; [ -e "$out" ] || break; done
for _ in $(seq 1 300); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
if kill -0 $pid 2>/dev/null; then echo "still running 30 s after its output directory was deleted"; kill -9 $pid; exit 1; fi
wait $pid
status=$?
cat "$out.stderr"
[ $status -eq 4 ] || { echo "exit status $status, expected 4"; exit 1; }
grep -Eq "glossa: error: .*(cannot|HDF5)" "$out.stderr" || { echo "no error message"; exit 1; }
