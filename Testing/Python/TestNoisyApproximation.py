"""Noisy, unevenly spaced points: both approximating families at their
defaults (Mode approximate, every other property as it comes) against SciPy's
smoothing spline told the true noise (splprep, k = 5, s = 3 n sigma^2), on
helices, trefoils, Viviani's curves and spirals whose radius grows, sampled
at random parameters, 60 to 400 points, noise 0.1% to 0.5% of the diagonal
(noisy_curves.py). Run by Debian's python3 (SciPy) with PYTHONPATH at the
build's site-packages: TestNoisyApproximation.py
"""
import sys

import numpy as np

from noisy_curves import cases, errors, splprep_route
from shapesplines.arrays import fit_curves

failures = []


def check(ok, what, detail=""):
    print(("ok   " if ok else "FAIL ") + what + (": " + detail if detail else ""))
    if not ok:
        failures.append(what)


MODES = {"quintic": "approximate", "vdps local": "approximate_local", "vdps global": "approximate_global"}
ours, theirs, violations = {m: [] for m in MODES}, [], {m: 0 for m in MODES}
for name, count, noise, seed, truth, points, sigma in cases():
    scipy_figures = errors(truth, *splprep_route(points, 3 * count * sigma ** 2))
    theirs.append(scipy_figures)
    case = "%s, %d points, noise %.1f%%, seed %d" % (name, count, 100 * noise, seed)
    for mode, value in MODES.items():
        curve = fit_curves(points, family=mode.split()[0], samples=20, mode=value)
        figures = errors(truth, curve.points, curve.curvature, curve.torsion, curve.arc_length)
        ours[mode].append(figures)
        violations[mode] += curve.shape_violations
        # Every case, no breakdown: curvature within 20% or SciPy's,
        # torsion within 100% or SciPy's, length within 1.5% of the curve's.
        check(figures[0] <= max(0.2, scipy_figures[0]) and figures[1] <= max(1.0, scipy_figures[1])
              and abs(figures[2]) <= 0.015,
              "%s, %s" % (mode, case),
              "median errors curvature %.3f torsion %.3f, length %+.4f; splprep %.3f, %.3f, %+.4f"
              % (figures + scipy_figures))

theirs = np.abs(np.array(theirs))
for mode in MODES:
    figures = np.abs(np.array(ours[mode]))
    strict = np.sum((figures[:, 0] <= 0.1) & (figures[:, 1] <= 0.3) & (figures[:, 2] <= 0.01))
    # Over all cases: medians of 10% / 30% at most, and a worst case no worse than SciPy's.
    check(np.median(figures[:, 0]) <= 0.1 and np.median(figures[:, 1]) <= 0.3
          and np.all(figures.max(0)[:2] <= theirs.max(0)[:2]),
          "%s: medians and worst case against splprep" % mode,
          "median curvature %.3f torsion %.3f (splprep %.3f, %.3f); worst %.3f, %.3f (splprep %.3f, %.3f); "
          "%d of %d cases within 10%%, 30%%, 1%%; %d shape violations left in all"
          % (np.median(figures[:, 0]), np.median(figures[:, 1]), np.median(theirs[:, 0]),
             np.median(theirs[:, 1]), figures[:, 0].max(), figures[:, 1].max(), theirs[:, 0].max(),
             theirs[:, 1].max(), strict, len(figures), violations[mode]))

print("%d checks failed" % len(failures) if failures else "all checks passed")
sys.exit(1 if failures else 0)
