"""shapesplines.names holds the strings Filters/ArrayNames.h holds, and they are
the names the filters write. Run by Debian's python3 with PYTHONPATH at the
build's site-packages:
    TestArrayNames.py --header Filters/ArrayNames.h

Two checks: every declaration of the header (read here with Python's own
parser, not the CMake one that generates the module) is in the module with
the same value; and the filters' outputs (the spline, the analysis, the comb,
approximation and connected points included) write every name of the module,
and no array of their own that the module lacks.
"""
import argparse
import math
import re
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkIntArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

import shapesplines
from shapesplines import names

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--header", required=True, help="path of Filters/ArrayNames.h")
args = parser.parse_args()

failures = []


def check(ok, what, detail=""):
    print(("ok   " if ok else "FAIL ") + what + (": " + detail if detail else ""))
    if not ok:
        failures.append(what)


# 1. The module against the header.
with open(args.header) as f:
    header = re.sub(r"//[^\n]*", "", f.read())
declared = {}
for name, value in re.findall(r"constexpr\s+const\s+char\s*\*\s*(\w+)\s*=\s*(\"[^\"]*\")\s*;", header):
    declared[name] = value.strip('"')
for name, values in re.findall(r"constexpr\s+std::array<[^>]*>\s*(\w+)\s*=\s*\{([^}]*)\}\s*;", header):
    declared[name] = tuple(re.findall(r"\"([^\"]*)\"", values))
module = {k: v for k, v in vars(names).items() if not k.startswith("_")}
check(len(declared) == header.count("constexpr"), "every constexpr of the header is a name read here",
      "%d names, %d constexpr" % (len(declared), header.count("constexpr")))
check(module == declared, "shapesplines.names equals Filters/ArrayNames.h (%d names)" % len(declared),
      "only in the header: %s; only in the module: %s; different: %s" % (
          sorted(set(declared) - set(module)), sorted(set(module) - set(declared)),
          sorted(k for k in set(module) & set(declared) if module[k] != declared[k])))
flat = set()
for value in module.values():
    flat.update(value if isinstance(value, tuple) else (value,))


# 2. The module against what the filters write.
def array_names(data):
    found = set()
    for attributes in (data.GetPointData(), data.GetCellData(), data.GetFieldData()):
        found.update(attributes.GetArrayName(a) for a in range(attributes.GetNumberOfArrays()))
    return found


def helix(per_turn, turns, noise=0.0, seed=0):
    t = 2 * math.pi * np.arange(per_turn * turns + 1) / per_turn
    points = np.column_stack([2 * np.cos(t), 2 * np.sin(t), t])
    return points + np.random.default_rng(seed).normal(0, noise, points.shape)


def polydata(lines, connect=True):
    """The lines as line cells, or (connect False) as bare points with a line_id array."""
    points = np.concatenate(lines)
    poly = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points, deep=True))
    poly.SetPoints(vtk_points)
    if connect:
        cells = vtkCellArray()
        start = 0
        for line in lines:
            cells.InsertNextCell(len(line), range(start, start + len(line)))
            start += len(line)
        poly.SetLines(cells)
    else:
        ids = vtkIntArray()
        ids.SetName("line_id")
        for k, line in enumerate(lines):
            for _ in line:
                ids.InsertNextValue(k + 3)
        poly.GetPointData().AddArray(ids)
    return poly


def run(algorithm, *inputs):
    for port, data in enumerate(inputs):
        algorithm.SetInputData(port, data)
    algorithm.Update()
    return algorithm.GetOutput()


written = {}
helices = [helix(8, 2), helix(8, 2)[::-1] + 5.0]
cubic = run(shapesplines.vtkCubicSplineFilter(), polydata(helices))
written["vtkCubicSplineFilter"] = array_names(cubic)
quintic = shapesplines.vtkTensionQuinticSplineFilter()
quintic.SetModeToApproximate()
# Its shape parameter's arrays are named by the math core, not by ArrayNames.h.
written["vtkTensionQuinticSplineFilter (approximate)"] = array_names(
    run(quintic, polydata([helix(16, 4, noise=0.01)]))) - {"Gamma", "MinGamma"}
connected = run(shapesplines.vtkCubicSplineFilter(), polydata(helices, connect=False))
written["vtkCubicSplineFilter (points and line ids)"] = array_names(connected) - {"line_id"}
written["vtkPolylineShapeAnalysis"] = array_names(
    run(shapesplines.vtkPolylineShapeAnalysis(), polydata(helices), cubic))
written["vtkCurvatureCombFilter"] = array_names(run(shapesplines.vtkCurvatureCombFilter(), cubic))
# The analysis and the comb pass their input's arrays on.
written["vtkPolylineShapeAnalysis"] -= written["vtkCubicSplineFilter"] - flat
everything = set().union(*written.values())
check(flat <= everything, "every name of shapesplines.names is written by a filter",
      "never written: %s" % sorted(flat - everything))
for filter_name, found in sorted(written.items()):
    check(found <= flat, "%s writes only arrays named in shapesplines.names" % filter_name,
          "not in the module: %s" % sorted(found - flat))
check(names.CriterionViolations[0] in written["vtkPolylineShapeAnalysis"]
      and names.LineId in written["vtkCubicSplineFilter (points and line ids)"]
      and names.NoiseLevel in written["vtkTensionQuinticSplineFilter (approximate)"],
      "the names of the analysis, of connected points and of approximations where they belong")

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("All checks passed.")
