"""pvpython image test: the CubicSpline proxy rendered on Akima's data.

Run as
    xvfb-run -a pvpython TestPluginImage.py --plugin ShapeSplines.so --data Data \
        --baseline Testing/Data/Baseline --temp <build>/Testing/Temporary

Shows Akima's data points (magenta), their polygon (thin grey) and the cubic
spline through them (NumberOfSubdivisions 20) as a thick line coloured by
Curvature (Turbo, fixed range 0..0.5, scalar bar), in a 400x300 render view with
a white background, looking at the z = 0 plane with a parallel camera fitted to
the data. The data span 16 x 75 units, so x is drawn stretched 4 times (the
caption says so) to show the flat run and the rise side by side.

The window is compared with <baseline>/TestPluginImageAkimaCubic.png by
paraview.vtk.test.Testing.compareImage (threshold 10). The image produced is
always written to <temp>/TestPluginImageAkimaCubic.png; on a mismatch
compareImage also writes .diff.png and .valid.png there. A missing baseline is a
failure: inspect the produced image, then copy it to Testing/Data/Baseline.
"""
import argparse
import os
import sys
import time

from paraview import servermanager
from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction, GetScalarBar, LoadPlugin, Render,
                             Show, Text, XMLPolyDataReader)
from paraview.vtk.test import Testing
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

BASELINE_NAME = "TestPluginImageAkimaCubic.png"
WIDTH, HEIGHT = 400, 300
X_STRETCH = 4.0
CURVATURE_RANGE = (0.0, 0.5)  # Akima's cubic peaks at 0.454

START = time.time()
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--plugin", required=True, help="path of ShapeSplines.so")
parser.add_argument("--data", required=True, help="folder holding akima.vtp")
parser.add_argument("--baseline", required=True, help="folder holding %s" % BASELINE_NAME)
parser.add_argument("--temp", required=True, help="folder for the produced image (not the baseline folder)")
args = parser.parse_args()

baseline_dir = os.path.realpath(args.baseline)
temp_dir = os.path.realpath(args.temp)
if temp_dir == baseline_dir:
    # compareImage writes the test image as <temp>/<baseline name>: it would
    # overwrite the baseline and the test could never fail again.
    raise SystemExit("--temp must differ from --baseline (%s)" % baseline_dir)
os.makedirs(temp_dir, exist_ok=True)
baseline_path = os.path.join(baseline_dir, BASELINE_NAME)
produced_path = os.path.join(temp_dir, BASELINE_NAME)
data_path = os.path.join(args.data, "akima.vtp")
if not os.path.isfile(args.plugin):
    raise SystemExit("plugin not found: %s" % args.plugin)
if not os.path.isfile(data_path):
    raise SystemExit("data file not found: %s" % data_path)

LoadPlugin(args.plugin, remote=False, ns=globals())

# --------------------------------------------------------------------------- pipeline
data = XMLPolyDataReader(FileName=[data_path])
spline = CubicSpline(Input=data, NumberOfSubdivisions=20)
spline.UpdatePipeline()
curve = servermanager.Fetch(spline)
curvature = curve.GetPointData().GetArray("Curvature")
assert curve.GetNumberOfPoints() == 10 * 20 + 1, curve.GetNumberOfPoints()
assert curvature is not None, "CubicSpline output has no Curvature"

# --------------------------------------------------------------------------- scene
view = CreateView("RenderView")
view.ViewSize = [WIDTH, HEIGHT]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]
view.EnableRenderOnInteraction = 0

stretch = [X_STRETCH, 1.0, 1.0]
# Draw order along z (parallel camera: no size change): polygon, curve, points.
# (Show returns the one representation a source has in a view: the polygon needs
# its own reader.)
polygon = Show(XMLPolyDataReader(FileName=[data_path]), view)
polygon.SetRepresentationType("Wireframe")
polygon.ColorArrayName = [None, ""]
polygon.AmbientColor = polygon.DiffuseColor = [0.6, 0.6, 0.6]
polygon.LineWidth = 1.5
polygon.Scale = stretch
polygon.Position = [0.0, 0.0, -20.0]

