"""NumPy in, NumPy out: the ShapeSplines filters on (n, 3) point arrays.

    import numpy as np
    from shapesplines.arrays import fit_curves

    curve = fit_curves(points)                      # one (n, 3) array
    curves = fit_curves([line0, line1], family="cubic", end_condition="natural",
                        samples=20, closed=False)   # a list of them
    curve.points, curve.curvature, curve.torsion, curve.tangent, curve.normal,
    curve.binormal, curve.arc_length, curve.parameter, curve.shape_violations
    curve = fit_curves(points, point_data={"radius": radius})  # (n,) or (n, k)
    curve.point_data["radius"]                      # on the samples

The work is done by the wrapped VTK filters, not re-implemented here: this is
the same code ParaView runs. Family options are the filter's Set methods in
snake case: end_condition="natural" calls SetEndConditionToNatural(),
degree=7 calls SetDegree(7), automatic=False (every family but the cubic)
calls SetAutomatic(False).
"""
import math
import numbers
import re
import warnings

import numpy as np
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

import shapesplines
from shapesplines import names

FAMILIES = {"cubic": "vtkCubicSplineFilter", "gencubic": "vtkGeneralizedCubicSplineFilter",
            "quintic": "vtkTensionQuinticSplineFilter", "vdps": "vtkVariableDegreeSplineFilter",
            "qqr": "vtkQQRSplineFilter"}

_POINT_ARRAYS = {"curvature": names.Curvature, "torsion": names.Torsion, "tangent": names.Tangent,
                 "normal": names.Normal, "binormal": names.Binormal, "arc_length": names.ArcLength,
                 "parameter": names.Parameter, "span_index": names.SpanIndex}

# point_data goes through the filter under these names, so that none of the
# filter's own arrays (Curvature, Degree...) can replace one of the user's.
_CARRIED = "fit_curves.point_data:"

# Older names of the automatic switch, when each family named it after its
# shape parameter; still taken, with a DeprecationWarning.
_RENAMED = {"automatic_tension": "automatic", "automatic_degrees": "automatic"}

# The filter's settings that are this function's arguments, for its messages.
_ARGUMENTS = {"NumberOfSubdivisions": "samples", "SampleLength": "arc_length"}


class Curve:
    """One fitted curve: samples (m, 3) and their arrays, the input's
    point_data on the samples, and the line's audit."""

    def __init__(self, output, ids, cell, dtypes):
        self.points = vtk_to_numpy(output.GetPoints().GetData())[ids].astype(float)
        for attribute, name in _POINT_ARRAYS.items():
            setattr(self, attribute, vtk_to_numpy(output.GetPointData().GetArray(name))[ids])
        cells = output.GetCellData()
        self.shape_violations = int(cells.GetArray(names.ShapeViolations).GetValue(cell))
        self.length = float(cells.GetArray(names.Length).GetValue(cell))
        self.cell_arrays = {cells.GetArrayName(a): cells.GetArray(a).GetTuple(cell)
                            for a in range(cells.GetNumberOfArrays())}
        self.point_arrays = {}
        self.point_data = {}
        for a in range(output.GetPointData().GetNumberOfArrays()):
            name = output.GetPointData().GetArrayName(a)
            values = vtk_to_numpy(output.GetPointData().GetArray(a))[ids]
            if name.startswith(_CARRIED):
                name = name[len(_CARRIED):]
                self.point_data[name] = values.astype(dtypes[name], copy=False)
            else:
                self.point_arrays[name] = values


def _camel(snake):
    return "".join(word.capitalize() for word in snake.split("_"))


def _configure(spline, options):
    for key, value in options.items():
        name = _camel(key)
        if isinstance(value, str):
            # SetContinuityToC2FC is continuity="c2_fc" (or "C2FC"), SetEndConditionToNotAKnot "not_a_knot".
            prefix = "Set%sTo" % name
            choices = {re.sub(r"(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])", "_", m[len(prefix):]).lower(): m
                       for m in dir(spline) if m.startswith(prefix) and m[len(prefix):][:1].isupper()}
            wanted = [m for choice, m in choices.items() if _letters(choice) == _letters(value)]
            if not choices and getattr(spline, "Set" + name, None) is None:
                raise ValueError("%s has no option %s" % (spline.GetClassName(), key))
            if not wanted:
                raise ValueError("%s: %s=%r must be one of %s" % (spline.GetClassName(), key, value,
                                                                   ", ".join(sorted(choices)) or "(none)"))
            getattr(spline, wanted[0])()
        else:
            setter = getattr(spline, "Set" + name, None)
            if setter is None:
                raise ValueError("%s has no option %s" % (spline.GetClassName(), key))
            setter(value)


