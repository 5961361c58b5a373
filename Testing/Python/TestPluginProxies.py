"""pvpython test: the ShapeSplines plugin loads and its proxies work on real data.

Run as
    PYTHONPATH=<build>/lib/python3.11/site-packages \\
        xvfb-run -a pvpython TestPluginProxies.py --plugin ShapeSplines.so --data Data \
        --baseline Testing/Data/Baseline --temp <build>/Testing/Temporary

It loads the plugin with LoadPlugin, builds every proxy of the plugin (CubicSpline,
PolylineShapeAnalysis) on the sample data, fetches the outputs with
servermanager.Fetch and checks their contents: the array contract, finite
values, unit orthonormal Frenet frames, the helix's curvature and torsion
(against the closed forms and against SciPy's CubicSpline), every End Condition,
Parameterization and Sampling Mode, Closed, the two tolerances, VMTK Array
Names, carried input arrays, the discrete shape and the shape audit, and the
documentation of every property. Each check prints one line with the measured
numbers; the script exits non-zero if any check fails.
"""
import argparse
import math
import os
import sys
import time

import numpy as np

from paraview import servermanager
from paraview.simple import CSVReader, LoadPlugin, PVTrivialProducer, TableToPoints, XMLPolyDataReader
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_STRING

from shapesplines import names  # the output array names (PYTHONPATH: the build's site-packages)

START = time.time()
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--plugin", required=True, help="path of ShapeSplines.so")
parser.add_argument("--data", required=True, help="folder holding helix.vtp, akima.vtp, ...")
parser.add_argument("--baseline", help="baseline image folder (unused here)")
parser.add_argument("--temp", required=True, help="temporary output folder (a CSV is written there)")
args = parser.parse_args()

if not os.path.isfile(args.plugin):
    raise SystemExit("plugin not found: %s" % args.plugin)
LoadPlugin(args.plugin, remote=False, ns=globals())
for proxy_name in ("CubicSpline", "PolylineShapeAnalysis", "CurvatureComb", "GeneralizedCubicSpline",
                   "TensionQuinticSpline", "VariableDegreeSpline", "QQRSpline"):
    if proxy_name not in globals():
        raise SystemExit("LoadPlugin did not define the proxy %s" % proxy_name)

POINT_CONTRACT = {names.Curvature: 1, names.Torsion: 1, names.Tangent: 3, names.Normal: 3, names.Binormal: 3,
                  names.Parameter: 1, names.ArcLength: 1, names.SpanIndex: 1}
CELL_CONTRACT = {names.ShapePreserving: 1, names.ShapeViolations: 1, names.Length: 1, names.Tortuosity: 1,
                 names.ConditionEstimate: 1}
DISCRETE_ARRAYS = {names.DiscreteCurvature: 1, names.DiscreteTorsion: 1, names.DiscreteBinormal: 3,
                   names.Collinear: 1, names.Convex: 1, names.Coplanar: 1}
AUDIT_CELL_ARRAYS = [names.ShapeViolations, names.ShapePreserving, *names.CriterionViolations]
FRAME_TOLERANCE = 1e-9

# --------------------------------------------------------------------------- checks
failures = []
check_count = [0]


def check(ok, what, detail="", quiet=False):
    """Records one check and prints it with its measured numbers (quiet: only if it fails)."""
    check_count[0] += 1
    ok = bool(ok)
    if ok and quiet:
        return ok
    print("%s %s%s" % ("ok  " if ok else "FAIL", what, (": " + detail) if detail else ""))
    if not ok:
        failures.append("%s: %s" % (what, detail))
    return ok


def fmt(x):
    return "%.6g" % x


# --------------------------------------------------------------------------- VTK messages
class MessageLog:
    """Collects the errors and warnings a filter reports through vtkErrorMacro/vtkWarningMacro."""

    def __init__(self):
        self.errors = []
        self.warnings = []

    def watch(self, proxy):
        algorithm = proxy.GetClientSideObject()

        @calldata_type(VTK_STRING)
        def on_error(caller, event, message):
            self.errors.append(str(message).strip())

        @calldata_type(VTK_STRING)
        def on_warning(caller, event, message):
            self.warnings.append(str(message).strip())

        algorithm.AddObserver("ErrorEvent", on_error)
        algorithm.AddObserver("WarningEvent", on_warning)
        return proxy

    def take(self):
        errors, warnings = self.errors, self.warnings
        self.errors, self.warnings = [], []
        return errors, warnings


LOG = MessageLog()


def interior_values(values):
    """The middle half of a line's samples."""
    n = len(values)
    return values[n // 4:3 * n // 4]


def fetch(proxy):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy)


def run(proxy, label, expect_warnings=()):
    """Updates and fetches proxy; checks it reported no error and only the expected warnings."""
    LOG.take()
    data = fetch(proxy)
    errors, warnings = LOG.take()
    check(not errors, "%s: no VTK error" % label, "; ".join(errors) or "none", quiet=True)
    unexpected = [w for w in warnings if not any(e in w for e in expect_warnings)]
    missing = [e for e in expect_warnings if not any(e in w for w in warnings)]
    if expect_warnings or warnings:
        check(not unexpected and not missing, "%s: warnings as expected" % label,
              "got %r, expected %r" % (warnings, list(expect_warnings)), quiet=True)
    return data


# --------------------------------------------------------------------------- data access
def point_array(data, name):
    array = data.GetPointData().GetAbstractArray(name)
    if array is None:
        raise AssertionError("point array %s missing" % name)
    return vtk_to_numpy(array)


def cell_array(data, name):
    array = data.GetCellData().GetAbstractArray(name)
    if array is None:
        raise AssertionError("cell array %s missing" % name)
    return vtk_to_numpy(array)


def points_of(data):
    return vtk_to_numpy(data.GetPoints().GetData()).astype(float)


