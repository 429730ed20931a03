"""Render a run's deformed geometry coloured by one of its fields (the look of the paper's Figs. 8
and 10), with ParaView (Debian's pvpython; its build renders through X, hence xvfb-run):

  xvfb-run -a pvpython doc/render_tongue.py RESULTS_DIR OUT.png [--field fibre_stretch_GGm]
                                            [--time T] [--range MIN MAX] [--cut | --no-cut]
                                            [--view side | above]

Reads RESULTS_DIR/results.xdmf (the run needs Output/fields on), takes the last step (or the
one at --time), moves every node by its displacement and colours the mesh by --field: a cell
field glossa writes (fibre_stretch_<group>, contractile_stretch_<group>, ffmr_<group>, J,
dilatation, pressure, ...), a scalar node field (contact_pressure, drawn in kPa; contact_gap) or
'displacement' (its magnitude, mm; the default). A field of one
muscle group is drawn on that group's elements only (muscle_set_<group> = 1), opaque, inside the
rest of the tongue drawn as a translucent grey shell. --cut cuts the mesh at the midsagittal
plane (the plane halfway across y, whole elements) and shows the cut face. The colour range is
the 2nd to 98th percentile of the values drawn (a stretch: symmetric about 1) unless --range.
The camera faces the sagittal plane (+x posterior to the right, +z superior up), or with
--view above looks down on the dorsum (+x posterior to the right, +y up). The title
names the run's deck and scene.
"""
import argparse
import os
import sys

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)


