"""shapesplines.arrays: NumPy points in, curves with curvature and torsion out,
through the wrapped filters. Run by Debian's python3 and by pvpython with
PYTHONPATH at the build's site-packages: TestNumPyArrays.py
"""
import math
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import shapesplines
from shapesplines.arrays import fit_curves

failures = []


def check(ok, what, detail=""):
    print(("ok   " if ok else "FAIL ") + what + (": " + detail if detail else ""))
    if not ok:
        failures.append(what)


def helix(per_turn, turns, a=2.0, b=1.0):
    t = 2 * math.pi * np.arange(per_turn * turns + 1) / per_turn
    return np.column_stack([a * np.cos(t), a * np.sin(t), b * t])


# One array in, one curve out, against the helix's closed forms.
points = helix(32, 3)
curve = fit_curves(points, samples=4)
m = len(curve.points)
middle = slice(m // 4, 3 * m // 4)
k_err = np.max(np.abs(curve.curvature[middle] - 0.4)) / 0.4
t_err = np.max(np.abs(curve.torsion[middle] - 0.2)) / 0.2
check(m == 96 * 4 + 1 and k_err < 5e-3 and t_err < 1e-2,
      "helix (32 points per turn): curvature 0.4 and torsion 0.2 in the middle",
      "%d samples, errors %.1e, %.1e" % (m, k_err, t_err))
check(np.array_equal(curve.points[::4], points), "the data points are among the samples, exactly")
frames = np.stack([curve.tangent, curve.normal, curve.binormal], axis=1)
check(np.allclose(np.linalg.det(frames), 1.0, atol=1e-9), "Frenet frames are right-handed orthonormal")
check(curve.shape_violations == 0 and abs(curve.length - math.sqrt(5) * 6 * math.pi) < 1e-4,
      "shape violations and length of the line", "%d, %.6f" % (curve.shape_violations, curve.length))

# The same numbers as the filter itself (this helper is plumbing, not a re-implementation).
spline = shapesplines.vtkCubicSplineFilter()
spline.SetEndConditionToNatural()
spline.SetNumberOfSubdivisions(3)
natural = fit_curves([points, points[::2] + 1.0], samples=3, end_condition="natural")
from shapesplines.arrays import _polydata  # the same input the helper builds
spline.SetInputData(_polydata([points, points[::2] + 1.0]))
spline.Update()
direct = vtk_to_numpy(spline.GetOutput().GetPointData().GetArray("Torsion"))
check(len(natural) == 2 and np.array_equal(np.concatenate([c.torsion for c in natural]), direct),
      "a list of lines: the filter's own torsion, with options (end_condition='natural')")

closed = fit_curves(np.array([[math.cos(a), math.sin(a), 0] for a in np.linspace(0, 2 * math.pi, 17)[:-1]]),
                    closed=True, arc_length=0.1)
check(len(closed.points) > 60 and np.allclose(closed.curvature, 1.0, rtol=0.02)
      and np.all(closed.torsion == 0), "closed circle, arc-length sampling: curvature 1, torsion 0")

# Another family, with its options: the shape-preserving generalized cubic on Akima's data.
akima = np.array([[0, 10, 0], [2, 10, 0], [3, 10, 0], [5, 10, 0], [6, 10, 0], [8, 10, 0], [9, 10.5, 0],
                  [11, 15, 0], [12, 50, 0], [14, 60, 0], [15, 85, 0]], float)
cubic = fit_curves(akima)
tense = fit_curves(akima, family="gencubic", space_kind="exponential", max_tension=500.0)
check(cubic.shape_violations > 0 and tense.shape_violations == 0 and 0 < tense.cell_arrays["MaxTension"][0] <= 500
      and np.all(tense.torsion == 0),
      "family='gencubic': Akima's shape kept where the cubic breaks it",
      "%d and %d violations, MaxTension %g" % (cubic.shape_violations, tense.shape_violations,
                                               tense.cell_arrays["MaxTension"][0]))

# Bad input: clear Python errors.
for bad, what in [(np.zeros((4, 2)), "(n, 2) array"), ([np.zeros((3, 3)), np.zeros(3)], "a 1-D line")]:
    try:
        fit_curves(bad)
        check(False, "ValueError for %s" % what)
    except ValueError as e:
        check("(n, 3)" in str(e), "ValueError for %s" % what, str(e))
nan_points = points.copy()
nan_points[5, 1] = float("nan")
for call, fragment, what in [(lambda: fit_curves(nan_points), "not finite", "NaN point"),
                             (lambda: fit_curves(points, family="bezier"), "unknown family", "unknown family"),
                             (lambda: fit_curves(points, end_condition="free"), "must be one of clamped, natural, not_a_knot",
                              "bad option value"),
                             (lambda: fit_curves(points, tension=2), "no option tension", "unknown option")]:
    try:
        call()
        check(False, "ValueError for a %s" % what)
    except ValueError as e:
        check(fragment in str(e), "ValueError for a %s" % what, str(e))

if failures:
    print("\n%d checks FAILED" % len(failures))
    sys.exit(1)
print("\nAll NumPy helper checks passed.")
