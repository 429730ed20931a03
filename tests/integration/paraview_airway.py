"""ParaView opens the airway's section outlines (doc/airway.md) as a time series. Run with Debian's
pvpython under xvfb-run:

  xvfb-run -a pvpython tests/integration/paraview_airway.py RUN_DIR

RUN_DIR: a finished run with an Airway section. The .vtk.series file is opened as one reader; at
every time it lists, the polydata has one closed polyline (cell) per measured section, the cell
arrays area, closed and section, and each cell's area equals that row's area in airway.csv (to
1e-12 relative). Prints the cells and points per time; exit status 1 on any mismatch."""
import csv
import math
import os
import sys

from paraview import servermanager  # noqa: E402
from paraview.simple import OpenDataFile, UpdatePipeline  # noqa: E402

run = sys.argv[1]
reader = OpenDataFile(os.path.join(run, "airway_sections.vtk.series"))
times = list(reader.TimestepValues)
rows = list(csv.reader(open(os.path.join(run, "airway.csv"))))
header = [h.split(" [")[0] for h in rows[0]]
sections = [i for i, h in enumerate(header) if h.startswith("area_")]
failures = 0
if len(times) != len(rows) - 1:
    print(f"FAIL {len(times)} times in the series, {len(rows) - 1} rows in airway.csv")
    failures += 1
for t, row in zip(times, rows[1:]):
    UpdatePipeline(t, reader)
    data = servermanager.Fetch(reader)
    areas = data.GetCellData().GetArray("area")
    section = data.GetCellData().GetArray("section")
    measured = [i for i in sections if not math.isnan(float(row[i]))]
    ok = areas is not None and section is not None and data.GetNumberOfCells() == len(measured)
    if ok:
        for c in range(data.GetNumberOfCells()):
            expected = float(row[sections[int(section.GetValue(c))]])
            ok = ok and abs(areas.GetValue(c) - expected) <= 1e-12 * abs(expected)
    print(("ok  " if ok else "FAIL") + f" t = {t:g}: {data.GetNumberOfCells()} cells, {data.GetNumberOfPoints()} points")
    failures += 0 if ok else 1
sys.exit(1 if failures else 0)
