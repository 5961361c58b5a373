"""ShapeSplines demo: cubic splines, curvature and torsion of the aorta centerlines and Akima's data.

Run as
    xvfb-run -a pvpython demo.py --plugin ShapeSplines.so --data Data --output DIR

Runs the CubicSpline filter on Data/aorta-centerline.vtp and Data/akima.vtp and
PolylineShapeAnalysis on the same data with the spline as its Curve input, and
writes into DIR (created if missing):
  aorta-cubic.vtp, aorta-analysis.vtp, akima-cubic.vtp, akima-analysis.vtp
  aorta-gencubic.vtp, akima-gencubic.vtp  the shape-preserving generalized cubic
  aorta-variable-degree.vtp, aorta-tension-quintic.vtp, aorta-qqr.vtp
                               the other families on the aorta, at their defaults
  aorta-variable-degree-approximation.vtp, aorta-tension-quintic-approximation.vtp
                               the approximations of the noisy centerline (knots
                               by cross-validation)
  headline.png                 the noisy aorta centerlines as tubes: the cubic
                               spline and the tension quintic approximation
                               coloured by curvature (top left pair) and by
                               torsion (top right pair), each pair on one colour
                               scale set by the approximation; below, Akima's data
                               through the cubic and the shape-preserving
                               generalized cubic
  aorta-curvature-torsion.png  curvature and torsion against arc length along
                               line 0 (two ParaView line charts)
  akima-curvature.png          Akima's data points and polygon, and the cubic
                               coloured by curvature
It prints a summary per line and the absolute path of every file written.
"""
import argparse
import os
import sys
import time

import numpy as np

from paraview import servermanager
from paraview.simple import (AssignViewToLayout, Clip, ColorBy, CreateLayout, CreateView, Delete, ExtractSelection,
                             GetColorTransferFunction, GetScalarBar, IDSelectionSource, LoadPlugin,
                             Render, SaveData, SaveScreenshot, Show, Text, Tube, XMLPolyDataReader)
from vtkmodules.util.numpy_support import vtk_to_numpy

START = time.time()
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--plugin", required=True, help="path of ShapeSplines.so")
parser.add_argument("--data", required=True, help="folder holding aorta-centerline.vtp and akima.vtp")
parser.add_argument("--output", required=True, help="folder for the .vtp and .png files (created if missing)")
args = parser.parse_args()

if not os.path.isfile(args.plugin):
    raise SystemExit("plugin not found: %s" % args.plugin)
output_dir = os.path.abspath(args.output)
os.makedirs(output_dir, exist_ok=True)
LoadPlugin(args.plugin, remote=False, ns=globals())

AKIMA_X_STRETCH = 4.0
written = []


def out_path(name):
    path = os.path.join(output_dir, name)
    written.append(path)
    return path


def reader(name):
    path = os.path.join(args.data, name)
    if not os.path.isfile(path):
        raise SystemExit("data file not found: %s" % path)
    return XMLPolyDataReader(FileName=[path])


def array(data, name, cells=False):
    attributes = data.GetCellData() if cells else data.GetPointData()
    a = attributes.GetArray(name)
    if a is None:
        raise RuntimeError("array %s missing from %s" % (name, data.GetClassName()))
    return vtk_to_numpy(a)


