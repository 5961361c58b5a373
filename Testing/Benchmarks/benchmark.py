"""Speed and accuracy of the ShapeSplines families against vtkSplineFilter, SciPy and
finite differences, on the same input.

Run (prints tables of output points per second and ratios, all measured in this run,
cost growth, memory and accuracy, and writes plots into build/benchmark/):
    bash Testing/Scripts/benchmark.sh

Every contender produces the same number of output points per line (10 per span, the
knots included). Ours also computes the Frenet frame, curvature, torsion, arc length
and the shape audit; vtkSplineFilter computes positions only; the SciPy route computes
positions, derivatives and curvature/torsion with NumPy.
"""
import argparse
import os
import time

import numpy as np
from paraview import simple
from scipy.interpolate import make_interp_spline
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints, vtkSMPTools
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersGeneral import vtkSplineFilter

SUBDIVISIONS = 10


def helix_lines(lines, points_per_line, points_per_turn=8.0, seed=1):
    """Helices of random radius and pitch, as an array (lines, points, 3)."""
    rng = np.random.default_rng(seed)
    t = 2 * np.pi * np.arange(points_per_line) / points_per_turn
    radius = rng.uniform(1, 3, size=(lines, 1))
    pitch = rng.uniform(0.2, 1, size=(lines, 1))
    phase = rng.uniform(0, 2 * np.pi, size=(lines, 1))
    return np.stack([radius * np.cos(t + phase), radius * np.sin(t + phase), pitch * t], axis=-1)


def to_polydata(xyz):
    lines, n, _ = xyz.shape
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz.reshape(-1, 3).copy(), deep=True))
    offsets = numpy_to_vtkIdTypeArray(np.arange(0, lines * n + 1, n, dtype=np.int64), deep=True)
    connectivity = numpy_to_vtkIdTypeArray(np.arange(lines * n, dtype=np.int64), deep=True)
    cells = vtkCellArray()
    cells.SetData(offsets, connectivity)
    poly = vtkPolyData()
    poly.SetPoints(points)
    poly.SetLines(cells)
    return poly


def best_time(run, repeats, budget=5.0):
    """The best of up to 'repeats' runs, stopping once they have taken 'budget'
    seconds: short runs repeat (one run of a few milliseconds varied 3x
    between benchmark runs here), long ones (vtkSplineFilter on 1.6e4 points)
    run once."""
    best, spent = float("inf"), 0.0
    for _ in range(repeats):
        start = time.perf_counter()
        output_points = run()
        seconds = time.perf_counter() - start
        best, spent = min(best, seconds), spent + seconds
        if spent >= budget:
            break
    return best, output_points


def ours(poly, backend, family="CubicSpline", **properties):
    vtkSMPTools.SetBackend(backend)
    algorithm = getattr(simple, family)(Input=simple.Line(), **properties).GetClientSideObject()
    algorithm.SetInputDataObject(0, poly)

    def run():
        algorithm.Modified()
        algorithm.Update()
        return algorithm.GetOutputDataObject(0).GetNumberOfPoints()
    return run


def vtk_spline(poly, points_per_line):
    spline = vtkSplineFilter()
    spline.SetInputData(poly)
    spline.SetSubdivideToSpecified()
    spline.SetNumberOfSubdivisions(points_per_line - 1)

    def run():
        spline.Modified()
        spline.Update()
        return spline.GetOutput().GetNumberOfPoints()
    return run


def scipy_route(xyz):
    """make_interp_spline (not-a-knot, chord length) + derivatives + curvature/torsion."""
    def run():
        total = 0
        for line in xyz:
            chord = np.linalg.norm(np.diff(line, axis=0), axis=1)
            t = np.concatenate([[0.0], np.cumsum(chord)])
            spline = make_interp_spline(t, line, k=3)
            u = np.linspace(t[0], t[-1], (len(t) - 1) * SUBDIVISIONS + 1)
            d1, d2, d3 = (spline(u, nu) for nu in (1, 2, 3))
            cross = np.cross(d1, d2)
            cross2 = np.einsum("ij,ij->i", cross, cross)
            speed = np.linalg.norm(d1, axis=1)
            curvature = np.sqrt(cross2) / speed**3
            torsion = np.einsum("ij,ij->i", cross, d3) / np.where(cross2 > 0, cross2, 1.0)
            assert curvature.shape == torsion.shape
            total += len(spline(u))
        return total
    return run