def _letters(text):
    """text's letters and digits, lower case: how a choice is matched."""
    return re.sub(r"[^a-z0-9]", "", text.lower())


def _renamed(options):
    """options with the older names replaced by the current ones."""
    for old, new in _RENAMED.items():
        if old in options:
            if new in options:
                raise ValueError("%s is the old name of %s: give one of them" % (old, new))
            warnings.warn("fit_curves: %s is deprecated, use %s" % (old, new), DeprecationWarning,
                          stacklevel=3)
            options[new] = options.pop(old)
    return options


def _sampling(spline, samples, arc_length, options):
    """Sets the sampling, refusing what the filter's setters would silently
    clamp: samples outside their range, a zero, negative or NaN spacing, or
    two settings for one thing."""
    for option, argument, value in (("number_of_subdivisions", "samples", samples),
                                    ("sample_length", "arc_length", arc_length)):
        if option in options and value is not None:
            raise ValueError("%s and %s are the same setting: give one of them" % (argument, option))
    samples = options.pop("number_of_subdivisions", samples)
    arc_length = options.pop("sample_length", arc_length)
    if "sampling_mode" in options:
        raise ValueError("sampling_mode follows from samples or arc_length: give one of them instead")
    if samples is not None and arc_length is not None:
        raise ValueError("give samples (per span) or arc_length (a spacing along the curve), not both")
    if arc_length is not None:
        if (isinstance(arc_length, bool) or not isinstance(arc_length, numbers.Real)
                or not (math.isfinite(arc_length) and arc_length > 0)):
            raise ValueError("arc_length must be a positive, finite distance between samples, not %r"
                             % (arc_length,))
        spline.SetSamplingModeToArcLength()
        spline.SetSampleLength(arc_length)
        return
    low, high = spline.GetNumberOfSubdivisionsMinValue(), spline.GetNumberOfSubdivisionsMaxValue()
    if samples is None:
        samples = spline.GetNumberOfSubdivisions()
    if isinstance(samples, bool) or not isinstance(samples, numbers.Integral) or not low <= samples <= high:
        raise ValueError("samples (per span) must be a whole number from %d to %d, not %r" % (low, high, samples))
    spline.SetNumberOfSubdivisions(int(samples))


def _point_data(point_data, lines, single):
    """point_data as {name: one array per line}, each (n,) or (n, k) for the
    line's n points, with the same k on every line."""
    if point_data is None:
        return {}
    if not isinstance(point_data, dict):
        raise ValueError("point_data must be a dict {name: array}, not %s" % type(point_data).__name__)
    checked = {}
    for name, values in point_data.items():
        if not isinstance(name, str) or not name:
            raise ValueError("point_data: names must be non-empty strings, not %r" % (name,))
        per_line = [values] if single else values
        sequence = isinstance(per_line, (list, tuple)) or (isinstance(per_line, np.ndarray) and per_line.ndim > 0)
        if not sequence or len(per_line) != len(lines):
            raise ValueError("point_data[%r]: expected a list of %d arrays, one per line" % (name, len(lines)))
        arrays = [np.asarray(a) for a in per_line]
        for k, (line, array) in enumerate(zip(lines, arrays)):
            where = "point_data[%r]%s" % (name, "" if single else " of line %d" % k)
            if array.dtype.kind not in "biuf" or array.dtype == np.float16:
                raise ValueError("%s: expected integers, booleans, float32 or float64, got %s" % (where, array.dtype))
            if array.ndim not in (1, 2) or len(array) != len(line):
                raise ValueError("%s: expected shape (%d,) or (%d, k), one value or row per point, got %s"
                                 % (where, len(line), len(line), array.shape))
            if array.shape[1:] != arrays[0].shape[1:]:
                raise ValueError("%s: shape %s, but line 0 has %s: every line needs the same components"
                                 % (where, array.shape, arrays[0].shape))
        checked[name] = arrays
    return checked


