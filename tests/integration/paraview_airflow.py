"""ParaView shows the airflow's pressure on the airway faces (doc/airflow.md, "Output"). Run with
Debian's pvpython under xvfb-run:

  xvfb-run -a pvpython tests/integration/paraview_airflow.py RUN_DIR

RUN_DIR: a finished run of inputs/verification/airflow_collapsible_channel.xml with its fields.
results.xdmf, opened with Xdmf3ReaderS at its last time, must carry the point array
airflow_pressure: 0 at every node below the block's top (no airway face there), and on the top
within the range of that step's section pressures in airflow.csv (the faces' pressures are
interpolated between the sections'), its most negative value within 5 % of the most negative
section pressure. Exit status 1 on any mismatch."""
import csv
import os
import sys

from paraview import servermanager  # noqa: E402
from paraview.simple import Xdmf3ReaderS  # noqa: E402

run = sys.argv[1]
reader = Xdmf3ReaderS(FileName=os.path.join(run, "results.xdmf"))
times = list(reader.TimestepValues)
reader.UpdatePipeline(times[-1])
data = servermanager.Fetch(reader)
while data.IsA("vtkMultiBlockDataSet"):
    data = data.GetBlock(0)
array = data.GetPointData().GetArray("airflow_pressure")
if array is None:
    print("FAIL no point array airflow_pressure")
    sys.exit(1)
rows = list(csv.reader(open(os.path.join(run, "airflow.csv"))))
header = [h.split(" [")[0] for h in rows[0]]
last = rows[-1]
sections = [float(last[i]) for i, h in enumerate(header) if h.startswith("pressure_")]
low, high = min(sections), max(sections)
top = max(data.GetPoint(i)[2] for i in range(data.GetNumberOfPoints()))
on_top = [array.GetValue(i) for i in range(data.GetNumberOfPoints()) if data.GetPoint(i)[2] > top - 1e-9]
below = [array.GetValue(i) for i in range(data.GetNumberOfPoints()) if data.GetPoint(i)[2] <= top - 1e-9]
# The deformed top is not flat: the reader gives reference coordinates, so "top" is z = 10 mm.
checks = [
    (all(v == 0.0 for v in below), f"0 below the top ({len(below)} nodes)"),
    (all(low - 1e-9 <= v <= high + 1e-9 for v in on_top),
     f"the top's {len(on_top)} nodes within [{low:.3f}, {high:.3f}] Pa"),
    (abs(min(on_top) - low) <= 0.05 * abs(low), f"its most negative {min(on_top):.3f} Pa near {low:.3f} Pa"),
]
for ok, what in checks:
    print(("ok   " if ok else "FAIL ") + what)
sys.exit(0 if all(ok for ok, _ in checks) else 1)
