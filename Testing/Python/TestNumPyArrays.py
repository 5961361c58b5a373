"""shapesplines.arrays: NumPy points in, curves with curvature and torsion out,
through the wrapped filters. Run by Debian's python3 and by pvpython with
PYTHONPATH at the build's site-packages: TestNumPyArrays.py
"""
import math
import re
import sys
import warnings

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

import shapesplines
from shapesplines import names
from shapesplines.arrays import FAMILIES, fit_curves

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
direct = vtk_to_numpy(spline.GetOutput().GetPointData().GetArray(names.Torsion))
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

# automatic= is every shape-preserving family's switch; the older keywords
# still set it, with a DeprecationWarning, and the wrapped classes' old
# method names still work.
for family, old in (("gencubic", "automatic_tension"), ("vdps", "automatic_degrees")):
    fixed = fit_curves(akima, family=family, automatic=False)
    automatic = fit_curves(akima, family=family, automatic=True)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        old_fixed = fit_curves(akima, family=family, **{old: False})
    check(fixed.shape_violations > automatic.shape_violations
          and np.array_equal(old_fixed.points, fixed.points)
          and any(w.category is DeprecationWarning and old in str(w.message) for w in caught),
          "family=%r: automatic=False fixes the shape parameter, %s=False too (deprecated)" % (family, old),
          "%d and %d violations fixed and automatic; warnings %s"
          % (fixed.shape_violations, automatic.shape_violations, [str(w.message) for w in caught]))
for family in ("quintic", "qqr"):
    check(fit_curves(akima, family=family, automatic=False).shape_violations
          > fit_curves(akima, family=family).shape_violations,
          "family=%r: automatic=False keeps the shape parameters, so more violations" % family)
with warnings.catch_warnings():
    warnings.simplefilter("ignore", DeprecationWarning)
    old_api = shapesplines.vtkGeneralizedCubicSplineFilter()
    old_api.SetAutomaticTension(False)
    old_degrees = shapesplines.vtkVariableDegreeSplineFilter()
    old_degrees.AutomaticDegreesOff()
    check(not old_api.GetAutomatic() and not old_api.GetAutomaticTension() and not old_degrees.GetAutomatic(),
          "the wrapped classes' old names SetAutomaticTension and AutomaticDegreesOff set Automatic")

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
                             (lambda: fit_curves(points, tension=2), "no option tension", "unknown option"),
                             (lambda: fit_curves(points, kind="exponential"), "no option kind",
                              "unknown option with a choice"),
                             (lambda: fit_curves(points, family="gencubic", automatic=True, automatic_tension=True),
                              "automatic_tension is the old name of automatic", "switch given twice")]:
    try:
        call()
        check(False, "ValueError for a %s" % what)
    except ValueError as e:
        check(fragment in str(e), "ValueError for a %s" % what, str(e))



def raises(call, message, what):
    """call() must raise a ValueError whose message contains `message`."""
    try:
        call()
        check(False, "ValueError for %s" % what)
    except ValueError as e:
        check(message in str(e), "ValueError for %s" % what, str(e))


# The sampling arguments, refused where the filter's setters would clamp
# silently, and the filter's names for them taken, not overridden.
check(len(fit_curves(points, number_of_subdivisions=4).points) == 96 * 4 + 1,
      "number_of_subdivisions=4 is samples=4 (not replaced by the default 10)")
check(np.array_equal(fit_curves(points, sample_length=0.5).points, fit_curves(points, arc_length=0.5).points),
      "sample_length=0.5 is arc_length=0.5")
for value in (0, -3, 2.5, 100001, True):
    raises(lambda: fit_curves(points, samples=value),
           "samples (per span) must be a whole number from 1 to 100000, not %r" % value, "samples=%r" % value)
for value in (0, -1.0, float("nan"), float("inf")):
    raises(lambda: fit_curves(points, arc_length=value),
           "arc_length must be a positive, finite distance between samples, not %r" % value,
           "arc_length=%r" % value)
