"""NumPy in, NumPy out: the ShapeSplines filters on (n, 3) point arrays.

    import numpy as np
    from shapesplines.arrays import fit_curves

    curve = fit_curves(points)                      # one (n, 3) array
    curves = fit_curves([line0, line1], family="cubic", end_condition="natural",
                        samples=20, closed=False)   # a list of them
    curve.points, curve.curvature, curve.torsion, curve.tangent, curve.normal,
    curve.binormal, curve.arc_length, curve.parameter, curve.shape_violations

The work is done by the wrapped VTK filters, not re-implemented here: this is
the same code ParaView runs. Family options are the filter's Set methods in
snake case: end_condition="natural" calls SetEndConditionToNatural(),
degree=7 calls SetDegree(7).
"""
import re

import numpy as np
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

import shapesplines

FAMILIES = {"cubic": "vtkCubicSplineFilter", "gencubic": "vtkGeneralizedCubicSplineFilter",
            "quintic": "vtkTensionQuinticSplineFilter", "vdps": "vtkVariableDegreeSplineFilter",
            "qqr": "vtkQQRSplineFilter"}

_POINT_ARRAYS = {"curvature": "Curvature", "torsion": "Torsion", "tangent": "Tangent",
                 "normal": "Normal", "binormal": "Binormal", "arc_length": "ArcLength",
                 "parameter": "Parameter", "span_index": "SpanIndex"}


class Curve:
    """One fitted curve: samples (m, 3) and their arrays, and the line's audit."""

    def __init__(self, output, ids, cell):
        self.points = vtk_to_numpy(output.GetPoints().GetData())[ids].astype(float)
        for attribute, name in _POINT_ARRAYS.items():
            setattr(self, attribute, vtk_to_numpy(output.GetPointData().GetArray(name))[ids])
        cells = output.GetCellData()
        self.shape_violations = int(cells.GetArray("ShapeViolations").GetValue(cell))
        self.length = float(cells.GetArray("Length").GetValue(cell))
        self.cell_arrays = {cells.GetArrayName(a): cells.GetArray(a).GetTuple(cell)
                            for a in range(cells.GetNumberOfArrays())}
        self.point_arrays = {output.GetPointData().GetArrayName(a):
                             vtk_to_numpy(output.GetPointData().GetArray(a))[ids]
                             for a in range(output.GetPointData().GetNumberOfArrays())}


def _camel(snake):
    return "".join(word.capitalize() for word in snake.split("_"))


def _configure(spline, options):
    for key, value in options.items():
        name = _camel(key)
        if isinstance(value, str):
            setter = getattr(spline, "Set%sTo%s" % (name, _camel(re.sub(r"[^a-z0-9]+", "_", value.lower()))), None)
            if setter is None:
                prefix = "Set%sTo" % name
                choices = [re.sub(r"(?<!^)([A-Z])", r"_\1", m[len(prefix):]).lower()
                           for m in dir(spline) if m.startswith(prefix)]
                raise ValueError("%s: %s=%r must be one of %s" % (spline.GetClassName(), key, value,
                                                                   ", ".join(choices) or "(none)"))
            setter()
        else:
            setter = getattr(spline, "Set" + name, None)
            if setter is None:
                raise ValueError("%s has no option %s" % (spline.GetClassName(), key))
            setter(value)


def _polydata(lines):
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
    return poly


def fit_curves(points, family="cubic", samples=10, arc_length=None, closed=False,
               parameterization="chord_length", **options):
    """Fits the family's spline to one (n, 3) array (returns a Curve) or to a
    list of them (returns a list). samples: samples per span; arc_length: a
    sample spacing along the curve instead. Raises ValueError for bad input
    (wrong shape, NaN or Inf, unknown option) with the filter's message."""
    single = isinstance(points, np.ndarray) and points.ndim == 2
    lines = [np.asarray(points, dtype=float)] if single else [np.asarray(p, dtype=float) for p in points]
    for k, line in enumerate(lines):
        if line.ndim != 2 or line.shape[1] != 3 or len(line) < 1:
            raise ValueError("line %d: expected an (n, 3) array of points, got shape %s" % (k, line.shape))
    if family not in FAMILIES:
        raise ValueError("unknown family %r: one of %s" % (family, ", ".join(sorted(FAMILIES))))
    spline = getattr(shapesplines, FAMILIES[family])()
    _configure(spline, dict(options, parameterization=parameterization))
    spline.SetClosed(closed)
    if arc_length is not None:
        spline.SetSamplingModeToArcLength()
        spline.SetSampleLength(arc_length)
    else:
        spline.SetNumberOfSubdivisions(samples)
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        errors.append(message.split("): ", 1)[-1].strip())

    spline.AddObserver(vtkCommand.ErrorEvent, on_error)
    spline.SetInputData(_polydata(lines))
    spline.Update()
    if errors:
        raise ValueError(" ".join(errors))
    output = spline.GetOutput()
    offsets = vtk_to_numpy(output.GetLines().GetOffsetsArray())
    connectivity = vtk_to_numpy(output.GetLines().GetConnectivityArray())
    curves = []
    for cell in range(output.GetNumberOfLines()):
        ids = connectivity[offsets[cell]:offsets[cell + 1]]
        if len(ids) > 2 and ids[0] == ids[-1]:
            ids = ids[:-1]  # a closed curve's cell repeats its first sample
        curves.append(Curve(output, ids, cell))
    return curves[0] if single else curves