def finite_difference_geometry(points):
    """Curvature and torsion of sampled points by central differences in the
    sample index (what VMTK's centerline geometry and users of vtkSplineFilter
    do); values at the two ends of each difference stencil are dropped."""
    d1 = np.gradient(points, axis=0)
    d2 = np.gradient(d1, axis=0)
    d3 = np.gradient(d2, axis=0)
    cross = np.cross(d1, d2)
    cross2 = np.einsum("ij,ij->i", cross, cross)
    curvature = np.sqrt(cross2) / np.linalg.norm(d1, axis=1) ** 3
    torsion = np.einsum("ij,ij->i", cross, d3) / np.where(cross2 > 0, cross2, np.inf)
    return curvature, torsion


def interior(values, fraction=0.25):
    n = len(values)
    return values[int(n * fraction):int(n * (1 - fraction))]


def helix_curve(t):
    """Helix a = 2, b = 1 and its exact curvature 0.4 and torsion 0.2."""
    xyz = np.stack([2 * np.cos(t), 2 * np.sin(t), t], axis=-1)
    return xyz, np.full(len(t), 0.4), np.full(len(t), 0.2)


def trefoil_curve(t):
    """Trefoil knot (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t), with its
    curvature and torsion from exact derivatives."""
    xyz = np.stack([np.sin(t) + 2 * np.sin(2 * t), np.cos(t) - 2 * np.cos(2 * t), -np.sin(3 * t)], axis=-1)
    d1 = np.stack([np.cos(t) + 4 * np.cos(2 * t), -np.sin(t) + 4 * np.sin(2 * t), -3 * np.cos(3 * t)], axis=-1)
    d2 = np.stack([-np.sin(t) - 8 * np.sin(2 * t), -np.cos(t) + 8 * np.cos(2 * t), 9 * np.sin(3 * t)], axis=-1)
    d3 = np.stack([-np.cos(t) - 16 * np.cos(2 * t), np.sin(t) - 16 * np.sin(2 * t), 27 * np.cos(3 * t)], axis=-1)
    cross = np.cross(d1, d2)
    cross2 = np.einsum("ij,ij->i", cross, cross)
    return xyz, np.sqrt(cross2) / np.linalg.norm(d1, axis=1) ** 3, np.einsum("ij,ij->i", cross, d3) / cross2


# Methods compared on the same samples: ours fitted through the filters, and
# what users do today (vtkSplineFilter then finite differences; finite
# differences of the raw points, as VMTK's centerline geometry).
# The approximations choose their knots by cross-validation (NumberOfKnots 0,
# the default) on Uniform parameters: the samples are evenly spaced in t, and
# chord lengths of noisy points carry the noise into the knots (the last column:
# the quintic on chord-length parameters, the filters' default).
METHODS = ("cubic", "VDPS interp.", "VDPS approx.", "quintic approx.", "quintic chord", "vtkSpline+FD",
           "FD raw")
UNIFORM = 0


def filter_geometry(family, xyz, **properties):
    algorithm = getattr(simple, family)(Input=simple.Line(), **properties).GetClientSideObject()
    algorithm.SetInputDataObject(0, to_polydata(xyz[None]))
    algorithm.Update()
    out = algorithm.GetOutputDataObject(0)
    data = out.GetPointData()
    if out.GetNumberOfPoints() == 0:  # the line was refused (reported by the filter)
        return None
    return (vtk_to_numpy(out.GetPoints().GetData()), vtk_to_numpy(data.GetArray("Curvature")),
            vtk_to_numpy(data.GetArray("Torsion")))