for kwargs, message in [
        (dict(samples=4, number_of_subdivisions=4), "samples and number_of_subdivisions are the same setting"),
        (dict(arc_length=0.5, sample_length=0.5), "arc_length and sample_length are the same setting"),
        (dict(samples=4, arc_length=0.5), "give samples (per span) or arc_length (a spacing along the curve), not both"),
        (dict(sampling_mode="arc_length"), "sampling_mode follows from samples or arc_length")]:
    raises(lambda: fit_curves(points, **kwargs), message, ", ".join("%s=%r" % kv for kv in kwargs.items()))
# The filter's own limit, in this function's words.
raises(lambda: fit_curves([points] * 3, samples=100000),
       "more than the 20000000 a run may make (about 170 bytes each while it is made): lower samples "
       "(now 100000)", "3 x 9.6e6 samples")

# No curves, wrong shapes; NaN, Inf and huge coordinates as the filter reports them.
raises(lambda: fit_curves([]), "no curves given", "an empty list")
raises(lambda: fit_curves(np.zeros((0, 5, 3))), "no curves given", "an empty (0, 5, 3) array")
raises(lambda: fit_curves(np.zeros(3)), "expected an (n, 3) array of points or a list of them, got shape (3,)",
       "a 1-D array")
raises(lambda: fit_curves([[0, 0, 0], [1, 0, 0], [2, 1, 0]]),
       "line 0: expected an (n, 3) array of points, got shape (3,) (one line is one array: np.asarray(points))",
       "a list of points")
inf_points = points.copy()
inf_points[7, 2] = -float("inf")
huge_points = points.copy()
huge_points[2, 0] = 1e301
raises(lambda: fit_curves([points, inf_points]), "Line (cell 1) skipped: point 7 is not finite.",
       "an Inf point on the second line")
raises(lambda: fit_curves(huge_points), "Line (cell 0) skipped: point 2 has a coordinate beyond 1e300",
       "a coordinate of 1e301")

# point_data: carried onto the samples as the filter carries input point arrays.
radius = 1.0 + 0.5 * np.sin(np.arange(len(points)) / 7.0)
labels = np.arange(len(points)) // 10
flags = np.arange(len(points)) % 3 == 0
pair = np.column_stack([radius, -radius]).astype(np.float32)
carried = fit_curves(points, samples=5, point_data={"radius": radius, "label": labels, "flag": flags,
                                                    "pair": pair, names.Curvature: np.ones(len(points))})
# The samples' positions in data point units (5 per span: none exactly halfway,
# where rounding decides which point is the nearer).
where = np.arange(len(carried.points)) / 5.0
nearer = np.rint(where).astype(int)
check(np.allclose(carried.point_data["radius"], np.interp(where, np.arange(len(points)), radius), rtol=0, atol=1e-14)
      and np.array_equal(carried.point_data["radius"][::5], radius),
      "point_data floats: linear between the data points around each sample, exact at the points")
check(carried.point_data["label"].dtype == labels.dtype and np.array_equal(carried.point_data["label"], labels[nearer])
      and carried.point_data["flag"].dtype == bool and np.array_equal(carried.point_data["flag"], flags[nearer]),
      "point_data integers and booleans: the nearer data point's, in their dtypes")
check(carried.point_data["pair"].shape == (len(carried.points), 2) and carried.point_data["pair"].dtype == np.float32
      and np.allclose(carried.point_data["pair"][:, 1], -carried.point_data["radius"], atol=1e-6),
      "point_data (n, 2) float32: (m, 2) float32")
