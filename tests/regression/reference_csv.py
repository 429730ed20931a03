"""What the regression scripts that compare one of a run's CSV files with a stored reference share:
their command line (REFERENCE.csv RUN_DIR [--tolerance T]) and reading the reference and the
run's file, each into its column names (units dropped) and rows keyed by them."""
import csv
import sys


def arguments(argv, doc):
    """(reference, run directory, tolerance), or None after printing `doc` for a wrong command line."""
    if len(argv) not in (3, 5) or (len(argv) == 5 and argv[3] != "--tolerance"):
        print(doc, file=sys.stderr)
        return None
    return argv[1], argv[2], float(argv[4]) if len(argv) == 5 else 1e-6


def load(reference, run_dir, name, tool):
    """The reference's and the run's RUN_DIR/name as read() gives them, or None after saying why."""
    try:
        return read(reference) + read(run_dir + "/" + name)
    except (OSError, IndexError) as e:
        print(f"{tool}: {e}", file=sys.stderr)
        return None


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header = [h.split(" [")[0] for h in rows[0]]
    return header, [dict(zip(header, r)) for r in rows[1:] if r]