def accuracy(turns=6, seed=2):
    """Median torsion error, relative to the exact torsion's RMS (0.2 for the
    helix), in the middle half of a helix a = 2, b = 1 and of a trefoil knot
    (one period sampled with as many points as 'turns' turns of the helix),
    clean and with Gaussian noise (a fraction of the radius, 2 for both), at 8
    to 64 points per turn. Each sample's exact value is the curve's at its
    nearest point on a dense sampling of the exact curve."""
    from scipy.spatial import cKDTree
    rng = np.random.default_rng(seed)
    errors = []
    print("\nAccuracy: median torsion error / RMS torsion, middle half (approximations: knots by "
          "cross-validation, uniform parameters, fixed degree 5 / tension 1)")
    print("%-8s %-7s %-8s" % ("curve", "noise", "pts/turn") + "".join("%16s" % m for m in METHODS))
    for curve_name, curve, periods in (("helix", helix_curve, turns), ("trefoil", trefoil_curve, 1)):
        dense_t = np.linspace(0, 2 * np.pi * periods, 200001)
        dense, dense_k, dense_tau = curve(dense_t)
        tree = cKDTree(dense)
        scale = np.sqrt(np.mean(dense_tau ** 2))  # the trefoil's torsion changes sign
        for noise in (0.0, 0.001, 0.005, 0.01):
            for per_turn in (8, 16, 32, 64):
                count = turns * per_turn
                # The trefoil is a closed line: its last sample repeats its first, noise included.
                samples = count + 1 if periods > 1 else count
                t = 2 * np.pi * periods * np.arange(samples) / count
                xyz = curve(t)[0] + rng.normal(scale=noise * 2.0, size=(samples, 3))
                if periods == 1:
                    xyz = np.vstack([xyz, xyz[:1]])
                fits = [filter_geometry("CubicSpline", xyz),
                        filter_geometry("VariableDegreeSpline", xyz),
                        filter_geometry("VariableDegreeSpline", xyz, Mode="Approximate Local", NumberOfKnots=0,
                                        AutomaticDegrees=0, Parameterization=UNIFORM),
                        filter_geometry("TensionQuinticSpline", xyz, Mode="Approximate", NumberOfKnots=0,
                                        Automatic=0, Parameterization=UNIFORM),
                        filter_geometry("TensionQuinticSpline", xyz, Mode="Approximate", NumberOfKnots=0,
                                        Automatic=0)]
                spline = vtkSplineFilter()
                spline.SetInputData(to_polydata(xyz[None]))
                spline.SetSubdivideToSpecified()
                spline.SetNumberOfSubdivisions((len(xyz) - 1) * SUBDIVISIONS)
                spline.Update()
                dense_vtk = vtk_to_numpy(spline.GetOutput().GetPoints().GetData())
                fits.append((dense_vtk, *finite_difference_geometry(dense_vtk)))
                fits.append((xyz, *finite_difference_geometry(xyz)))
                row = []
                for fit in fits:
                    if fit is None:
                        row.append(float("nan"))
                        continue
                    points, _, tau = fit
                    exact = dense_tau[tree.query(interior(points))[1]]
                    row.append(np.median(np.abs(interior(tau) - exact)) / scale)
                print("%-8s %-7s %-8d" % (curve_name, "%.1f%%" % (100 * noise), per_turn) +
                      "".join("%15.3g%%" % (100 * e) for e in row))
                errors.append((curve_name, noise, per_turn, row))
    return errors


def peak_resident_kib():
    """This process's peak resident memory (VmHWM) in KiB."""
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmHWM:"):
                return int(line.split()[1])
    raise RuntimeError("no VmHWM in /proc/self/status")


