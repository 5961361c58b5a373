"""The wrapped VTK module without the plugin: `from shapesplines import ...`.

Run with PYTHONPATH at the build's site-packages, by Debian's python3 (with
ParaView's vtkmodules) and by pvpython:
    python3 TestPythonImport.py --data Data
and by an interpreter without VTK (a virtualenv's, pyenv's; Debian's python3
-S stands in for them), where the import must say which interpreter to use:
    python3 -S TestPythonImport.py --data Data --without-vtk
"""
import argparse
import importlib.util
import math
import sys

parser = argparse.ArgumentParser()
parser.add_argument("--data", required=True)
parser.add_argument("--without-vtk", action="store_true")
args = parser.parse_args()

if args.without_vtk:
    if importlib.util.find_spec("vtkmodules"):
        print("FAIL %s has vtkmodules: this check needs an interpreter without VTK" % sys.executable)
        sys.exit(1)
    try:
        import shapesplines  # noqa: F401
        print("FAIL shapesplines imported without VTK")
        sys.exit(1)
    except ImportError as e:
        message = str(e)
    print("%s: %s" % (sys.executable, message))
    hints = ["No module named 'vtkmodules'", "this Python (%s)" % sys.executable,
             "Debian's /usr/bin/python3", "python3-paraview", "pvpython"]
    missing = [hint for hint in hints if hint not in message]
    for hint in missing:
        print("FAIL the message does not say %r" % hint)
    sys.exit(1 if missing else 0)

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader  # noqa: E402

import shapesplines  # noqa: E402
from shapesplines import vtkCubicSplineFilter, vtkPolylineShapeAnalysis  # noqa: E402

reader = vtkXMLPolyDataReader()
reader.SetFileName(args.data + "/helix.vtp")
spline = vtkCubicSplineFilter()
spline.SetInputConnection(reader.GetOutputPort())
spline.SetNumberOfSubdivisions(4)
spline.SetEndConditionToNatural()
spline.Update()
curve = spline.GetOutput()
curvature = curve.GetPointData().GetArray("Curvature")
torsion = curve.GetPointData().GetArray("Torsion")
middle = curve.GetNumberOfPoints() // 2  # a knot in the middle of the helix
failures = []
if curve.GetNumberOfPoints() != 32 * 4 + 1:
    failures.append("expected 129 samples, got %d" % curve.GetNumberOfPoints())
# A C2 cubic at 8 points per turn: within 6% of 0.4 and 10% of 0.2 (measured 5.6%, 9.6%).
if not abs(curvature.GetValue(middle) - 0.4) < 0.06 * 0.4:
    failures.append("curvature %g, not 0.4 within 6%%" % curvature.GetValue(middle))
if not abs(torsion.GetValue(middle) - 0.2) < 0.10 * 0.2:
    failures.append("torsion %g, not 0.2 within 10%%" % torsion.GetValue(middle))
if spline.GetEndConditionAsString() != "Natural":
    failures.append("end condition %s" % spline.GetEndConditionAsString())

analysis = vtkPolylineShapeAnalysis()
analysis.SetInputConnection(reader.GetOutputPort())
analysis.SetCurveConnection(spline.GetOutputPort())
analysis.Update()
violations = analysis.GetOutput().GetCellData().GetArray("ShapeViolations").GetValue(0)
if violations != 0:
    failures.append("the cubic breaks the helix's shape %d times" % violations)
if not all(math.isfinite(curvature.GetValue(i)) for i in range(curvature.GetNumberOfTuples())):
    failures.append("non-finite curvature")

print("%s: shapesplines from %s; curvature %.4f, torsion %.4f at the middle knot; %d violations"
      % (sys.executable, shapesplines.__file__, curvature.GetValue(middle),
         torsion.GetValue(middle), violations))
for failure in failures:
    print("FAIL", failure)
sys.exit(1 if failures else 0)
