#!/usr/bin/env bash
# kill_and_restart.sh OUT K COMMAND...: COMMAND is a glossa run (perhaps under mpiexec) that writes a
# checkpoint every few steps. Runs it uninterrupted into OUT/whole; runs it again into OUT/killed
# and, once its latest checkpoint is after step K and a step more is on disk, kills every
# rank with SIGKILL (nothing is flushed or cleaned up; STOP_SIGNAL=TERM sends SIGTERM instead,
# after which the run writes a checkpoint of its last step); restarts it with --restart OUT/killed.
# Passes when the restarted run converged and its traces.csv, reactions.csv, activation.csv, contact.csv, energy.csv,
# airway.csv, airflow.csv and
# controls.csv (those the run writes) are byte for byte the uninterrupted run's, summary.json
# lists the same steps (times, Newton, Krylov and Uzawa counts, control inputs), results.xdmf
# the same field steps, and the summary records the restart.
out=$1 after=$2
shift 2
rm -rf "$out" && mkdir -p "$out"
"$@" --output "$out/whole" --quiet >"$out/whole.log" 2>&1 || { echo "the uninterrupted run failed"; cat "$out/whole.log"; exit 1; }

"$@" --output "$out/killed" --quiet >"$out/killed.log" 2>&1 &
job=$!
checkpoint() { sed -n 's/^step_0*\([0-9][0-9]*\)$/\1/p' "$out/killed/checkpoint/latest" 2>/dev/null || true; }
steps() { /usr/bin/python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['steps']))" "$out/killed/summary.json" 2>/dev/null || echo 0; }
for _ in $(seq 1 3000); do
  c=$(checkpoint)
  if [ -n "$c" ] && [ "$c" -ge "$after" ] && [ "$(steps)" -ge $((c + 1)) ]; then break; fi
  kill -0 $job 2>/dev/null || { echo "the run ended before it could be killed"; cat "$out/killed.log"; exit 1; }
  sleep 0.02
done
# Every rank at once (under mpiexec the ranks are its children; killing mpiexec alone could leave them running).
pkill -"${STOP_SIGNAL:-KILL}" -f -- "--output $out/killed" || true
wait $job 2>/dev/null
for _ in $(seq 1 300); do pgrep -f -- "--output $out/killed" >/dev/null || break; sleep 0.1; done
echo "killed after $(steps) steps on disk, the latest checkpoint after step $(checkpoint)"

"$@" --restart "$out/killed" --quiet >"$out/restart.log" 2>&1 || { echo "the restarted run failed"; cat "$out/restart.log"; exit 1; }

status=0
for f in traces.csv reactions.csv activation.csv controls.csv resultants.csv volumes.csv contact.csv energy.csv airway.csv airflow.csv; do
  [ -f "$out/whole/$f" ] || continue
  if cmp -s "$out/whole/$f" "$out/killed/$f"; then echo "$f: identical"; else echo "$f differs"; diff "$out/whole/$f" "$out/killed/$f" | head -5; status=1; fi
done
/usr/bin/python3 - "$out/whole" "$out/killed" <<'PY' || status=1
import json, re, sys
a, b = (json.load(open(d + "/summary.json")) for d in sys.argv[1:3])
assert b["converged"] is True and b["running"] is False, (b["converged"], b.get("failure"))
assert len(b.get("restarts", [])) == 1, b.get("restarts")
keys = ["time", "dt", "newton_iterations", "linear_iterations", "uzawa_iterations", "max_dilatation_error", "control"]
assert len(a["steps"]) == len(b["steps"]), (len(a["steps"]), len(b["steps"]))
for k, (x, y) in enumerate(zip(a["steps"], b["steps"])):
    for key in keys:
        assert x.get(key) == y.get(key), f"step {k + 1}: {key} {x.get(key)} != {y.get(key)}"
assert a["final_displacement"] == b["final_displacement"]
grids = [len(re.findall(r"<Grid Name=\"step", open(d + "/results.xdmf").read())) for d in sys.argv[1:3]]
assert grids[0] == grids[1], f"results.xdmf: {grids[0]} and {grids[1]} field steps"
print(f"{len(b['steps'])} steps, restarted after step {b['restarts'][0]['after_step']}: the same as the uninterrupted run")
PY
exit $status