def cold_run(plugin, n):
    """Fits one line of n points once, in a fresh pvpython (cold memory: what a
    user's first run pays, page faults included): seconds, output points and the
    peak resident memory before and after the fit, in KiB."""
    import shutil
    import subprocess
    # VmHWM, not getrusage's ru_maxrss: Linux keeps ru_maxrss across exec, so a
    # child of this (large) process would report the parent's peak.
    code = ("import sys, time; sys.argv=['x']\n"
            "from paraview import simple\n"
            "simple.LoadPlugin(%r, remote=False)\n"
            "import benchmark as b\n"
            "poly = b.to_polydata(b.helix_lines(1, %d))\n"
            "before = b.peak_resident_kib()\n"
            "run = b.ours(poly, 'Sequential')\n"
            "start = time.perf_counter(); points = run(); seconds = time.perf_counter() - start\n"
            "peak = b.peak_resident_kib()\n"
            "print(seconds, points, before, peak)\n" % (plugin, n))
    here = os.path.dirname(os.path.abspath(__file__))
    result = subprocess.run([shutil.which("pvpython"), "-c", code], cwd=here, capture_output=True, text=True,
                            env=dict(os.environ, PYTHONPATH=here + os.pathsep + os.environ.get("PYTHONPATH", "")))
    words = result.stdout.split()[-4:]
    if result.returncode != 0 or len(words) < 4:
        raise RuntimeError("the fit of %d points in a fresh pvpython failed:\n%s" % (n, result.stderr[-2000:]))
    return float(words[0]), int(words[1]), int(words[2]), int(words[3])


def growth(plugin):
    """Time per output point and memory on one line of 1e3 to 1e6 points (ours,
    one thread, each size in a fresh process): a linear method keeps it flat."""
    print("\nCost growth, one line, 10 samples per span, one thread, first run in a fresh process:")
    print("%10s %10s %18s %16s %18s" % ("points", "seconds", "ns per out point", "peak RSS MiB", "fit bytes/out pt"))
    sizes, per_point = [], []
    for n in (1000, 10000, 100000, 1000000):
        seconds, points, before, peak = cold_run(plugin, n)
        sizes.append(n)
        per_point.append(1e9 * seconds / points)
        print("%10d %10.3f %18.1f %16.0f %18.0f" % (n, seconds, per_point[-1], peak / 1024,
                                                     (peak - before) * 1024 / points))
    print("largest / smallest time per output point: %.2f (flat within 30%% means <= 1.3); "
          "the output arrays alone hold 148 bytes per point" % (max(per_point) / min(per_point)))
    return sizes, per_point


def threads_identical(poly):
    """The output does not depend on the number of threads."""
    outputs = []
    for backend in ("Sequential", "STDThread"):
        vtkSMPTools.SetBackend(backend)
        algorithm = simple.CubicSpline(Input=simple.Line()).GetClientSideObject()
        algorithm.SetInputDataObject(0, poly)
        algorithm.Update()
        out = algorithm.GetOutputDataObject(0)
        outputs.append([vtk_to_numpy(out.GetPoints().GetData())] +
                       [vtk_to_numpy(out.GetPointData().GetArray(a)) for a in range(out.GetPointData().GetNumberOfArrays())])
    same = all(np.array_equal(a, b) for a, b in zip(*outputs))
    print("Output with 1 and 2 threads identical: %s" % ("yes" if same else "NO"))
    return same


def plot_growth(sizes, per_point, folder):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(folder, exist_ok=True)
    figure, axes = plt.subplots(figsize=(6, 4))
    axes.semilogx(sizes, per_point, "o-")
    axes.set_xlabel("points on the line")
    axes.set_ylabel("ns per output point")
    axes.set_ylim(0, 1.3 * max(per_point))
    axes.set_title("ShapeSplines cubic: cost per output point (one thread)")
    axes.grid(True, which="both", alpha=0.3)
    path = os.path.join(folder, "growth.png")
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    print("wrote", path)