def line_ids(data):
    cells = data.GetLines()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    connectivity = vtk_to_numpy(cells.GetConnectivityArray())
    return [connectivity[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


def white_render_view(width, height):
    view = CreateView("RenderView")
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    return view


def place_parallel_camera(view, bounds, box_x, box_y, width, height, stretch=1.0):
    """Looks down -z with a parallel camera so that bounds (x stretched) fill the pixel box."""
    Render(view)  # paraview.simple resets the camera on a view's first render
    x0, x1, y0, y1, z0, z1 = bounds
    x0, x1 = stretch * x0, stretch * x1
    units_per_pixel = max((x1 - x0) / (box_x[1] - box_x[0]), (y1 - y0) / (box_y[1] - box_y[0]))
    cx = 0.5 * (x0 + x1) + (0.5 * width - 0.5 * sum(box_x)) * units_per_pixel
    cy = 0.5 * (y0 + y1) + (0.5 * height - 0.5 * sum(box_y)) * units_per_pixel
    cz = 0.5 * (z0 + z1)
    view.InteractionMode = "2D"
    view.CameraParallelProjection = 1
    view.CameraFocalPoint = [cx, cy, cz]
    view.CameraPosition = [cx, cy, cz + 10 * (y1 - y0 + x1 - x0 + z1 - z0)]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelScale = 0.5 * height * units_per_pixel
    Render(view)


def style_scalar_bar(bar, title, position, length, fmt, font=16):
    bar.Visibility = 1
    bar.Title = title
    bar.ComponentTitle = ""
    bar.HorizontalTitle = 1
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize = font + 2
    bar.LabelFontSize = font
    bar.WindowLocation = "Any Location"
    bar.Position = position
    bar.ScalarBarLength = length
    bar.ScalarBarThickness = 16
    bar.AutomaticLabelFormat = 0
    bar.LabelFormat = fmt
    bar.RangeLabelFormat = fmt


def show_plain(source, view, representation, color, scale, z, **style):
    """Shows source in one colour (no colour map), scaled, and moved along z so
    that the parallel camera draws it in front of (z > 0) or behind the rest."""
    shown = Show(source, view)
    shown.SetRepresentationType(representation)
    shown.ColorArrayName = [None, ""]
    shown.AmbientColor = shown.DiffuseColor = color
    shown.Scale = scale
    shown.Position = [0.0, 0.0, z]
    for name, value in style.items():
        setattr(shown, name, value)
    return shown


def caption(view, text, size=15):
    shown = Show(Text(Text=text), view)
    shown.WindowLocation = "Upper Left Corner"
    shown.FontSize = size
    shown.Color = [0.0, 0.0, 0.0]
    shown.Justification = "Left"
    return shown


# =========================================================================== filters
results = {}
for key, file_name in (("aorta", "aorta-centerline.vtp"), ("akima", "akima.vtp")):
    src = reader(file_name)
    cubic = CubicSpline(Input=src)  # defaults: Not A Knot, Chord Length, 10 samples per span
    analysis = PolylineShapeAnalysis(Input=src, Curve=cubic)
    analysis.UpdatePipeline()
    SaveData(out_path("%s-cubic.vtp" % key), proxy=cubic)
    SaveData(out_path("%s-analysis.vtp" % key), proxy=analysis)
    # The shape-preserving generalized cubic (automatic exponential tension) on the same data.
    tensioned = GeneralizedCubicSpline(Input=src)
    SaveData(out_path("%s-gencubic.vtp" % key), proxy=tensioned)
    results[key] = (src, cubic, analysis, servermanager.Fetch(src), servermanager.Fetch(cubic),
                    servermanager.Fetch(analysis), servermanager.Fetch(tensioned))

# =========================================================================== summary
aorta_audit = results["aorta"][5]
data_curvature = [array(aorta_audit, "DiscreteCurvature")[ids].max() for ids in line_ids(aorta_audit)]
print("Cubic spline (Not A Knot, Chord Length, 10 samples per span) and its shape audit")
for key, (src, cubic, analysis, data, curve, audit, tensioned) in results.items():
    curvature, torsion = array(curve, "Curvature"), array(curve, "Torsion")
    length, violations = array(curve, "Length", True), array(curve, "ShapeViolations", True)
    seen = array(audit, "ShapeViolations", True)
    data_lines, curve_lines = line_ids(data), line_ids(curve)
    for i, (data_ids, curve_ids) in enumerate(zip(data_lines, curve_lines)):
        k, t = curvature[curve_ids], torsion[curve_ids]
        print("  %s line %d: %d points, %d samples, length %.4g, max curvature %.4g, torsion %.4g .. %.4g "
              "(98th percentile of |torsion| %.4g), ShapeViolations %d (analysis of the output curve: %d)"
              % (key, i, len(data_ids), len(curve_ids), length[i], k.max(), t.min(), t.max(),
                 np.percentile(np.abs(t), 98), violations[i], seen[i]))
print("  (the filter audits its curve at 16 samples per span; PolylineShapeAnalysis sees only the output's "
      "10 per span)")
print("Generalized cubic spline, automatic exponential tension (the shape-preserving family)")
for key, result in results.items():
    tensioned = result[6]
    violations, tension = array(tensioned, "ShapeViolations", True), array(tensioned, "MaxTension", True)
    for i in range(len(violations)):
        print("  %s line %d: ShapeViolations %d (the cubic: %d), largest tension %.4g"
              % (key, i, violations[i], array(result[4], "ShapeViolations", True)[i], tension[i]))

print("Every family on the aorta at its defaults (the automatic shape mode), and the approximations of the")
print("noisy centerline (knots by cross-validation); the data's largest discrete curvature: %s"
      % " / ".join("%.3g" % k for k in data_curvature))
print("  %-32s %-17s %-21s %s" % ("family, mode", "ShapeViolations", "largest curvature", "x the data's"))
aorta_source = results["aorta"][0]
aorta_approximation = TensionQuinticSpline(Input=aorta_source, Mode="Approximate")
aorta_cubic, aorta_tensioned = results["aorta"][4], results["aorta"][6]
for name, proxy in (("cubic (reference)", None),
                    ("generalized cubic, automatic", None),
                    ("variable degree, automatic", VariableDegreeSpline(Input=aorta_source)),
                    ("tension quintic, automatic", TensionQuinticSpline(Input=aorta_source)),
                    ("qqr, automatic", QQRSpline(Input=aorta_source)),
                    ("variable degree, approximation", VariableDegreeSpline(Input=aorta_source,
                                                                            Mode="Approximate Local")),
                    ("tension quintic, approximation", aorta_approximation)):
    if proxy is None:
        fitted = aorta_cubic if name.startswith("cubic") else aorta_tensioned
    else:
        file_name = "aorta-%s.vtp" % name.split(",")[0].replace(" ", "-")
        if "approximation" in name:
            file_name = file_name.replace(".vtp", "-approximation.vtp")
        SaveData(out_path(file_name), proxy=proxy)
        fitted = servermanager.Fetch(proxy)
    violations, curvature = array(fitted, "ShapeViolations", True), array(fitted, "Curvature")
    largest = [curvature[ids].max() for ids in line_ids(fitted)]
    print("  %-32s %-17s %-21s %s" % (name, " / ".join("%d" % v for v in violations),
                                      " / ".join("%.3g" % k for k in largest),
                                      " / ".join("%.3g" % (k / d) for k, d in zip(largest, data_curvature))))
print("  (approximations are audited against their least-squares polygon, not the noisy points; the automatic")
print("  modes may not raise the curvature beyond 1e3 (1e4 with straight runs) x the data's, nor to a cusp (1e6")
print("  over the line's bounding box diagonal): where a family cannot remove a violation within that, it keeps")
print("  its best curve and counts what is left)")

# =========================================================================== aorta-curvature-torsion.png
# (Made before the render views: after a render view's screenshot, the charts in
# this layout came out with their axis labels cut by the axis titles.)
src, cubic, analysis, data, curve, audit, _ = results["aorta"]
line0 = ExtractSelection(Input=cubic, Selection=IDSelectionSource(IDs=[0, 0], FieldType="CELL"))
line0.UpdatePipeline()
line0_data = servermanager.Fetch(line0)
arc = array(line0_data, "ArcLength")
k0, t0 = array(line0_data, "Curvature"), array(line0_data, "Torsion")
k_top = float(np.percentile(k0, 99.5) * 1.2)
t_lim = float(np.percentile(np.abs(t0), 98))
layout = CreateLayout("aorta line 0")
curvature_view = CreateView("XYChartView")
torsion_view = CreateView("XYChartView")
AssignViewToLayout(curvature_view, layout, 0)
layout.SplitVertical(0, 0.5)
AssignViewToLayout(curvature_view, layout, 1)
AssignViewToLayout(torsion_view, layout, 2)
charts = (
    (curvature_view, "Curvature", [0.0, k_top], ["0.1", "0.25", "0.8"],
     "Curvature along aorta line 0 (cubic spline; axis cut at %.3g, max %.3g at s = %.1f)"
     % (k_top, k0.max(), arc[np.argmax(k0)])),
    (torsion_view, "Torsion", [-t_lim, t_lim], ["0.8", "0.1", "0.1"],
     "Torsion along aorta line 0 (axis cut at +-%.3g, the 98th percentile of the absolute torsion; "
     "extremes %.3g and %.3g)"
     % (t_lim, t0.min(), t0.max())),
)
for chart, name, axis_range, color, title in charts:
    series = Show(line0, chart)
    series.UseIndexForXAxis = 0
    series.XArrayName = "ArcLength"
    series.SeriesVisibility = [name]
    series.SeriesColor = [name] + color
    series.SeriesLineThickness = [name, "2"]
    chart.ShowLegend = 0
    chart.ChartTitle = title
    chart.LeftAxisTitle = name
    chart.BottomAxisTitle = "Arc length along line 0"
    chart.LeftAxisUseCustomRange = 1
    chart.LeftAxisRangeMinimum, chart.LeftAxisRangeMaximum = axis_range
layout.SetSize(1000, 700)
Render(curvature_view)
Render(torsion_view)
SaveScreenshot(out_path("aorta-curvature-torsion.png"), layout, ImageResolution=[1000, 700])

# =========================================================================== headline.png
# The noisy aorta as users want it: the approximation's curvature and torsion next
# to the cubic's, on one colour scale per quantity (set by the approximation, so
# the cubic's noise spikes saturate), and the Akima data through the
# shape-preserving generalized cubic next to the cubic's overshoot.
src, cubic, analysis, data, curve, audit, tensioned = results["aorta"]
smooth = servermanager.Fetch(aorta_approximation)
k_limit = float(np.percentile(array(smooth, "Curvature"), 99))
t_limit = float(np.percentile(np.abs(array(smooth, "Torsion")), 98))
W, H = 1400, 1000
AORTA_H = 700
layout = CreateLayout("headline")
layout.SplitVertical(0, AORTA_H / H)  # 1: the aorta row, 2: the Akima row
layout.SplitHorizontal(1, 0.5)  # 3: curvature pair, 4: torsion pair
layout.SplitHorizontal(3, 0.5)
layout.SplitHorizontal(4, 0.5)
layout.SplitHorizontal(2, 0.5)
aorta_w = W // 4


def aorta_panel(cell, proxy, fitted, name, limits, preset, title, with_bar):
    view = white_render_view(aorta_w, AORTA_H)
    AssignViewToLayout(view, layout, cell)
    tube_display = Show(Tube(Input=proxy, Radius=0.6, NumberofSides=16), view)
    ColorBy(tube_display, ("POINTS", name))
    lut = GetColorTransferFunction(name)
    lut.ApplyPreset(preset, True)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(*limits)
    values = array(fitted, name)
    beyond = 100.0 * np.mean((values < limits[0]) | (values > limits[1]))
    caption(view, "%s\n%s %.3g .. %.3g\n(%.0f%% of samples beyond the scale)"
            % (title, name.lower(), values.min(), values.max(), beyond), size=13)
    if with_bar:
        style_scalar_bar(GetScalarBar(lut, view), name, [0.78, 0.08], 0.35, "%-#.2f", font=13)
    place_parallel_camera(view, curve.GetBounds(), (20, aorta_w - 90), (20, AORTA_H - 110), aorta_w, AORTA_H)
    return view


views = [aorta_panel(7, cubic, curve, "Curvature", (0.0, k_limit), "Turbo", "Aorta: cubic spline", False),
         aorta_panel(8, aorta_approximation, smooth, "Curvature", (0.0, k_limit), "Turbo",
                     "Aorta: tension quintic,\nMode Approximate", True),
         aorta_panel(9, cubic, curve, "Torsion", (-t_limit, t_limit), "Cool to Warm", "Aorta: cubic spline",
                     False),
         aorta_panel(10, aorta_approximation, smooth, "Torsion", (-t_limit, t_limit), "Cool to Warm",
                     "Aorta: tension quintic,\nMode Approximate", True)]

akima_src, akima_cubic, _, _, akima_curve, akima_audit, akima_tensioned = results["akima"]
akima_w, akima_h = W // 2, H - AORTA_H
# Akima's flat run y = 10 and the start of the rise, y exaggerated: the cubic's
# undershoot (0.08 below the run) and ripples show; the shape-preserving curve stays flat.
zoom_x, zoom_y = (0.0, 10.5), (9.85, 10.6)
akima_scale = [30.0, 300.0, 1.0]
zoom_bounds = [zoom_x[0] * akima_scale[0], zoom_x[1] * akima_scale[0],
               zoom_y[0] * akima_scale[1], zoom_y[1] * akima_scale[1], 0.0, 0.0]


def below_zoom(proxy):
    clip = Clip(Input=proxy, ClipType="Plane", Invert=1)
    clip.ClipType.Origin = [0.0, zoom_y[1], 0.0]
    clip.ClipType.Normal = [0.0, 1.0, 0.0]
    return clip


for cell, proxy, fitted, title in (
        (5, akima_cubic, akima_curve, "Akima's data: cubic spline"),
        (6, GeneralizedCubicSpline(Input=akima_src), akima_tensioned,
         "Akima's data: generalized cubic, automatic tension (shape-preserving)")):
    view = white_render_view(akima_w, akima_h)
    AssignViewToLayout(view, layout, cell)
    # Cut above the zoom so the rise does not run through the caption.
    show_plain(below_zoom(reader("akima.vtp")), view, "Wireframe", [0.7, 0.7, 0.7], akima_scale, -20.0,
               LineWidth=2.0)
    show_plain(below_zoom(proxy), view, "Surface", [0.1, 0.3, 0.8], akima_scale, 0.0, LineWidth=4.0,
               Ambient=1.0, Diffuse=0.0)
    show_plain(akima_src, view, "Points", [0.9, 0.0, 0.9], akima_scale, 20.0, PointSize=12.0,
               RenderPointsAsSpheres=1)
    lowest = vtk_to_numpy(fitted.GetPoints().GetData())[:, 1].min()
    caption(view, "%s: ShapeViolations %d\nthe data never go below y = 10; the curve goes down to y = %.3f\n"
                  "(zoom on x 0 .. 10.5, y 9.85 .. 10.6, y drawn 10x more than x; magenta: data)"
            % (title, array(fitted, "ShapeViolations", True)[0], lowest), size=13)
    place_parallel_camera(view, zoom_bounds, (20, akima_w - 20), (10, akima_h - 75), akima_w, akima_h)
    views.append(view)
layout.SetSize(W, H)
for view in views:
    Render(view)
SaveScreenshot(out_path("headline.png"), layout, ImageResolution=[W, H])
print("headline.png: curvature scale 0 .. %.3g (99th percentile of the approximation's), torsion +-%.3g "
      "(98th percentile of its |torsion|)" % (k_limit, t_limit))

# =========================================================================== akima-curvature.png
src, cubic, analysis, data, curve, audit, _ = results["akima"]
fine = CubicSpline(Input=src, NumberOfSubdivisions=20)
fine.UpdatePipeline()
fine_curve = servermanager.Fetch(fine)
W, H = 800, 600
view = white_render_view(W, H)
stretch = [AKIMA_X_STRETCH, 1.0, 1.0]
# A second reader: Show gives one representation per source.
show_plain(reader("akima.vtp"), view, "Wireframe", [0.6, 0.6, 0.6], stretch, -20.0, LineWidth=2.0)
line = Show(fine, view)
ColorBy(line, ("POINTS", "Curvature"))
lut = GetColorTransferFunction("Curvature")
lut.ApplyPreset("Turbo", True)
lut.AutomaticRescaleRangeMode = "Never"
lut.RescaleTransferFunction(0.0, 0.5)
line.LineWidth = 6.0
line.Ambient, line.Diffuse = 1.0, 0.0  # unlit: the colours are the colour map's
line.Scale = stretch
show_plain(src, view, "Points", [0.9, 0.0, 0.9], stretch, 20.0, PointSize=14.0, RenderPointsAsSpheres=1)
bar = GetScalarBar(lut, view)
style_scalar_bar(bar, "Curvature", [0.86, 0.15], 0.65, "%-#.1f", font=15)
bar.UseCustomLabels = 1
bar.CustomLabels = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5]
bar.AddRangeLabels = 0
violations = array(audit, "ShapeViolations", True)[0]
criteria = [(int(array(audit, name + "Violations", True)[0]), text) for name, text in (
    ("Collinearity", "collinearity (the flat run y = 10 is not kept straight)"),
    ("ConvexityAtKnot", "convexity at a data point"), ("ConvexityOnSpan", "convexity on a span"),
    ("Coplanarity", "coplanarity"), ("TorsionSignAtKnot", "torsion sign at a data point"),
    ("TorsionSignOnSpan", "torsion sign on a span"))]
caption(view, "Akima's data (magenta) and the cubic spline through them, coloured by curvature\n"
              "(x stretched %gx; grey: the data polygon). ShapeViolations = %d:\n%s"
        % (AKIMA_X_STRETCH, violations, ", ".join("%d %s" % c for c in criteria if c[0] > 0)), size=14)
place_parallel_camera(view, fine_curve.GetBounds(), (40, 640), (30, 510), W, H, stretch=AKIMA_X_STRETCH)
SaveScreenshot(out_path("akima-curvature.png"), view, ImageResolution=[W, H])

# =========================================================================== files
missing = [p for p in written if not os.path.isfile(p) or os.path.getsize(p) == 0]
if missing:
    raise SystemExit("not written: %s" % missing)
print("Files written (%.1f s):" % (time.time() - START))
for path in written:
    print("  " + path)