line = Show(spline, view)
line.SetRepresentationType("Surface")
ColorBy(line, ("POINTS", "Curvature"))
lut = GetColorTransferFunction("Curvature")
lut.ApplyPreset("Turbo", True)
lut.AutomaticRescaleRangeMode = "Never"
lut.RescaleTransferFunction(*CURVATURE_RANGE)
line.LineWidth = 4.0
# Unlit, so the colours are exactly the colour map's.
line.Ambient = 1.0
line.Diffuse = 0.0
line.Scale = stretch

points = Show(data, view)
points.SetRepresentationType("Points")
points.ColorArrayName = [None, ""]
points.AmbientColor = points.DiffuseColor = [0.9, 0.0, 0.9]
points.PointSize = 10.0
points.RenderPointsAsSpheres = 1
points.Scale = stretch
points.Position = [0.0, 0.0, 20.0]

bar = GetScalarBar(lut, view)
bar.Visibility = 1
bar.Title = "Curvature"
bar.ComponentTitle = ""
bar.HorizontalTitle = 1
bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
bar.TitleFontSize = 14
bar.LabelFontSize = 13
bar.WindowLocation = "Any Location"
bar.Position = [0.81, 0.12]
bar.ScalarBarLength = 0.7
bar.ScalarBarThickness = 12
bar.AutomaticLabelFormat = 0
bar.LabelFormat = "%-#.1f"
bar.AddRangeLabels = 0

caption = Show(Text(Text="Cubic spline through Akima's data\n(x stretched %gx)" % X_STRETCH), view)
caption.WindowLocation = "Upper Left Corner"
caption.FontSize = 13
caption.Color = [0.0, 0.0, 0.0]

# 2D view of z = 0 with a parallel camera fitted to the (stretched) curve: the
# curve fills the pixel box x 25..280, y 30..270 (from the bottom); the scalar
# bar takes the right of the window.
Render(view)  # paraview.simple resets the camera on a view's first render: do it before placing it
x0, x1, y0, y1, _, _ = curve.GetBounds()
x0, x1 = X_STRETCH * x0, X_STRETCH * x1
box_x, box_y = (25, 280), (30, 270)
units_per_pixel = max((x1 - x0) / (box_x[1] - box_x[0]), (y1 - y0) / (box_y[1] - box_y[0]))
scale = 0.5 * HEIGHT * units_per_pixel
cx = 0.5 * (x0 + x1) + (0.5 * WIDTH - 0.5 * sum(box_x)) * units_per_pixel
cy = 0.5 * (y0 + y1) + (0.5 * HEIGHT - 0.5 * sum(box_y)) * units_per_pixel
view.InteractionMode = "2D"
view.CameraParallelProjection = 1
view.CameraFocalPoint = [cx, cy, 0.0]
view.CameraPosition = [cx, cy, 100.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraParallelScale = scale
Render(view)

# --------------------------------------------------------------------------- compare
window = view.GetRenderWindow()
grabber = vtkWindowToImageFilter()
grabber.SetInput(window)
grabber.ReadFrontBufferOff()
grabber.Update()
writer = vtkPNGWriter()
writer.SetFileName(produced_path)
writer.SetInputConnection(grabber.GetOutputPort())
writer.Write()
size = window.GetSize()
print("rendered %dx%d: curve of %d samples, curvature %.4g..%.4g (colour range %g..%g); image %s"
      % (size[0], size[1], curve.GetNumberOfPoints(), curvature.GetRange()[0], curvature.GetRange()[1],
         CURVATURE_RANGE[0], CURVATURE_RANGE[1], produced_path))
if list(size) != [WIDTH, HEIGHT]:
    raise SystemExit("render window is %dx%d, expected %dx%d" % (size[0], size[1], WIDTH, HEIGHT))

if not os.path.isfile(baseline_path):
    print("FAIL: missing baseline %s\n  Inspect %s and, if it is right, copy it there."
          % (baseline_path, produced_path))
    sys.exit(1)

Testing.VTK_TEMP_DIR = temp_dir
Testing.compareImage(window, baseline_path, threshold=10)  # raises RuntimeError on a mismatch
print("image matches %s (threshold 10) in %.1f s" % (baseline_path, time.time() - START))