def plot_accuracy(errors, folder):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    os.makedirs(folder, exist_ok=True)
    figure, panels = plt.subplots(2, 2, figsize=(11, 8), sharex=True)
    for column, curve_name in enumerate(("helix", "trefoil")):
        for row, noise in enumerate((0.0, 0.005)):
            axes = panels[row][column]
            rows = [e for e in errors if e[0] == curve_name and e[1] == noise]
            for method, name in enumerate(METHODS):
                axes.loglog([r[2] for r in rows], [100 * r[3][method] for r in rows], marker="o",
                            color="C%d" % method, label=name)
            axes.set_xticks([8, 16, 32, 64])
            axes.xaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
            axes.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
            axes.set_title("%s, noise %.1f%%" % (curve_name, 100 * noise))
            axes.set_ylabel("median torsion error (%)")
            axes.grid(True, which="both", alpha=0.3)
            if row == 1:
                axes.set_xlabel("points per turn")
    panels[0][0].legend(fontsize=7)
    path = os.path.join(folder, "accuracy.png")
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    print("wrote", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--lines", type=int, default=10000)
    parser.add_argument("--accuracy-only", action="store_true", help="skip the speed part")
    parser.add_argument("--output", default="build/benchmark", help="folder for the plots")
    args = parser.parse_args()
    args.plugin = os.path.abspath(args.plugin)  # the growth runs load it from another folder
    simple.LoadPlugin(args.plugin, remote=False)
    if args.accuracy_only:
        plot_accuracy(accuracy(), args.output)
        return

    cases = [("%d lines x 50 points" % args.lines, helix_lines(args.lines, 50), 3)]
    for n in (1000, 4000, 16000):
        cases.append(("1 line x %d points" % n, helix_lines(1, n), 7))
    families = (("cubic", "CubicSpline", None), ("gencubic", "GeneralizedCubicSpline", "AutomaticTension"),
                ("quintic", "TensionQuinticSpline", "Automatic"), ("vdps", "VariableDegreeSpline", "AutomaticDegrees"),
                ("qqr", "QQRSpline", "Automatic"))
    print("Output points per second (2 threads unless said), and ratios measured in this run:")
    print("%-24s %-9s %11s %11s %9s %9s %9s" % ("case", "family", "fixed", "automatic", "x vtk", "x SciPy",
                                                "auto cost"))
    for name, xyz, repeats in cases:
        poly = to_polydata(xyz)
        per_line = (xyz.shape[1] - 1) * SUBDIVISIONS + 1
        rates = {}
        runs = [("seq", ours(poly, "Sequential")), ("vtk", vtk_spline(poly, per_line)), ("scipy", scipy_route(xyz))]
        for family, proxy, automatic in families:
            if automatic is None:
                runs.append((family, ours(poly, "STDThread", proxy)))
            else:
                runs.append((family, ours(poly, "STDThread", proxy, **{automatic: 0})))
                # The qqr search fails on every span of a helix and audits
                # thousands of candidates per line: measured on 200 lines.
                subset = to_polydata(xyz[:200]) if family == "qqr" else poly
                runs.append((family + " auto", ours(subset, "STDThread", proxy)))
        for label, run in runs:
            seconds, points = best_time(run, repeats)
            assert points == per_line * (min(200, xyz.shape[0]) if label == "qqr auto" else xyz.shape[0]), \
                (label, points)
            rates[label] = points / seconds
        print("%-24s %-9s %11.3g %11s %9s %9s %9s" % (name, "vtkSpline", rates["vtk"], "", "", "", ""))
        print("%-24s %-9s %11.3g %11s %9s %9s %9s" % (name, "SciPy", rates["scipy"], "", "", "", ""))
        print("%-24s %-9s %11.3g %11s %9s %9s %9s" % (name, "cubic 1th", rates["seq"], "", "", "", ""))
        for family, _, automatic in families:
            auto = rates.get(family + " auto")
            print("%-24s %-9s %11.3g %11s %8.2fx %8.2fx %9s" % (
                name, family, rates[family], "%.3g" % auto if auto else "-", rates[family] / rates["vtk"],
                rates[family] / rates["scipy"], "%.2fx" % (rates[family] / auto) if auto else "-"))
    print("(x vtk, x SciPy: the fixed mode's rate over theirs; auto cost: fixed rate / automatic rate, on helices)")
    threads_identical(to_polydata(helix_lines(2000, 50)))
    sizes, per_point = growth(args.plugin)
    plot_growth(sizes, per_point, args.output)
    plot_accuracy(accuracy(), args.output)


if __name__ == "__main__":
    main()
