"""ParaView reads Glossa's results as Glossa means them (doc/output.md). Run with Debian's pvpython
under xvfb-run (its build renders through X):

  xvfb-run -a pvpython tests/integration/paraview_readers.py GLOSSA WORKDIR

1. A finished job (the step-44 block, 4 cells per side, to t = 0.2): both of ParaView 5.11's XDMF
   readers, Xdmf3ReaderS and the legacy XDMFReader, give each element's Cauchy stress as the same
   nine components, equal to the data in the last step file (read by h5dump); the tensor is symmetric,
   its mean normal stress is the element pressure Glossa writes beside it, and its yy and xy
   entries differ (so a reader that swapped them would be caught).
2. A running job (uniaxial tension in small steps): both readers open results.xdmf while it runs,
   without HDF5_USE_FILE_LOCKING, and the job goes on to finish with exit status 0.
"""
import json
import os
import subprocess
import sys
import time

os.environ.pop("HDF5_USE_FILE_LOCKING", None)  # the point: no environment variable is needed
from paraview import servermanager  # noqa: E402
from paraview.simple import Delete, XDMFReader, Xdmf3ReaderS  # noqa: E402

GLOSSA, WORK = sys.argv[1], sys.argv[2]
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def read_cells(reader_name, xdmf, array):
    reader = Xdmf3ReaderS(FileName=xdmf) if reader_name == "Xdmf3ReaderS" else XDMFReader(FileNames=[xdmf])
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    reader.UpdatePipeline(times[-1])
    data = servermanager.Fetch(reader)
    while data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    a = data.GetCellData().GetArray(array)
    values = None if a is None else [[a.GetComponent(i, c) for c in range(a.GetNumberOfComponents())]
                                     for i in range(a.GetNumberOfTuples())]
    Delete(reader)
    return times, values


def h5_values(h5, dataset, width):
    out = os.path.join(WORK, "h5dump.txt")
    subprocess.run(["h5dump", "-d", dataset, "-m", "%.17g", "-y", "-w", "0", "-o", out, h5], check=True, stdout=subprocess.DEVNULL)
    numbers = [float(x) for x in open(out).read().replace(",", " ").split()]
    return [numbers[i:i + width] for i in range(0, len(numbers), width)]


# 1. A finished job.
finished = os.path.join(WORK, "finished")
subprocess.run([GLOSSA, "run", os.path.join(ROOT, "inputs", "verification", "step44_block.xml"), "--quiet",
                "--output", finished, "--set", "Mesh/Box/cells=4,4,4", "--set", "Time/end time=0.2"], check=True)
xdmf = os.path.join(finished, "results.xdmf")
steps = len(json.load(open(os.path.join(finished, "summary.json")))["steps"])
last = f"/step_{steps:06d}"  # step 0 is the initial state
last_file = os.path.join(finished, "results_steps", f"step_{steps:06d}.h5")
raw = h5_values(last_file, last + "/cauchy_stress", 9)
pressure = [p[0] for p in h5_values(last_file, last + "/pressure", 1)]
check(len(raw) == 64, f"the last step's file holds 64 stress tensors of 9 components ({len(raw)})")
scale = max(abs(v) for t in raw for v in t)
check(all(abs(t[1] - t[3]) <= 1e-12 * scale and abs(t[2] - t[6]) <= 1e-12 * scale and abs(t[5] - t[7]) <= 1e-12 * scale
          for t in raw), "the stored tensors are symmetric")
check(max(abs((t[0] + t[4] + t[8]) / 3 - p) for t, p in zip(raw, pressure)) <= 1e-8 * scale,
      "the mean normal stress (xx + yy + zz) / 3 of each element is its pressure")
check(max(abs(t[4] - t[1]) for t in raw) > 1e-3 * scale, "yy and xy differ, so a swap would show")
for name in ("Xdmf3ReaderS", "XDMFReader"):
    times, seen = read_cells(name, xdmf, "cauchy_stress")
    check(len(times) == steps + 1, f"{name}: {len(times)} time steps, {steps + 1} written")
    check(seen is not None and len(seen) == len(raw) and all(len(t) == 9 for t in seen),
          f"{name}: cauchy_stress has 9 components per element")
    if seen is not None and len(seen) == len(raw):
        gap = max(abs(a - b) for s, r in zip(seen, raw) for a, b in zip(s, r))
        check(gap <= 1e-12 * scale, f"{name}: every component equals the step file's (largest difference {gap:.3g} Pa)")

# 2. A running job.
running = os.path.join(WORK, "running")
job = subprocess.Popen([GLOSSA, "run", os.path.join(ROOT, "inputs", "verification", "uniaxial_tension.xml"), "--quiet",
                        "--output", running, "--set", "Time/step size=0.002"])
summary = os.path.join(running, "summary.json")
deadline = time.time() + 120
while time.time() < deadline:
    try:
        if len(json.load(open(summary))["steps"]) >= 3:
            break
    except (OSError, ValueError, KeyError):
        pass
    time.sleep(0.1)
for name in ("Xdmf3ReaderS", "XDMFReader"):
    still = job.poll() is None
    times, seen = read_cells(name, os.path.join(running, "results.xdmf"), "cauchy_stress")
    check(still and seen is not None and len(times) >= 3,
          f"{name}: opens the running job's files ({len(times)} steps so far, running: {still})")
check(job.wait(timeout=600) == 0, "the running job goes on and finishes with exit status 0")

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
