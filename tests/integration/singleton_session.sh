#!/usr/bin/env bash
# singleton_session.sh GLOSSA DECK: an isolated singleton (OMPI_MCA_ess_singleton_isolated=1, no
# mpiexec) keeps Open MPI's session directory under a base of its own, <TMPDIR>/glossa-ompi-<pid>
# (src/app/SingletonSession.hpp), not in the one every isolated singleton shares, and removes that
# base when it ends. Passes when the session directory is seen there while the run goes on, the
# run succeeds, and nothing of it is left.
glossa=$1 deck=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
TMPDIR=$dir OMPI_MCA_ess_singleton_isolated=1 "$glossa" run "$deck" --quiet --output "$dir/out" \
  --set "Time/step size=0.0005" --set "Time/end time=0.02" > "$dir/stdout" 2> "$dir/stderr" &
pid=$!
seen=""
for _ in $(seq 1 400); do
  if compgen -G "$dir/glossa-ompi-$pid/ompi.*" > /dev/null; then seen=yes; break; fi
  kill -0 $pid 2> /dev/null || break
  sleep 0.02
done
wait $pid
status=$?
cat "$dir/stderr"
[ $status -eq 0 ] || { echo "the run failed (exit status $status)"; exit 1; }
[ -n "$seen" ] || { echo "no session directory under $dir/glossa-ompi-$pid:"; ls -R "$dir" | head -20; exit 1; }
[ ! -e "$dir/glossa-ompi-$pid" ] || { echo "$dir/glossa-ompi-$pid is left after the run"; exit 1; }
if compgen -G "$dir/ompi.*" > /dev/null; then echo "a shared session directory was made in $dir"; exit 1; fi
echo "session directory under glossa-ompi-$pid while running, removed at the end"
