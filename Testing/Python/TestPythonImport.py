"""The wrapped VTK module without the plugin: `from shapesplines import ...`.

Run with PYTHONPATH at the build's site-packages, by Debian's python3 (with
ParaView's vtkmodules) and by pvpython:
    python3 TestPythonImport.py --data Data
"""
import argparse
import math
import sys

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

import shapesplines
from shapesplines import vtkCubicSplineFilter, vtkPolylineShapeAnalysis

parser = argparse.ArgumentParser()
parser.add_argument("--data", required=True)
args = parser.parse_args()

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