def lines_of(data):
    """Point ids of each line cell, in order."""
    cells = data.GetLines()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    connectivity = vtk_to_numpy(cells.GetConnectivityArray())
    return [connectivity[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


def clean_line(points):
    """Consecutive repeated points merged, as the filters do (indices into points)."""
    diagonal = np.linalg.norm(points.max(axis=0) - points.min(axis=0))
    kept = [0]
    for i in range(1, len(points)):
        if np.linalg.norm(points[i] - points[kept[-1]]) > 1e-12 * diagonal:
            kept.append(i)
    return kept


def data_lines(data):
    """Cleaned point coordinates of each input line."""
    pts = points_of(data)
    result = []
    for ids in lines_of(data):
        line = pts[ids]
        result.append(line[clean_line(line)])
    return result


def reader(name):
    path = os.path.join(args.data, name)
    if not os.path.isfile(path):
        raise SystemExit("data file not found: %s" % path)
    return XMLPolyDataReader(FileName=[path])


# --------------------------------------------------------------------------- contract
def check_curve(label, out, inp, expected_points=None, subdivisions=None):
    """Checks what every CubicSpline output must satisfy, in one reported check:
    one line per input line, the sample count, the contract arrays and the carried
    input arrays, finite values, unit orthonormal right-handed frames, curvature
    >= 0, tangents along the curve, and per line: ArcLength from 0 to Length,
    SpanIndex and Parameter increasing, the data points among the samples,
    Tortuosity = Length / chord and ShapePreserving = (ShapeViolations == 0).
    Returns per-line facts, or None if arrays are missing."""
    problems = []
    npts, ncells = out.GetNumberOfPoints(), out.GetNumberOfCells()
    data = data_lines(inp)
    if ncells != len(data) or out.GetNumberOfLines() != ncells:
        problems.append("%d lines for %d input lines" % (ncells, len(data)))
    if expected_points is not None and npts != expected_points:
        problems.append("%d samples, expected %d" % (npts, expected_points))
    # Array contract.
    missing = []
    for name, comps in POINT_CONTRACT.items():
        a = out.GetPointData().GetArray(name)
        if a is None or a.GetNumberOfComponents() != comps or a.GetNumberOfTuples() != npts:
            missing.append(name)
    for name, comps in CELL_CONTRACT.items():
        a = out.GetCellData().GetArray(name)
        if a is None or a.GetNumberOfComponents() != comps or a.GetNumberOfTuples() != ncells:
            missing.append(name)
    carried = [inp.GetPointData().GetArrayName(i) for i in range(inp.GetPointData().GetNumberOfArrays())]
    missing += ["input:" + n for n in carried if out.GetPointData().GetAbstractArray(n) is None]
    if missing:
        check(False, "%s: output contract" % label, "missing or wrong arrays %s; %s" % (missing, problems))
        return None
    # Finite everywhere.
    bad = []
    for attributes in (out.GetPointData(), out.GetCellData()):
        for i in range(attributes.GetNumberOfArrays()):
            a = attributes.GetArray(i)
            if a is not None and not np.all(np.isfinite(vtk_to_numpy(a))):
                bad.append(a.GetName())
    pts = points_of(out)
    if not np.all(np.isfinite(pts)):
        bad.append("Points")
    if bad:
        problems.append("NaN/Inf in %s" % bad)
    # Unit, orthogonal, right-handed frames.
    T, N, B = (point_array(out, n) for n in (names.Tangent, names.Normal, names.Binormal))
    frame_error = max([np.abs(np.linalg.norm(v, axis=1) - 1).max() for v in (T, N, B)]
                      + [np.abs(np.einsum("ij,ij->i", u, v)).max() for u, v in ((T, N), (T, B), (N, B))]
                      + [np.abs(np.cross(T, N) - B).max()])
    if not frame_error < FRAME_TOLERANCE:
        problems.append("frame error %.2g (|T|,|N|,|B| - 1, dot products, TxN - B)" % frame_error)
    k = point_array(out, names.Curvature)
    if k.min() < 0:
        problems.append("negative curvature %g" % k.min())
    # Per line.
    lines = lines_of(out)
    arc, span, param = (point_array(out, n) for n in (names.ArcLength, names.SpanIndex, names.Parameter))
    length, tortuosity = cell_array(out, names.Length), cell_array(out, names.Tortuosity)
    viol, preserving = cell_array(out, names.ShapeViolations), cell_array(out, names.ShapePreserving)
    knot_error = 0.0
    forward = []
    for c, (ids, dl) in enumerate(zip(lines, data)):
        spans = len(dl) - 1
        if subdivisions is not None and len(ids) != spans * subdivisions + 1:
            problems.append("line %d has %d samples, expected %d" % (c, len(ids), spans * subdivisions + 1))
        a = arc[ids]
        if a[0] != 0 or np.any(np.diff(a) < 0) or abs(a[-1] - length[c]) > 1e-9 * length[c]:
            problems.append("line %d arc length 0..%g vs Length %g" % (c, a[-1], length[c]))
        s = span[ids]
        if s[0] != 0 or s[-1] != spans - 1 or np.any(np.diff(s) < 0) or np.any(np.diff(s) > 1):
            problems.append("line %d span indices %d..%d for %d spans" % (c, s[0], s[-1], spans))
        if np.any(np.diff(param[ids]) <= 0):
            problems.append("line %d parameter not increasing" % c)
        starts = [ids[0]] + [ids[i] for i in range(1, len(ids)) if s[i] != s[i - 1]] + [ids[-1]]
        if len(starts) == len(dl):
            knot_error = max(knot_error, np.abs(pts[starts] - dl).max())
        else:
            problems.append("line %d: %d span starts for %d data points" % (c, len(starts), len(dl)))
        chord = np.linalg.norm(dl[-1] - dl[0])
        if abs(tortuosity[c] - length[c] / chord) > 1e-9 * tortuosity[c] or tortuosity[c] < 1:
            problems.append("line %d Tortuosity %g vs Length/chord %g" % (c, tortuosity[c], length[c] / chord))
        if preserving[c] != (1 if viol[c] == 0 else 0):
            problems.append("line %d ShapePreserving %d with %d violations" % (c, preserving[c], viol[c]))
        steps = np.diff(pts[ids], axis=0)
        forward.append(np.einsum("ij,ij->i", T[ids][:-1], steps) > 0)
    scale = max(1.0, np.abs(pts).max())
    if knot_error > 1e-12 * scale:
        problems.append("data points missing from the samples (max distance %.2g)" % knot_error)
    forward = np.concatenate(forward)
    if forward.mean() < 0.999:
        problems.append("only %.2f%% of tangents point to the next sample" % (100 * forward.mean()))
    check(not problems, "%s: output contract" % label,
          "; ".join(problems) if problems else
          "%d samples on %d line(s), %d point + %d cell arrays finite, frame error %.1g, "
          "curvature %s..%s, Length %s, Tortuosity %s, ShapeViolations %s"
          % (npts, ncells, out.GetPointData().GetNumberOfArrays(), out.GetCellData().GetNumberOfArrays(),
             frame_error, fmt(k.min()), fmt(k.max()), "/".join(fmt(x) for x in length),
             "/".join(fmt(x) for x in tortuosity), "/".join(str(v) for v in viol)))
    return {"length": length, "tortuosity": tortuosity, "violations": viol, "lines": lines}


# =========================================================================== documentation
print("== documentation of every property")
helix = reader("helix.vtp")
for proxy in (CubicSpline(Input=helix), PolylineShapeAnalysis(Input=helix),
              CurvatureComb(Input=CubicSpline(Input=helix)), GeneralizedCubicSpline(Input=helix),
              TensionQuinticSpline(Input=helix), VariableDegreeSpline(Input=helix), QQRSpline(Input=helix)):
    name = proxy.GetXMLName()
    doc = proxy.SMProxy.GetDocumentation()
    check(doc is not None and (doc.GetShortHelp() or "").strip() and (doc.GetDescription() or "").strip(),
          "%s: proxy documentation" % name, "%r" % ((doc.GetShortHelp() or "")[:60] if doc else None))
    undocumented = []
    property_names = proxy.ListProperties()
    for prop_name in property_names:
        sm = proxy.GetProperty(prop_name).SMProperty
        text = sm.GetDocumentation().GetDescription() if sm.GetDocumentation() else None
        if not text or not text.strip():
            undocumented.append(prop_name)
    check(len(property_names) > 0 and not undocumented, "%s: all %d properties documented" % (name, len(property_names)),
          "undocumented: %s" % undocumented if undocumented else ", ".join(property_names))
    expected = {"CubicSpline": ["Input", "Parameterization", "Closed", "SamplingMode", "NumberOfSubdivisions",
                                "SampleLength", "DataShapeTolerance", "CurveShapeTolerance", "VMTKArrayNames", "ConnectPoints", "LineIdArray", "NumberOfThreads",
                                "EndCondition"],
                "PolylineShapeAnalysis": ["Input", "Curve", "Closed", "DataShapeTolerance",
                                          "CurveShapeTolerance"],
                "CurvatureComb": ["Input", "CombType", "ScaleMode", "RelativeToothLength", "ScaleFactor",
                                  "Stride", "Envelope"],
                "GeneralizedCubicSpline": ["Input", "Parameterization", "Closed", "SamplingMode",
                                           "NumberOfSubdivisions", "SampleLength", "DataShapeTolerance",
                                           "CurveShapeTolerance", "VMTKArrayNames", "ConnectPoints", "LineIdArray", "NumberOfThreads", "SpaceKind",
                                           "Automatic", "AutomaticTension", "Tension", "MaxTension",
                                           "EndCondition", "TensionArray"],
                "TensionQuinticSpline": ["Input", "Parameterization", "Closed", "SamplingMode",
                                         "NumberOfSubdivisions", "SampleLength", "DataShapeTolerance",
                                         "CurveShapeTolerance", "VMTKArrayNames", "ConnectPoints", "LineIdArray", "NumberOfThreads", "Continuity", "Mode",
                                         "NumberOfKnots", "CorrectParameters", "Automatic", "Gamma", "Lambda"],
                "VariableDegreeSpline": ["Input", "Parameterization", "Closed", "SamplingMode",
                                         "NumberOfSubdivisions", "SampleLength", "DataShapeTolerance",
                                         "CurveShapeTolerance", "VMTKArrayNames", "ConnectPoints", "LineIdArray", "NumberOfThreads", "Mode", "NumberOfKnots",
                                         "CorrectParameters",
                                         "Automatic", "AutomaticDegrees", "Degree", "MaxDegree", "Lambda",
                                         "ScaleLambdaWithDegree", "EndCondition", "DegreeArray"],
                "QQRSpline": ["Input", "Parameterization", "Closed", "SamplingMode", "NumberOfSubdivisions",
                              "SampleLength", "DataShapeTolerance", "CurveShapeTolerance", "VMTKArrayNames", "ConnectPoints", "LineIdArray", "NumberOfThreads",
                              "Mode", "Automatic", "Alpha", "Beta", "MaxAlpha", "LocalParameters", "X", "Y",
                              "Z", "ZArray", "Continuity", "FrenetOrder"]}[name]
    check(sorted(property_names) == sorted(expected), "%s: Python property names" % name, ", ".join(sorted(property_names)))

# =========================================================================== CubicSpline defaults
print("== CubicSpline at default settings on every data set")
data_sets = {}
defaults = {}
for file_name, warnings in (("helix.vtp", ()), ("akima.vtp", ()), ("rpn15a.vtp", ()),
                            ("titanium.vtp", ()), ("aorta-centerline.vtp", ())):
    src = reader(file_name)
    inp = fetch(src)
    data_sets[file_name] = (src, inp)
    spline = LOG.watch(CubicSpline(Input=src))
    check(spline.EndCondition == "Not A Knot" and spline.Parameterization == "Chord Length"
          and spline.SamplingMode == "Subdivisions" and spline.NumberOfSubdivisions == 10
          and spline.SampleLength == 1.0 and spline.Closed == 0 and spline.VMTKArrayNames == 0,
          "%s: default property values" % file_name,
          "%s, %s, %s, %s" % (spline.EndCondition, spline.Parameterization, spline.SamplingMode,
                              spline.NumberOfSubdivisions))
    out = run(spline, "CubicSpline(%s)" % file_name, warnings)
    spans = sum(len(dl) - 1 for dl in data_lines(inp))
    facts = check_curve("CubicSpline(%s)" % file_name, out, inp,
                        expected_points=sum(10 * (len(dl) - 1) + 1 for dl in data_lines(inp)), subdivisions=10)
    defaults[file_name] = (spline, out, facts)

# --------------------------------------------------------------------------- helix values
print("== helix curvature 0.4 and torsion 0.2")
spline, out, facts = defaults["helix.vtp"]
k, tau, span = (point_array(out, n) for n in (names.Curvature, names.Torsion, names.SpanIndex))
interior = (span >= 2) & (span <= 29)  # drop the two end spans at each end (end-condition effects)
k_mean, tau_mean = k[interior].mean(), tau[interior].mean()
check(abs(k_mean / 0.4 - 1) < 0.02, "helix.vtp: mean interior curvature within 2% of 0.4",
      "%s (%.3f%%); pointwise %s..%s" % (fmt(k_mean), 100 * (k_mean / 0.4 - 1), fmt(k[interior].min()),
                                        fmt(k[interior].max())))
check(abs(tau_mean / 0.2 - 1) < 0.05, "helix.vtp: mean interior torsion within 5% of 0.2",
      "%s (%.3f%%); pointwise %s..%s" % (fmt(tau_mean), 100 * (tau_mean / 0.2 - 1), fmt(tau[interior].min()),
                                        fmt(tau[interior].max())))
# With 8 points per turn the cubic's curvature and torsion oscillate within each
# span (about +-6% and +-10%): that is the cubic, not an error; SciPy's
# CubicSpline (not-a-knot, chord-length knots) gives the same pointwise range.
check(abs(k[interior].min() - 0.388094062814448) < 1e-9 and abs(k[interior].max() - 0.43339577139897) < 1e-9
      and abs(tau[interior].min() - 0.178492980556143) < 1e-9
      and abs(tau[interior].max() - 0.217835196506046) < 1e-9,
      "helix.vtp: interior pointwise range equals SciPy CubicSpline's",
      "curvature %s..%s, torsion %s..%s" % (fmt(k[interior].min()), fmt(k[interior].max()),
                                           fmt(tau[interior].min()), fmt(tau[interior].max())))
check(abs(facts["length"][0] - 8 * math.pi * math.sqrt(5)) < 0.01 * 8 * math.pi * math.sqrt(5),
      "helix.vtp: Length within 1% of 8 pi sqrt(5) = 56.199", fmt(facts["length"][0]))

# A denser helix (32 points per turn): pointwise accuracy.
# (Built here and handed over with a trivial producer: a ProgrammableSource would run
# its script in this module's namespace and leave numpy_interface's max/min behind.)
dense_points = vtkPoints()
dense_points.SetDataTypeToDouble()
dense_lines = vtkCellArray()
dense_lines.InsertNextCell(129)
for i in range(129):
    t = i * math.pi / 16
    dense_points.InsertNextPoint(2 * math.cos(t), 2 * math.sin(t), t)
    dense_lines.InsertCellPoint(i)
dense_helix = vtkPolyData()
dense_helix.SetPoints(dense_points)
dense_helix.SetLines(dense_lines)
dense = PVTrivialProducer()
dense.GetClientSideObject().SetOutput(dense_helix)
dense_out = run(LOG.watch(CubicSpline(Input=dense)), "CubicSpline(dense helix)")
k, tau, span = (point_array(dense_out, n) for n in (names.Curvature, names.Torsion, names.SpanIndex))
interior = (span >= 4) & (span <= 123)
k_err = np.abs(k[interior] / 0.4 - 1).max()
tau_err = np.abs(tau[interior] / 0.2 - 1).max()
check(k_err < 0.02 and tau_err < 0.05, "dense helix (32 points/turn): pointwise interior curvature within 2%, "
      "torsion within 5%", "max deviation %.3f%% and %.3f%%" % (100 * k_err, 100 * tau_err))

# --------------------------------------------------------------------------- end conditions
print("== End Condition")
# SciPy CubicSpline on helix.vtp, chord-length knots, bc_type natural / not-a-knot /
# first derivatives of the end parabolas; samples 0, 5, 10, 160, 315, 320 of 321.
SCIPY = {
    "Natural": ([0.0, 0.251943330256563, 0.544062028104898, 0.42249065279016, 0.251943330256563, 0.0],
                [0.0, 0.0, 0.196016091773677, 0.18072024790789, 0.0, 0.0]),
    "Not A Knot": ([0.477568351621342, 0.444738110579291, 0.38099340672396, 0.422490653481714,
                    0.444738110579292, 0.477568351621344],
                   [0.0947073101610354, 0.149201730323541, 0.200273128022103, 0.180720247722862,
                    0.149201730323542, 0.0947073101610354]),
    "Clamped": ([0.213394424879669, 0.390124993058961, 0.440663372945815, 0.422490652954703,
                 0.390124993058961, 0.213394424879669],
                [-0.13559469296526, -0.103986975309229, 0.269216437486671, 0.180720248137175,
                 -0.103986975309229, -0.13559469296526]),
}
SAMPLES = [0, 5, 10, 160, 315, 320]
helix_src, helix_in = data_sets["helix.vtp"]
spline = LOG.watch(CubicSpline(Input=helix_src))
end_outputs = {}
for condition in ("Natural", "Not A Knot", "Clamped"):
    spline.EndCondition = condition
    out = run(spline, "EndCondition=%s" % condition)
    check_curve("EndCondition=%s" % condition, out, helix_in, expected_points=321)
    k, tau = point_array(out, names.Curvature), point_array(out, names.Torsion)
    ref_k, ref_tau = SCIPY[condition]
    err = max(np.abs(k[SAMPLES] - ref_k).max(), np.abs(tau[SAMPLES] - ref_tau).max())
    check(err < 1e-9, "EndCondition=%s: curvature and torsion equal SciPy's" % condition,
          "ends k=%s..%s tau=%s..%s, max |diff| %.2g" % (fmt(k[0]), fmt(k[-1]), fmt(tau[0]), fmt(tau[-1]), err))
    end_outputs[condition] = out
natural, notaknot, clamped = (end_outputs[c] for c in ("Natural", "Not A Knot", "Clamped"))
k_nat = point_array(natural, names.Curvature)
check(k_nat[0] < 1e-12 and k_nat[-1] < 1e-12, "Natural: zero curvature at both ends",
      "%s, %s" % (fmt(k_nat[0]), fmt(k_nat[-1])))
# Clamped: the end tangents are those of the parabolas through the first/last three points.
pts = data_lines(helix_in)[0]
knots = np.r_[0, np.cumsum(np.linalg.norm(np.diff(pts, axis=0), axis=1))]


def parabola_derivative(t, p):
    d01 = (p[1] - p[0]) / (t[1] - t[0])
    d12 = (p[2] - p[1]) / (t[2] - t[1])
    return d01 + (t[0] - t[1]) * (d12 - d01) / (t[2] - t[0])


d0 = parabola_derivative(knots[:3], pts[:3])
dn = parabola_derivative(knots[::-1][:3], pts[::-1][:3])
T = point_array(clamped, names.Tangent)
angle = max(np.linalg.norm(np.cross(T[0], d0 / np.linalg.norm(d0))),
            np.linalg.norm(np.cross(T[-1], dn / np.linalg.norm(dn))))
check(angle < 1e-9, "Clamped: end tangents along the end parabolas", "sin(angle) %.2g" % angle)
P = {c: points_of(o) for c, o in end_outputs.items()}
end_diff = min(np.abs(P["Natural"] - P["Not A Knot"]).max(), np.abs(P["Clamped"] - P["Not A Knot"]).max(),
               np.abs(P["Natural"] - P["Clamped"]).max())
mid = slice(150, 171)
mid_diff = max(np.abs(P[a][mid] - P["Not A Knot"][mid]).max() for a in ("Natural", "Clamped"))
check(end_diff > 1e-3 and mid_diff < 1e-4, "End conditions change the ends, not the middle",
      "min end-span difference %s, middle difference %.2g" % (fmt(end_diff), mid_diff))

# --------------------------------------------------------------------------- parameterization
print("== Parameterization")
akima_src, akima_in = data_sets["akima.vtp"]
akima_pts = data_lines(akima_in)[0]
chords = np.linalg.norm(np.diff(akima_pts, axis=0), axis=1)
expected_knots = {"Uniform": np.r_[0, np.cumsum(np.ones_like(chords))],
                  "Chord Length": np.r_[0, np.cumsum(chords)],
                  "Centripetal": np.r_[0, np.cumsum(np.sqrt(chords))]}
spline = LOG.watch(CubicSpline(Input=akima_src))
param_points = {}
for kind, expected in expected_knots.items():
    spline.Parameterization = kind
    out = run(spline, "Parameterization=%s" % kind)
    check_curve("Parameterization=%s" % kind, out, akima_in, expected_points=101)
    knots_out = point_array(out, names.Parameter)[::10]
    err = np.abs(knots_out - expected).max()
    check(err < 1e-12 * expected[-1], "Parameterization=%s: Parameter at the data points" % kind,
          "last knot %s, max |diff| %.2g" % (fmt(knots_out[-1]), err))
    param_points[kind] = points_of(out)
diffs = [np.abs(param_points[a] - param_points[b]).max()
         for a, b in (("Uniform", "Chord Length"), ("Uniform", "Centripetal"), ("Chord Length", "Centripetal"))]
check(min(diffs) > 1e-2, "Parameterizations give different curves on unevenly spaced akima",
      "pairwise max differences %s" % [fmt(d) for d in diffs])
spline = LOG.watch(CubicSpline(Input=helix_src))
helix_points = {}
for kind in expected_knots:
    spline.Parameterization = kind
    helix_points[kind] = points_of(run(spline, "helix Parameterization=%s" % kind))
diff = max(np.abs(helix_points[a] - helix_points["Chord Length"]).max() for a in ("Uniform", "Centripetal"))
check(diff < 1e-9, "Parameterizations agree on the evenly spaced helix", "max difference %.2g" % diff)

# --------------------------------------------------------------------------- sampling
print("== Sampling Mode")
spline = LOG.watch(CubicSpline(Input=helix_src, NumberOfSubdivisions=1))
out = run(spline, "NumberOfSubdivisions=1")
got, want = points_of(out), points_of(helix_in)
same_count = out.GetNumberOfPoints() == helix_in.GetNumberOfPoints()
# Exact up to rounding: the spline is fitted about the centre of the line's
# bounding box and its end is evaluated, not copied, so a point may come back off
# by an ulp or two of the coordinates' magnitude.
error = np.abs(got - want).max() if same_count else float("inf")
identical = int(np.all(got == want, axis=1).sum()) if same_count else 0
check(same_count and error <= 1e-14 * np.abs(want).max(),
      "NumberOfSubdivisions=1 gives back the helix points (to rounding)",
      "%d points, %d bit-identical, max |diff| %.2g (coordinates up to %.3g)"
      % (out.GetNumberOfPoints(), identical, error, np.abs(want).max()))
spline.NumberOfSubdivisions = 20
out = run(spline, "NumberOfSubdivisions=20")
check_curve("NumberOfSubdivisions=20", out, helix_in, expected_points=32 * 20 + 1, subdivisions=20)
length_subdiv = cell_array(out, names.Length)[0]
spline.SamplingMode = "Arc Length"
spline.SampleLength = 0.5
out = run(spline, "SamplingMode=Arc Length, SampleLength=0.5")
facts = check_curve("SamplingMode=Arc Length", out, helix_in)
n, length = out.GetNumberOfPoints(), facts["length"][0]
check(length / 0.5 <= n - 1 <= length / 0.5 + 32, "Arc Length 0.5: about Length/0.5 samples",
      "%d samples for Length %s (Length/0.5 = %s)" % (n, fmt(length), fmt(length / 0.5)))
arc, span = point_array(out, names.ArcLength), point_array(out, names.SpanIndex)
steps = np.diff(arc)
same_span = span[1:] == span[:-1]
spread = max(np.ptp(steps[(span[1:] == j) & same_span]) for j in range(32))
check(steps.max() <= 0.5 + 1e-9 and spread < 1e-9, "Arc Length 0.5: even spacing <= 0.5 within each span",
      "spacing %s..%s, spread within spans %.2g" % (fmt(steps.min()), fmt(steps.max()), spread))
check(abs(length - length_subdiv) < 1e-9 * length, "Length does not depend on the sampling",
      "%s vs %s" % (fmt(length), fmt(length_subdiv)))

# Aorta at one subdivision: the input points minus the merged repeat, radius carried.
aorta_src, aorta_in = data_sets["aorta-centerline.vtp"]
spline = LOG.watch(CubicSpline(Input=aorta_src, NumberOfSubdivisions=1))
out = run(spline, "aorta NumberOfSubdivisions=1")
in_pts = points_of(aorta_in)
in_r = point_array(aorta_in, "MaximumInscribedSphereRadius")
want_pts, want_r, want_merged = [], [], []
for ids in lines_of(aorta_in):
    kept = np.asarray(ids)[clean_line(in_pts[ids])]
    want_merged.append(len(ids) - len(kept))
    want_pts.append(in_pts[kept])
    want_r.append(in_r[kept])
want_pts, want_r = np.concatenate(want_pts), np.concatenate(want_r)
got_r = point_array(out, "MaximumInscribedSphereRadius")
check(out.GetNumberOfPoints() == len(want_pts) and np.abs(points_of(out) - want_pts).max() < 1e-12 * 300
      and np.abs(got_r - want_r).max() < 1e-12,
      "aorta NumberOfSubdivisions=1: input points (repeat merged) and their radii",
      "%d of %d points, max |diff| %.2g, radius |diff| %.2g" % (out.GetNumberOfPoints(), aorta_in.GetNumberOfPoints(),
                                                              np.abs(points_of(out) - want_pts).max(),
                                                              np.abs(got_r - want_r).max()))
check(list(cell_array(out, names.MergedPoints)) == want_merged and sum(want_merged) > 0,
      "aorta: the routine merge counted in MergedPoints, not warned",
      "%s, expected %s" % (list(cell_array(out, names.MergedPoints)), want_merged))

# --------------------------------------------------------------------------- aorta arrays
print("== aorta: two lines, repeated point, carried arrays")
spline, out, facts = defaults["aorta-centerline.vtp"]
r_in = point_array(aorta_in, "MaximumInscribedSphereRadius")
r_out = point_array(out, "MaximumInscribedSphereRadius")
check(r_out.min() >= r_in.min() - 1e-12 and r_out.max() <= r_in.max() + 1e-12,
      "aorta: MaximumInscribedSphereRadius carried within the input range",
      "output %s..%s, input %s..%s" % (fmt(r_out.min()), fmt(r_out.max()), fmt(r_in.min()), fmt(r_in.max())))
check(out.GetNumberOfCells() == 2 and [len(ids) for ids in facts["lines"]] == [2091, 1971],
      "aorta: 2 lines of 209 and 197 spans sampled 10 times",
      "%s samples per line" % [len(ids) for ids in facts["lines"]])
k, tau = point_array(out, names.Curvature), point_array(out, names.Torsion)
print("     aorta: Length %s, curvature max %s, torsion %s..%s (98th percentile |torsion| %s), "
      "ShapeViolations %s" % ([fmt(x) for x in facts["length"]], fmt(k.max()), fmt(tau.min()), fmt(tau.max()),
                              fmt(np.percentile(np.abs(tau), 98)), list(facts["violations"])))

# --------------------------------------------------------------------------- closed
print("== Closed")
spline = LOG.watch(CubicSpline(Input=akima_src, Closed=1))
out = run(spline, "Closed=1 (akima)")
ids = lines_of(out)[0]
arc = point_array(out, names.ArcLength)
check(out.GetNumberOfPoints() == 11 * 10 and len(ids) == 111 and ids[0] == ids[-1]
      and cell_array(out, names.Tortuosity)[0] == 0
      and cell_array(out, names.Length)[0] > arc[ids[-2]] > defaults["akima.vtp"][2]["length"][0],
      "Closed=1: periodic curve, 11 spans, seam not repeated, Tortuosity 0",
      "%d points, cell of %d ids closing on %d, Length %s (open %s)"
      % (out.GetNumberOfPoints(), len(ids), ids[-1], fmt(cell_array(out, names.Length)[0]),
         fmt(defaults["akima.vtp"][2]["length"][0])))

# --------------------------------------------------------------------------- tolerances
print("== shape tolerances")
spline = LOG.watch(CubicSpline(Input=akima_src))
counts = []
for tolerance in (1e-3, 0.1, 1.0):
    spline.CurveShapeTolerance = tolerance
    counts.append(int(cell_array(run(spline, "CurveShapeTolerance=%g" % tolerance), names.ShapeViolations)[0]))
check(counts[0] > counts[1] > counts[2] == 0 and counts[0] == defaults["akima.vtp"][2]["violations"][0],
      "CurveShapeTolerance 1e-3 / 0.1 / 1: fewer violations on akima", "%s" % counts)
spline.CurveShapeTolerance = 1e-3
counts = []
for tolerance in (1e-6, 1.0):
    spline.DataShapeTolerance = tolerance
    counts.append(int(cell_array(run(spline, "DataShapeTolerance=%g" % tolerance), names.ShapeViolations)[0]))
check(counts[1] > counts[0], "DataShapeTolerance 1e-6 / 1: every point collinear gives more violations on akima",
      "%s" % counts)

# --------------------------------------------------------------------------- VMTK names
print("== VMTK Array Names")
spline = LOG.watch(CubicSpline(Input=aorta_src, VMTKArrayNames=1))
out = run(spline, "VMTKArrayNames=1")
same = all(np.array_equal(point_array(out, "Frenet" + n), point_array(out, n))
           for n in (names.Tangent, names.Normal, names.Binormal))
check(same, "VMTKArrayNames=1: FrenetTangent/Normal/Binormal equal Tangent/Normal/Binormal",
      "%d point arrays" % out.GetPointData().GetNumberOfArrays())
plain = defaults["aorta-centerline.vtp"][1]
check(all(plain.GetPointData().GetArray("Frenet" + n) is None for n in (names.Tangent, names.Normal, names.Binormal)),
      "VMTKArrayNames=0 (default): no Frenet* arrays", "%d point arrays" % plain.GetPointData().GetNumberOfArrays())

# =========================================================================== PolylineShapeAnalysis
print("== PolylineShapeAnalysis without a curve")


def check_discrete(label, out, inp):
    """The analysis output: the input geometry and arrays plus the discrete arrays, all finite."""
    n = inp.GetNumberOfPoints()
    problems = [name for name, comps in DISCRETE_ARRAYS.items()
                if out.GetPointData().GetArray(name) is None
                or out.GetPointData().GetArray(name).GetNumberOfTuples() != n
                or out.GetPointData().GetArray(name).GetNumberOfComponents() != comps]
    if out.GetNumberOfPoints() != n or out.GetNumberOfCells() != inp.GetNumberOfCells():
        problems.append("geometry changed")
    if not np.array_equal(points_of(out), points_of(inp)):
        problems.append("points changed")
    problems += ["input array %s lost" % inp.GetPointData().GetArrayName(i)
                 for i in range(inp.GetPointData().GetNumberOfArrays())
                 if out.GetPointData().GetAbstractArray(inp.GetPointData().GetArrayName(i)) is None]
    for attributes in (out.GetPointData(), out.GetCellData()):
        problems += ["%s not finite" % attributes.GetArrayName(i) for i in range(attributes.GetNumberOfArrays())
                     if attributes.GetArray(i) is not None
                     and not np.all(np.isfinite(vtk_to_numpy(attributes.GetArray(i))))]
    check(not problems, "%s: discrete arrays on the input geometry" % label,
          "; ".join(problems) if problems else "%d points, %d cells, %d point + %d cell arrays, all finite"
          % (n, out.GetNumberOfCells(), out.GetPointData().GetNumberOfArrays(),
             out.GetCellData().GetNumberOfArrays()))


analysis = LOG.watch(PolylineShapeAnalysis(Input=helix_src))
out = run(analysis, "PolylineShapeAnalysis(helix)")
check_discrete("PolylineShapeAnalysis(helix)", out, helix_in)
check(out.GetPointData().GetArray(names.ViolationMask) is None and out.GetCellData().GetArray(names.ShapeViolations) is None,
      "PolylineShapeAnalysis without Curve: no audit arrays", "")
dtau, dk = point_array(out, names.DiscreteTorsion), point_array(out, names.DiscreteCurvature)
hp = points_of(helix_in)
a, b = hp[1:-1] - hp[:-2], hp[2:] - hp[1:-1]
menger = 2 * np.linalg.norm(np.cross(a, b), axis=1) / (np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1)
                                                       * np.linalg.norm(a + b, axis=1))
check(np.all(dtau[1:31] > 0) and dtau[0] == 0 and dtau[31] == 0 and dtau[32] == 0,
      "helix: DiscreteTorsion positive in the interior, 0 at the ends",
      "interior %s..%s" % (fmt(dtau[1:31].min()), fmt(dtau[1:31].max())))
check(np.abs(dk[1:-1] - menger).max() < 1e-12 and dk[0] == 0 and dk[-1] == 0,
      "helix: DiscreteCurvature is the Menger curvature", "%s (closed form 0.4)" % fmt(dk[1:-1].mean()))
check(np.all(point_array(out, names.Convex)[1:-1] == 1) and not np.any(point_array(out, names.Collinear))
      and not np.any(point_array(out, names.Coplanar)),
      "helix: all interior points convex, none collinear or coplanar", "")

analysis = LOG.watch(PolylineShapeAnalysis(Input=akima_src))
out = run(analysis, "PolylineShapeAnalysis(akima)")
check_discrete("PolylineShapeAnalysis(akima)", out, akima_in)
collinear, convex, coplanar = (list(point_array(out, n)) for n in (names.Collinear, names.Convex, names.Coplanar))
check(collinear == [0, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0], "akima: the flat run y=10 (points 1-4) flagged Collinear",
      "Collinear %s" % collinear)
# Segments 0-4 touch the flat run's collinear points, where no plane exists:
# no coplanarity criterion on them (the flat run's is collinearity).
check(convex == [0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 0] and coplanar == [0, 0, 0, 0, 0, 1, 1, 1, 1, 0, 0]
      and not np.any(point_array(out, names.DiscreteTorsion)),
      "akima: points 5-9 convex, segments 5-8 coplanar (0-4 touch the flat run), zero discrete torsion",
      "Convex %s, Coplanar %s" % (convex, coplanar))

print("== PolylineShapeAnalysis with Curve = CubicSpline output")
audits = {}
for file_name in ("akima.vtp", "helix.vtp", "aorta-centerline.vtp"):
    src, inp = data_sets[file_name]
    warnings = ()
    curve = LOG.watch(CubicSpline(Input=src, NumberOfSubdivisions=16))
    analysis = LOG.watch(PolylineShapeAnalysis(Input=src, Curve=curve))
    out = run(analysis, "PolylineShapeAnalysis(%s, Curve)" % file_name, warnings)
    check_discrete("PolylineShapeAnalysis(%s, Curve)" % file_name, out, inp)
    missing = [n for n in AUDIT_CELL_ARRAYS if out.GetCellData().GetArray(n) is None]
    check(out.GetPointData().GetArray(names.ViolationMask) is not None and not missing,
          "%s: ViolationMask and the audit cell arrays present" % file_name,
          "missing %s" % missing if missing else "")
    viol = cell_array(out, names.ShapeViolations)
    parts = sum(cell_array(out, n) for n in AUDIT_CELL_ARRAYS[2:])
    filter_viol = cell_array(servermanager.Fetch(curve), names.ShapeViolations)
    # The filter audits each knot from both sides (torsion jumps at knots); the
    # analysis sees the samples only, a knot from the span after it: it can find
    # fewer torsion-sign failures, never more, and the same where torsion has no sign.
    same = np.array_equal(viol, filter_viol) if not file_name.startswith("aorta") else np.all(viol <= filter_viol)
    check(np.array_equal(viol, parts) and same
          and np.array_equal(cell_array(out, names.ShapePreserving), (viol == 0).astype(int)),
          "%s: ShapeViolations = sum of the criteria, and %s the filter's own audit (16 samples/span)"
          % (file_name, "at most" if file_name.startswith("aorta") else "equal to"),
          "analysis %s, filter %s" % (list(viol), list(filter_viol)))
    audits[file_name] = out
akima_viol = cell_array(audits["akima.vtp"], names.ShapeViolations)[0]
mask = list(point_array(audits["akima.vtp"], names.ViolationMask))
check(akima_viol > 0 and any(mask[1:5]), "akima: the cubic violates the Akima shape",
      "ShapeViolations %d, ViolationMask %s, collinearity %d, convexity at knot %d"
      % (akima_viol, mask, cell_array(audits["akima.vtp"], "CollinearityViolations")[0],
         cell_array(audits["akima.vtp"], "ConvexityAtKnotViolations")[0]))
check(cell_array(audits["helix.vtp"], names.ShapeViolations)[0] == 0
      and not np.any(point_array(audits["helix.vtp"], names.ViolationMask)),
      "helix: the cubic preserves the helix's shape", "ShapeViolations 0")

# The audit sees the curve only at the curve's samples: at the default 10 per span
# it can differ from the filter's own audit (16 per span).
curve = LOG.watch(CubicSpline(Input=aorta_src))
coarse = run(PolylineShapeAnalysis(Input=aorta_src, Curve=curve), "aorta analysis, 10 samples/span")
print("     aorta: ShapeViolations seen by the analysis on 10 samples/span %s, by the filter (16/span) %s"
      % (list(cell_array(coarse, names.ShapeViolations)), list(cell_array(fetch(curve), names.ShapeViolations))))

print("== Closed in PolylineShapeAnalysis")
curve = LOG.watch(CubicSpline(Input=akima_src, Closed=1, NumberOfSubdivisions=16))
analysis = LOG.watch(PolylineShapeAnalysis(Input=akima_src, Curve=curve, Closed=1))
out = run(analysis, "PolylineShapeAnalysis(akima, Closed=1, Curve closed)")
check_discrete("PolylineShapeAnalysis(akima, Closed=1, Curve closed)", out, akima_in)
dk = point_array(out, names.DiscreteCurvature)
check(dk[0] > 0 and dk[-1] > 0 and np.array_equal(cell_array(out, names.ShapeViolations),
                                                  cell_array(fetch(curve), names.ShapeViolations)),
      "Closed=1: the ends get a discrete curvature and the closed curve is audited like the filter does",
      "DiscreteCurvature at the ends %s, %s; ShapeViolations %d"
      % (fmt(dk[0]), fmt(dk[-1]), cell_array(out, names.ShapeViolations)[0]))
analysis.Closed = 0
out = run(analysis, "PolylineShapeAnalysis(akima, Closed=0, Curve closed)", ("not audited",))
# A line that is not audited reads ShapeViolations -1 and ShapePreserving 0: never a pass.
check(cell_array(out, names.ShapeViolations)[0] == -1 and cell_array(out, names.ShapePreserving)[0] == 0
      and not np.any(point_array(out, names.ViolationMask)),
      "Closed=0 with a closed curve: warned and not audited",
      "ShapeViolations 0, empty ViolationMask, ShapePreserving %d" % cell_array(out, names.ShapePreserving)[0])

# =========================================================================== CurvatureComb
print("== CurvatureComb on the Akima cubic")
curve = LOG.watch(CubicSpline(Input=akima_src, NumberOfSubdivisions=8))
comb = LOG.watch(CurvatureComb(Input=curve, Stride=2))
out = run(comb, "CurvatureComb(akima cubic, Stride=2)")
curve_out = fetch(curve)
samples = curve_out.GetNumberOfPoints()
teeth = (samples - 1) // 2 + 1 + (1 if (samples - 1) % 2 else 0)
cells = lines_of(out)
base = points_of(out)
lengths = [np.linalg.norm(base[c[1]] - base[c[0]]) for c in cells[:teeth]]
diagonal = curve_out.GetLength()
typical = np.sort(lengths)[int(0.95 * (len(lengths) - 1))]
check(len(cells) == teeth + 1 and len(cells[-1]) == teeth and abs(typical - 0.15 * diagonal) < 1e-9 * diagonal,
      "CurvatureComb: a tooth per second sample and the last, one envelope, 95th percentile tooth 0.15 diagonal",
      "%d cells for %d samples, 95th percentile tooth %s of the diagonal" % (len(cells), samples, fmt(typical / diagonal)))
comb.CombType = "Torsion"
out = run(comb, "CurvatureComb(akima cubic, Torsion)")
# A planar curve has zero torsion: the torsion comb has zero-length teeth.
check(np.allclose(points_of(out)[0::2][:teeth], points_of(out)[1::2][:teeth], atol=1e-12 * diagonal),
      "CurvatureComb(Torsion) of a planar curve has zero-length teeth")

# =========================================================================== GeneralizedCubicSpline
print("== GeneralizedCubicSpline on the classic shape data")
for file_name in ("akima.vtp", "rpn15a.vtp", "titanium.vtp"):
    src = reader(file_name)
    plain = fetch(LOG.watch(CubicSpline(Input=src)))
    spline = LOG.watch(GeneralizedCubicSpline(Input=src))
    out = run(spline, "GeneralizedCubicSpline(%s)" % file_name)
    tension = point_array(out, "Tension")
    check(cell_array(plain, names.ShapeViolations)[0] > 0 and cell_array(out, names.ShapeViolations)[0] == 0
          and cell_array(out, "MaxTension")[0] == tension.max() > 0 and tension.min() == 0,
          "%s: the cubic breaks the shape, the automatic tension does not, and only some spans are tensioned"
          % file_name, "cubic %d violations, generalized %d; tension %s..%s"
          % (cell_array(plain, names.ShapeViolations)[0], cell_array(out, names.ShapeViolations)[0],
             fmt(tension.min()), fmt(tension.max())))
spline = LOG.watch(GeneralizedCubicSpline(Input=reader("akima.vtp"), SpaceKind="Trigonometric", Tension=5.0,
                                          Automatic=0))
out = run(spline, "GeneralizedCubicSpline(akima, Trigonometric, Tension=5)", ("limited to 0.99 pi",))
check(abs(point_array(out, "Tension").max() - 0.99 * np.pi) < 1e-12,
      "Trigonometric tension 5 is limited to 0.99 pi, with a warning")

# =========================================================================== TensionQuinticSpline
print("== TensionQuinticSpline on Akima's data and the helix")
akima_points = np.array([[0, 10], [2, 10], [3, 10], [5, 10], [6, 10], [8, 10], [9, 10.5], [11, 15],
                         [12, 50], [14, 60], [15, 85]], dtype=float)
turn = akima_points[1:-1] - akima_points[:-2], akima_points[2:] - akima_points[1:-1]
akima_menger = np.max(2 * np.abs(np.cross(turn[0], turn[1])) / (
    np.linalg.norm(turn[0], axis=1) * np.linalg.norm(turn[1], axis=1) *
    np.linalg.norm(akima_points[2:] - akima_points[:-2], axis=1)))
for continuity in ("C3", "C4"):
    plain = LOG.watch(TensionQuinticSpline(Input=reader("akima.vtp"), Continuity=continuity, Automatic=0))
    automatic = LOG.watch(TensionQuinticSpline(Input=reader("akima.vtp"), Continuity=continuity))
    p_out = run(plain, "TensionQuinticSpline(akima, %s, fixed)" % continuity)
    # Akima's straight run keeps a collinearity violation at gamma's floor:
    # the warning names it.
    a_out = run(automatic, "TensionQuinticSpline(akima, %s, automatic)" % continuity,
                ["keep shape violations", "collinearity at knot"])
    # Fewer violations, and no cusp: the curvature within 1e4 times the data's
    # largest discrete curvature (Akima's straight run would need one).
    largest = point_array(a_out, names.Curvature).max()
    check(cell_array(a_out, names.ShapeViolations)[0] < cell_array(p_out, names.ShapeViolations)[0]
          and 0 < cell_array(a_out, "MinGamma")[0] <= 1 and largest <= 1e4 * akima_menger,
          "TensionQuinticSpline %s: Akima's violations at gamma = 1 lowered in automatic mode, no cusp" % continuity,
          "%d -> %d violations, MinGamma %s, largest curvature %s (data's %s)" % (
              cell_array(p_out, names.ShapeViolations)[0], cell_array(a_out, names.ShapeViolations)[0],
              fmt(cell_array(a_out, "MinGamma")[0]), fmt(largest), fmt(akima_menger)))
out = run(LOG.watch(TensionQuinticSpline(Input=reader("helix.vtp"))), "TensionQuinticSpline(helix)")
k, tau = interior_values(point_array(out, names.Curvature)), interior_values(point_array(out, names.Torsion))
check(np.max(np.abs(k - 0.4)) < 4e-3 and np.max(np.abs(tau - 0.2)) < 4e-3,
      "TensionQuinticSpline(helix, 8 points per turn): curvature 0.4 and torsion 0.2 within 1%",
      "curvature %s..%s, torsion %s..%s" % (fmt(k.min()), fmt(k.max()), fmt(tau.min()), fmt(tau.max())))

# =========================================================================== VariableDegreeSpline
print("== VariableDegreeSpline on Akima's data, the helix and noisy helix points")
plain = LOG.watch(VariableDegreeSpline(Input=reader("akima.vtp"), Automatic=0))
automatic = LOG.watch(VariableDegreeSpline(Input=reader("akima.vtp")))
p_out = run(plain, "VariableDegreeSpline(akima, degree 5)")
a_out = run(automatic, "VariableDegreeSpline(akima, automatic)")
degree = point_array(a_out, "Degree")
check(cell_array(p_out, names.ShapeViolations)[0] > 0 and cell_array(a_out, names.ShapeViolations)[0] == 0
      and degree.min() < degree.max() == cell_array(a_out, "MaxDegree")[0],
      "VariableDegreeSpline: Akima's shape broken by the quintic, kept with degrees raised where needed",
      "%d -> %d violations, MaxDegree %s" % (cell_array(p_out, names.ShapeViolations)[0],
                                            cell_array(a_out, names.ShapeViolations)[0],
                                            fmt(cell_array(a_out, "MaxDegree")[0])))
out = run(LOG.watch(VariableDegreeSpline(Input=reader("helix.vtp"))), "VariableDegreeSpline(helix)")
k, tau = interior_values(point_array(out, names.Curvature)), interior_values(point_array(out, names.Torsion))
check(np.max(np.abs(k - 0.4)) < 4e-3 and np.max(np.abs(tau - 0.2)) < 4e-3,
      "VariableDegreeSpline(helix, 8 points per turn): curvature 0.4 and torsion 0.2 within 1%",
      "curvature %s..%s, torsion %s..%s" % (fmt(k.min()), fmt(k.max()), fmt(tau.min()), fmt(tau.max())))
for mode in ("Approximate Global", "Approximate Local"):
    out = run(LOG.watch(VariableDegreeSpline(Input=reader("helix.vtp"), Mode=mode, NumberOfKnots=6)),
              "VariableDegreeSpline(helix, %s)" % mode)
    check(cell_array(out, names.ShapeViolations)[0] == 0 and point_array(out, "Degree").min() >= 5,
          "VariableDegreeSpline %s: keeps the shape of psi" % mode,
          "violations %d" % cell_array(out, names.ShapeViolations)[0])

# =========================================================================== QQRSpline
print("== QQRSpline on Akima's data and the helix")
out = run(LOG.watch(QQRSpline(Input=reader("akima.vtp"))), "QQRSpline(akima, interpolation)")
automatic = cell_array(out, names.ShapeViolations)[0]
fixed_out = run(LOG.watch(QQRSpline(Input=reader("akima.vtp"), Automatic=0)), "QQRSpline(akima, alpha 4)")
check(automatic == 0 < cell_array(fixed_out, names.ShapeViolations)[0] and point_array(fixed_out, "Alpha").max() == 4
      and point_array(fixed_out, "Straightness").max() == 0 < cell_array(out, "MaxStraightness")[0] <= 1,
      "QQRSpline: the automatic mode straightens Akima's flat run (alpha = beta = 4 breaks it); Alpha and "
      "Straightness written",
      "%d (automatic) vs %d violations, MaxStraightness %s" % (
          automatic, cell_array(fixed_out, names.ShapeViolations)[0], fmt(cell_array(out, "MaxStraightness")[0])))
polygon = run(LOG.watch(QQRSpline(Input=reader("helix.vtp"), Mode="Approximate", Automatic=0)),
              "QQRSpline(helix, control polygon)")
cubic_bspline = run(LOG.watch(QQRSpline(Input=reader("helix.vtp"), Mode="Approximate", Automatic=0,
                                        Continuity="C2 and FC(2l+3)", FrenetOrder=3)),
                    "QQRSpline(helix, control polygon, FC9)")
check(point_array(cubic_bspline, "Alpha").min() == 6 and point_array(polygon, "Alpha").max() == 4,
      "QQRSpline: C2 and FC(2l+3) with l = 3 raises alpha = beta to l + 3 = 6",
      "Alpha %s" % fmt(point_array(cubic_bspline, "Alpha").min()))
run(LOG.watch(QQRSpline(Input=reader("helix.vtp"), Continuity="C2 and FC(2l+3)")),
    "QQRSpline(helix, interpolation, FC asked)", ("using C2",))

# =========================================================================== Automatic, old names
print("== Automatic on every shape-preserving family; the old names still set it")


def akima_violations(proxy):
    return cell_array(run(proxy, proxy.GetXMLName()), names.ShapeViolations)[0]


for family, old in ((GeneralizedCubicSpline, "AutomaticTension"), (TensionQuinticSpline, None),
                    (VariableDegreeSpline, "AutomaticDegrees"), (QQRSpline, None)):
    automatic = akima_violations(family(Input=reader("akima.vtp")))
    fixed = akima_violations(family(Input=reader("akima.vtp"), Automatic=0))
    check(fixed > automatic, "%s: Automatic=0 fixes the shape parameters" % family.__name__,
          "Akima's violations %d fixed, %d automatic" % (fixed, automatic))
    if old is None:
        continue
    # The old name is a hidden alias of Automatic, empty until a script sets
    # it: it sets Automatic at creation and later, and never overrides it.
    proxy = family(Input=reader("akima.vtp"), **{old: 0})
    states = [akima_violations(proxy)]
    setattr(proxy, old, 1)
    states.append(akima_violations(proxy))
    proxy.Automatic = 0
    states.append(akima_violations(proxy))
    check(states == [fixed, automatic, fixed] and proxy.GetProperty(old).SMProperty.GetPanelVisibility() == "never",
          "%s: the hidden old name %s still sets Automatic" % (family.__name__, old),
          "violations after %s=0, %s=1, Automatic=0: %s" % (old, old, states))

# =========================================================================== Table To Points
print("== CSV -> Table To Points -> spline filter (Connect Points)")
# Two helices 10 apart in one CSV with a track column: two lines of their own.
os.makedirs(args.temp, exist_ok=True)
csv_path = os.path.join(args.temp, "two_tracks.csv")
t = np.arange(20) * 0.4
with open(csv_path, "w") as csv:
    csv.write("x,y,z,track\n")
    for track, shift in ((5, 0.0), (7, 10.0)):
        for ti in t:
            csv.write("%r,%r,%r,%d\n" % (math.cos(ti), math.sin(ti) + shift, 0.25 * ti, track))
table_points = TableToPoints(Input=CSVReader(FileName=[csv_path]), XColumn="x", YColumn="y",
                             ZColumn="z")
for family in (CubicSpline, GeneralizedCubicSpline):
    out = run(LOG.watch(family(Input=table_points)), "%s(Table To Points)" % family.__name__)
    lengths = cell_array(out, names.Length)
    check(out.GetNumberOfLines() == 2 and list(cell_array(out, names.LineId)) == [5, 7]
          and np.abs(lengths - 7.6 * math.sqrt(1.0625)).max() < 0.01,
          "%s(Table To Points): two lines, LineId 5 and 7, each one helix long" % family.__name__,
          "%d lines, LineId %s, lengths %s" % (out.GetNumberOfLines(),
                                               list(cell_array(out, names.LineId)), np.round(lengths, 4)))
out = run(LOG.watch(CubicSpline(Input=table_points, ConnectPoints=0)), "CubicSpline(points, ConnectPoints=0)",
          ("Input has no lines",))
check(out.GetNumberOfPoints() == 0, "Connect Points off: points without lines give an empty output",
      "%d points" % out.GetNumberOfPoints())

# =========================================================================== summary
elapsed = time.time() - START
if failures:
    print("\n%d of %d checks FAILED (%.1f s):" % (len(failures), check_count[0], elapsed))
    for f in failures:
        print("  - " + f)
    sys.exit(1)
print("\nAll %d checks passed (%.1f s)." % (check_count[0], elapsed))
