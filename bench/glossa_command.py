"""The command line of one `glossa run` for the bench scripts: the deck, an output directory,
`--set` overrides, and mpiexec (with the flags this machine needs) on more than one rank; and a run
of it timed in CPU seconds."""
import os
import subprocess
import sys


def glossa_run_command(glossa, deck, out, overrides=(), ranks=1):
    cmd = [glossa, "run", deck, "--output", out, "--quiet"]
    for o in overrides:
        cmd += ["--set", o]
    if ranks > 1:
        cmd = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + cmd
    return cmd


def cpu_seconds_of(cmd, cwd, who):
    """Runs `cmd` (its output discarded) and returns its CPU time, user + system, from the child's
    rusage; exits naming `who` when it fails."""
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=cwd)
    _, status, usage = os.wait4(proc.pid, 0)
    if status != 0:
        sys.exit(f"{who}: {' '.join(cmd)} exited with {status}")
    return usage.ru_utime + usage.ru_stime
