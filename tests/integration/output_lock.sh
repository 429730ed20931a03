#!/usr/bin/env bash
# output_lock.sh OUTDIR COMMAND...: starts COMMAND (a glossa run into OUTDIR, its arguments
# ending with --output OUTDIR) and, once summary.json records a step, starts the same command
# again. Passes when the second run is refused at once with exit status 2 and a message naming
# OUTDIR and the other run, leaving the first run's files in place; and when, after the first run
# is killed with SIGKILL, its stale lock file does not block a third run (it writes its summary).
out=$1
shift
rm -rf "$out"
mkdir -p "$(dirname "$out")"
"$@" >"$out.first.stdout" 2>"$out.first.stderr" &
pid=$!
steps() { /usr/bin/python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['steps']))" "$out/summary.json" 2>/dev/null || echo 0; }
for _ in $(seq 1 600); do
  [ "$(steps)" -ge 1 ] && break
  kill -0 $pid 2>/dev/null || { echo "the first run ended before its first step"; cat "$out.first.stderr"; exit 1; }
  sleep 0.1
done
"$@" >/dev/null 2>"$out.second.stderr"
status=$?
cat "$out.second.stderr"
fail() { echo "$1"; kill -9 $pid 2>/dev/null; exit 1; }
[ $status -eq 2 ] || fail "second run: exit status $status, expected 2"
grep -Fq "the output directory $out is in use by another glossa run (process $pid)" "$out.second.stderr" ||
  fail "second run: the message does not name the directory and the first run"
kill -0 $pid 2>/dev/null || fail "the first run ended before the second was refused: nothing was tested"
[ -e "$out/traces.csv" ] && [ -e "$out/summary.json" ] || fail "the second run removed the first run's files"
kill -9 $pid
wait $pid 2>/dev/null
[ -e "$out/.glossa.lock" ] || fail "no lock file left by the killed run: its staleness was not tested"
timeout 120 "$@" --set "Time/end time=0.001" >/dev/null 2>"$out.third.stderr"
status=$?
cat "$out.third.stderr"
[ $status -eq 0 ] || fail "third run after a killed one: exit status $status, expected 0"
echo "second run refused while the first ran; a run after the first was killed went ahead"
