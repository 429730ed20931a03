#!/usr/bin/env bash
# stop_signal.sh SIGNAL OUTDIR COMMAND...: starts COMMAND (a glossa run into OUTDIR, perhaps under
# mpiexec), sends SIGNAL once summary.json records two steps, and passes when, within 30 s, the
# run has ended and summary.json says it was interrupted by that signal (running false, the
# reason in words) and describes the same last step as traces.csv (or says that the next step
# was being written, under mpiexec on a slow disk: then traces.csv may hold that one step more). Without mpiexec the exit
# status must be 3 and the reason must be on stderr, and the last step must be a checkpoint.
#   SIGNAL_TWICE=1   the signal is sent again as soon as the first was handled, as `timeout`
#                    sends it to the process and its group: the run must end as after one (its
#                    steps must outlast that moment).
#   SIGNAL_RANKS=1   the signal goes to mpiexec's children, the ranks (as a batch system sends
#                    it), not to mpiexec: then mpiexec's exit status is theirs and must be 3.
signal=$1 out=$2
shift 2
rm -rf "$out"
mkdir -p "$(dirname "$out")"
"$@" >"$out.stdout" 2>"$out.stderr" &
pid=$!
steps() { /usr/bin/python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['steps']))" "$out/summary.json" 2>/dev/null || echo 0; }
for _ in $(seq 1 600); do
  [ "$(steps)" -ge 2 ] && break
  kill -0 $pid 2>/dev/null || { echo "the run ended before two steps"; cat "$out.stderr"; exit 1; }
  sleep 0.1
done
targets=$pid
if [ -n "$SIGNAL_RANKS" ]; then
  targets=$(pgrep -P $pid)
  [ -n "$targets" ] || { echo "mpiexec has no child processes"; exit 1; }
fi
kill -s "$signal" $targets
if [ -n "$SIGNAL_TWICE" ]; then
  # Two signals sent at once merge while pending: the second must come once the first was handled
  # (summary.json says so), as the group's copy does when the process ran in between.
  interrupted() { /usr/bin/python3 -c "import json,sys; sys.exit('interrupted' not in json.load(open(sys.argv[1])))" "$out/summary.json" 2>/dev/null; }
  for _ in $(seq 1 100); do interrupted && break; sleep 0.01; done
  kill -s "$signal" $targets 2>/dev/null || { echo "the run ended before the second $signal: nothing was tested"; exit 1; }
fi
for _ in $(seq 1 300); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
if kill -0 $pid 2>/dev/null; then echo "still running 30 s after $signal"; kill -9 $pid; exit 1; fi
wait $pid
status=$?
cat "$out.stderr"
/usr/bin/python3 - "$out" "$signal" "$1" "$status" "$SIGNAL_RANKS" <<'PY' || exit 1
import csv, json, os, sys
out, signal, command, status, ranks = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
s = json.load(open(out + "/summary.json"))
assert s["running"] is False, "summary.json still says running"
assert s["interrupted"] == signal, s.get("interrupted")
assert s["converged"] is False
assert ("interrupted by " + signal) in s["failure"], s["failure"]
times = sorted({float(r["time [s]"]) for r in csv.DictReader(open(out + "/traces.csv"))})
last = s["steps"][-1]["time"]
beyond = [t for t in times if t > last + 1e-12 * max(1.0, abs(last))]
assert any(abs(t - last) <= 1e-12 * max(1.0, abs(last)) for t in times), f"summary.json's last step {last} is not in traces.csv"
if s.get("interrupted_while_writing"):
    # mpiexec killed the ranks while a step's output outlasted the watcher's wait: the summary
    # says so, and that step alone may be in traces.csv.
    assert "while the next step was being written" in s["failure"], s["failure"]
    assert len(beyond) <= 1, f"traces.csv has {len(beyond)} steps after summary.json's last"
else:
    assert not beyond, f"traces.csv ends at {times[-1]}, summary.json at {last}"
if not command.endswith("mpiexec") or ranks:
    assert status == 3, f"exit status {status}, expected 3"
    assert ("stopped: interrupted by " + signal) in open(out + ".stderr").read()
if not command.endswith("mpiexec"):
    assert os.listdir(out + "/checkpoint"), "no checkpoint of the last step"
print(f"interrupted by {signal} after {len(s['steps'])} steps (t = {last}), exit status {status}")
PY