check(np.all(carried.point_data[names.Curvature] == 1) and abs(carried.curvature[len(where) // 2] - 0.4) < 2e-3
      and sorted(carried.point_arrays) == sorted(fit_curves(points, samples=5).point_arrays),
      "point_data named like a filter array (Curvature) neither replaces it nor joins point_arrays")
# An approximation's samples lie between data points its own knots do not
# mark: the values must be the filter's own for an input point array.
rng = np.random.default_rng(3)
noisy = helix(16, 4) + rng.normal(0, 0.01, (65, 3))
weights = rng.uniform(0, 1, len(noisy))
smooth = fit_curves(noisy, family="quintic", mode="approximate", point_data={"weight": weights})
spline = shapesplines.vtkTensionQuinticSplineFilter()
spline.SetModeToApproximate()
poly = _polydata([noisy])
poly.GetPointData().AddArray(numpy_to_vtk(weights, deep=True))
poly.GetPointData().GetArray(0).SetName("weight")
spline.SetInputData(poly)
spline.Update()
check(np.array_equal(smooth.point_data["weight"], vtk_to_numpy(spline.GetOutput().GetPointData().GetArray("weight"))),
      "point_data on an approximation: the filter's own values for an input point array")
ring = np.array([[math.cos(a), math.sin(a), 0] for a in np.linspace(0, 2 * math.pi, 17)[:-1]])
rings = fit_curves([ring, 2 * ring], closed=True, samples=2,
                   point_data={"k": [np.arange(16.0), 10 + np.arange(16.0)]})
check([len(c.points) for c in rings] == [32, 32] and np.isclose(rings[0].point_data["k"][-1], 7.5)
      and np.isclose(rings[1].point_data["k"][-1], 17.5) and rings[1].point_data["k"][2] == 11.0,
      "point_data on a list of closed lines: each line its own, the seam span between the last and first points")
for kwargs, message, what in [
        (dict(point_data={"r": radius[:-1]}), "point_data['r']: expected shape (97,) or (97, k), one value or row "
         "per point, got (96,)", "point_data one value short"),
        (dict(point_data={"r": np.array(["a"] * 97)}), "point_data['r']: expected integers, booleans, float32 or "
         "float64, got <U1", "point_data of strings"),
        (dict(point_data=[radius]), "point_data must be a dict {name: array}, not list", "point_data not a dict"),
        (dict(point_data={"": radius}), "point_data: names must be non-empty strings", "an empty name")]:
    raises(lambda: fit_curves(points, **kwargs), message, what)
raises(lambda: fit_curves([points, points], point_data={"r": [radius]}),
       "point_data['r']: expected a list of 2 arrays, one per line", "point_data for one line of two")
raises(lambda: fit_curves([points, points], point_data={"r": [radius, pair]}),
       "point_data['r'] of line 1: shape (97, 2), but line 0 has (97,): every line needs the same components",
       "point_data with different components per line")

# Every choice a filter names (Set<Option>To<Choice>) is a string argument,
# in snake case, and does what the number does.
def snake(name):
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])", "_", name).lower()


for family, class_name in sorted(FAMILIES.items()):
    spline = getattr(shapesplines, class_name)()
    for method in sorted(m for m in dir(spline) if re.fullmatch(r"Set[A-Za-z]+To[A-Z][A-Za-z0-9]*", m)):
        option, choice = re.fullmatch(r"Set([A-Za-z]+?)To([A-Z][A-Za-z0-9]*)", method).groups()
        if not hasattr(spline, "Get%sMinValue" % option):
            continue  # not an option with named choices (SetInputArrayToProcess)
        getattr(spline, method)()
        number = getattr(spline, "Get" + option)()
        outcomes = []
        for value in (snake(choice), number):
            try:
                outcomes.append(fit_curves(points, family=family, samples=2, **{snake(option): value}).points)
            except ValueError as e:
                outcomes.append(str(e))
        same = all(isinstance(o, np.ndarray) for o in outcomes) and np.array_equal(*outcomes) or \
            outcomes[0] == outcomes[1]
        check(same, "%s: %s=%r is %s=%s" % (family, snake(option), snake(choice), snake(option), number),
              "" if same else str(outcomes[0])[:200])
natural, clamped = (fit_curves(points, family="vdps", automatic=False, end_condition=end).points
                    for end in ("natural", "clamped"))
check(not np.allclose(natural, clamped), "vdps: end_condition='clamped' changes the ends")

if failures:
    print("\n%d checks FAILED" % len(failures))
    sys.exit(1)
print("\nAll NumPy helper checks passed.")
