#!/usr/bin/python3
"""Every script in doc/ (and the bench plotting scripts) answers --help: exit status 0 and an
argparse usage line, no traceback.

  /usr/bin/python3 tests/integration/doc_scripts_help.py DOC_DIR [SCRIPT.py ...] [--python PYTHON]

The plotting scripts are run by hand months apart; a --help that crashes (it once did, for
doc/plot_curves.py) is how a reader first meets them. Exits 1 naming each script that fails,
and if DOC_DIR holds no script (a wrong path must not pass).
"""
import argparse
import glob
import os
import subprocess
import sys

p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
p.add_argument("doc", help="the doc/ directory of the source tree: every *.py in it")
p.add_argument("more", nargs="*", help="further scripts to ask (e.g. bench/incompressibility.py)")
p.add_argument("--python", default=sys.executable, help="the interpreter to run them with (default: this one)")
args = p.parse_args()
in_doc = sorted(glob.glob(os.path.join(args.doc, "*.py")))
scripts = in_doc + args.more
failures = []
for script in scripts:
    done = subprocess.run([args.python, script, "--help"], capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, MPLBACKEND="Agg"))
    ok = done.returncode == 0 and done.stdout.startswith("usage:") and "Traceback" not in done.stderr
    print(("ok   " if ok else "FAIL ") + f"{os.path.basename(script)} --help: exit {done.returncode}")
    if not ok:
        failures.append(script)
        print(done.stdout[-2000:] + done.stderr[-2000:])
if not in_doc:
    print(f"FAIL no scripts in {args.doc}")
    sys.exit(1)
print(f"{len(scripts) - len(failures)} of {len(scripts)} answer --help")
sys.exit(1 if failures else 0)