def _polydata(lines, point_data=None):
    """The lines as one poly data, a line cell each, with their point_data
    ({name: one array per line}) as point arrays the filter carries."""
    points = np.concatenate(lines).astype(float)
    poly = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points, deep=True))
    poly.SetPoints(vtk_points)
    cells = vtkCellArray()
    start = 0
    for line in lines:
        cells.InsertNextCell(len(line), range(start, start + len(line)))
        start += len(line)
    poly.SetLines(cells)
    for name, arrays in (point_data or {}).items():
        values = np.concatenate(arrays)
        if values.dtype.kind == "b":
            values = values.astype(np.uint8)  # VTK has no bool arrays
        array = numpy_to_vtk(np.ascontiguousarray(values), deep=True)
        array.SetName(_CARRIED + name)
        poly.GetPointData().AddArray(array)
    return poly


def fit_curves(points, family="cubic", samples=None, arc_length=None, closed=False,
               parameterization="chord_length", point_data=None, **options):
    """Fits the family's spline to one (n, 3) array (returns a Curve) or to a
    list of them (returns a list, a Curve per line, in order).

    samples: samples per span (default 10); arc_length: a sample spacing
    along the curve instead (number_of_subdivisions and sample_length, the
    filter's names, are taken for them too). point_data: {name: values} with an (n,) or
    (n, k) array per point of the line (a list of them, one per line, for a
    list of lines); the filter carries them onto the samples as it carries
    input point arrays (floats interpolated linearly between the data points
    around each sample, integers and booleans taken from the nearer one),
    and each Curve has them in point_data, in the dtypes given.

    Raises ValueError for bad input (wrong shape, no curves, an argument out
    of its range, NaN or Inf, unknown option) naming what is wrong; what the
    filter refuses is reported with the filter's message, and then no curve
    is returned, not even the lines it could fit.
    """
    if isinstance(points, np.ndarray) and points.ndim not in (2, 3):
        raise ValueError("expected an (n, 3) array of points or a list of them, got shape %s" % (points.shape,))
    single = isinstance(points, np.ndarray) and points.ndim == 2
    lines = [np.asarray(points, dtype=float)] if single else [np.asarray(p, dtype=float) for p in points]
    if not lines:
        raise ValueError("no curves given: expected an (n, 3) array of points or a list of them")
    for k, line in enumerate(lines):
        if line.ndim != 2 or line.shape[1] != 3 or len(line) < 1:
            # A list of [x, y, z] rows is taken for a list of lines.
            hint = " (one line is one array: np.asarray(points))" if line.shape == (3,) else ""
            raise ValueError("line %d: expected an (n, 3) array of points, got shape %s%s" % (k, line.shape, hint))
    if family not in FAMILIES:
        raise ValueError("unknown family %r: one of %s" % (family, ", ".join(sorted(FAMILIES))))
    carried = _point_data(point_data, lines, single)
    spline = getattr(shapesplines, FAMILIES[family])()
    _sampling(spline, samples, arc_length, options)
    _configure(spline, dict(_renamed(options), parameterization=parameterization))
    spline.SetClosed(closed)
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        message = message.split("): ", 1)[-1].strip()
        for setting, argument in _ARGUMENTS.items():
            message = message.replace(setting, argument)
        errors.append(message)

    spline.AddObserver(vtkCommand.ErrorEvent, on_error)
    spline.SetInputData(_polydata(lines, carried))
    spline.Update()
    if errors:
        raise ValueError(" ".join(errors))
    output = spline.GetOutput()
    offsets = vtk_to_numpy(output.GetLines().GetOffsetsArray())
    connectivity = vtk_to_numpy(output.GetLines().GetConnectivityArray())
    dtypes = {name: np.result_type(*arrays) for name, arrays in carried.items()}
    curves = []
    for cell in range(output.GetNumberOfLines()):
        ids = connectivity[offsets[cell]:offsets[cell + 1]]
        if len(ids) > 2 and ids[0] == ids[-1]:
            ids = ids[:-1]  # a closed curve's cell repeats its first sample
        curves.append(Curve(output, ids, cell, dtypes))
    return curves[0] if single else curves