def parse(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("results", help="the run's output directory (results.xdmf, results.h5, results_steps/, summary.json)")
    p.add_argument("png", help="the picture to write")
    p.add_argument("--field", default="displacement",
                   help="cell field to colour by, or 'displacement' for its magnitude (default)")
    p.add_argument("--time", type=float, help="the step nearest this time [s] (default: the last)")
    p.add_argument("--range", nargs=2, type=float, metavar=("MIN", "MAX"),
                   help="colour range (default: the data's; stretches symmetric about 1)")
    cut = p.add_mutually_exclusive_group()
    cut.add_argument("--cut", dest="cut", action="store_true", default=None,
                     help="cut at the midsagittal plane (whole elements) and show the cut face")
    cut.add_argument("--no-cut", dest="cut", action="store_false", help="draw the whole mesh (default)")
    p.add_argument("--view", choices=("side", "above"), default="side",
                   help="side: the sagittal plane from -y (default); above: the dorsum from +z")
    p.add_argument("--size", nargs=2, type=int, default=(1400, 900), metavar=("W", "H"), help="pixels")
    return p.parse_args(argv)


def group_of(field, cell_fields):
    """The muscle group a per-group field belongs to ('GGm' of fibre_stretch_GGm), if the run
    wrote its element set; None for a field of the whole mesh."""
    for name in cell_fields:
        if name.startswith("muscle_set_"):
            group = name[len("muscle_set_"):]
            if field.endswith("_" + group) and field != name:
                return group
    return None


def colour_range(values, field, requested):
    """The colour bar's range: the 2nd to 98th percentile of the values drawn (a few distorted
    elements would otherwise wash the rest out to one colour), a stretch (1 = rest length)
    symmetric about 1 so that shortening and lengthening read alike on a diverging map."""
    if requested:
        return tuple(requested)
    low, high = (float(v) for v in numpy.percentile(values, [2.0, 98.0]))
    if "stretch" in field:
        half = max(abs(low - 1.0), abs(high - 1.0), 1e-6)
        return 1.0 - half, 1.0 + half
    if high <= low:
        high = low + 1e-12
    return low, high


def values_of(source, array, association):
    """The array's values on the filter's output (cells or points), as numpy."""
    from paraview import servermanager
    from vtk.numpy_interface import dataset_adapter as dsa
    data = servermanager.Fetch(source)
    while data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    wrapped = dsa.WrapDataObject(data)
    return numpy.asarray((wrapped.PointData if association == "POINTS" else wrapped.CellData)[array])


def main(argv):
    args = parse(argv)
    xdmf = os.path.join(args.results, "results.xdmf")
    if not os.path.exists(xdmf):
        sys.exit(f"{xdmf}: no such file (was the run made with Output/fields=true?)")
    from paraview import simple as pv
    import plot_style  # the run's title, shared with the matplotlib plots

    reader = pv.Xdmf3ReaderS(FileName=xdmf)
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    time = times[-1] if args.time is None else min(times, key=lambda t: abs(t - args.time))
    reader.UpdatePipeline(time)
    cell_fields = list(reader.CellData.keys())
    point_fields = [f for f in reader.PointData.keys() if f != "displacement"]
    if args.field != "displacement" and args.field not in cell_fields + point_fields:
        sys.exit(f"no field '{args.field}' in {xdmf}; it has: displacement, " + ", ".join(cell_fields + point_fields))
    group = group_of(args.field, cell_fields)
    cut = bool(args.cut)

    warped = pv.WarpByVector(Input=reader, Vectors=["POINTS", "displacement"], ScaleFactor=1.0)
    shape = warped
    if cut:
        (x0, x1, y0, y1, z0, z1) = reader.GetDataInformation().GetBounds()
        # Whole cells (crinkle) keep their colour; the half nearer the camera (y < mid) goes.
        shape = pv.Clip(Input=warped, ClipType="Plane", Crinkleclip=1, Invert=0)
        shape.ClipType.Origin = [0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1)]
        shape.ClipType.Normal = [0.0, -1.0, 0.0]
    coloured = shape
    if group:
        coloured = pv.Threshold(Input=shape, Scalars=["CELLS", f"muscle_set_{group}"],
                                LowerThreshold=0.5, UpperThreshold=1.5)
    if args.field == "displacement":
        # In mm: the tongue moves millimetres, and metres on the bar would read 0.00x.
        coloured = pv.Calculator(Input=coloured, AttributeType="Point Data", ResultArrayName="displacement_mm",
                                 Function="mag(displacement)*1000")
        array, association, bar_title = "displacement_mm", "POINTS", "|u| [mm]"
    elif args.field == "contact_pressure":
        # In kPa, the unit tongue-palate pressures are measured and reported in.
        coloured = pv.Calculator(Input=coloured, AttributeType="Point Data", ResultArrayName="contact_pressure_kPa",
                                 Function="contact_pressure/1000")
        array, association, bar_title = "contact_pressure_kPa", "POINTS", "contact pressure [kPa]"
    elif args.field in point_fields:
        array, association, bar_title = args.field, "POINTS", args.field
    else:
        array, association, bar_title = args.field, "CELLS", args.field
    coloured.UpdatePipeline(time)
    data = coloured.PointData if association == "POINTS" else coloured.CellData
    if array not in data.keys() or coloured.GetDataInformation().GetNumberOfCells() == 0:
        sys.exit(f"'{args.field}': nothing to draw (no elements of group {group}?)")
    values = values_of(coloured, array, association)
    low, high = colour_range(values, args.field, args.range)
    print(f"{array}: {values.size} values in [{values.min():.4g}, {values.max():.4g}]; colours over [{low:.4g}, {high:.4g}]")

    view = pv.GetActiveViewOrCreate("RenderView")
    view.ViewSize = list(args.size)
    view.ViewTime = time  # the view draws its own time (0 unless told), not the pipeline's
    view.UseColorPaletteForBackground = 0  # else the palette's blue-grey wins over Background
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 1
    view.OrientationAxesLabelColor = [0.2, 0.2, 0.2]
    if group:
        # The elements outside the group, a translucent grey shell: the group's elements lie
        # inside the tongue (left and right of the septum, so a midsagittal cut misses them).
        rest = pv.Threshold(Input=shape, Scalars=["CELLS", f"muscle_set_{group}"], LowerThreshold=0.5,
                            ThresholdMethod="Below Lower Threshold")
        shown_rest = pv.Show(rest, view)
        pv.ColorBy(shown_rest, None)
        shown_rest.AmbientColor = shown_rest.DiffuseColor = [0.75, 0.75, 0.75]
        shown_rest.Opacity = 1.0 if cut else 0.22
    display = pv.Show(coloured, view)
    pv.ColorBy(display, (association, array))
    lut = pv.GetColorTransferFunction(array)
    lut.ApplyPreset("Cool to Warm" if "stretch" in args.field else "Viridis (matplotlib)", True)
    lut.RescaleTransferFunction(low, high)
    lut.AutomaticRescaleRangeMode = "Never"
    pv.GetOpacityTransferFunction(array).RescaleTransferFunction(low, high)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = bar_title
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    bar.TitleFontSize = bar.LabelFontSize = 18
    bar.RangeLabelFormat = "%-#.3g"
    bar.Visibility = 1
    display.SetScalarBarVisibility(view, True)

    what = "|displacement|" if args.field == "displacement" else args.field
    what += f" on {group}'s elements" if group else ""
    where = ", cut at the midsagittal plane" if cut else ""
    title = pv.Text(Text=f"{plot_style.run_title(args.results)}\n{what} at t = {time:g} s, on the deformed mesh{where}")
    shown = pv.Show(title, view)
    shown.Color = [0.1, 0.1, 0.1]
    shown.FontSize = 20
    shown.WindowLocation = "Upper Center"

    if args.view == "above":
        # Looking down on the dorsum from +z: +x (posterior) to the right, +y (the right side) up.
        view.CameraPosition = [0.0, 0.0, 1.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
    else:
        # Facing the sagittal plane from -y: +x (posterior) to the right, +z (superior) up.
        view.CameraPosition = [0.0, -1.0, 0.0]
        view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraParallelProjection = 1
    view.ResetCamera()
    view.CameraParallelScale *= 0.8
    pv.Render(view)
    pv.SaveScreenshot(args.png, view, ImageResolution=list(args.size), TransparentBackground=0)
    print("wrote", args.png)


if __name__ == "__main__":
    main(sys.argv[1:])
