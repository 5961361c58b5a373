#!/usr/bin/python3
"""Reference values of classical quintic splines from SciPy.

The tensioned quintic B-splines of Cravero, Manni & Sampoli with all shape parameters 1 are
the classical quintic B-splines. For random 3D data on uneven knots this writes
SciPy's values and derivatives 0..4 of
  basis  - BSpline(k=5) with given coefficients on the knots t_0..t_n extended
           by five knots each side at the end spacings,
  open   - make_interp_spline(k=5) with s' and s'' at each end taken from the
           quintic through the six end points,
  natural - make_interp_spline(k=5) with s'' = s''' = 0 at both ends,
  closed - make_interp_spline(k=5, bc_type="periodic"),
so the C++ test compares the construction with an independent implementation.

Usage: /usr/bin/python3 scipy_quintic_reference.py OUTPUT.txt
"""
import sys

import numpy as np
from numpy.polynomial import polynomial as P
from scipy.interpolate import BSpline, make_interp_spline


def end_derivatives(x, p, at_start):
    """s'(x_end) and s''(x_end) of the quintic through the six end points."""
    xs, ps = (x[:6], p[:6]) if at_start else (x[-6:], p[-6:])
    x0 = xs[0] if at_start else xs[-1]
    c = P.polyfit(xs - x0, ps, 5)
    return [(1, c[1]), (2, 2.0 * c[2])]


def write_case(out, name, closed, knots, points, spline, x):
    evaluation = np.unique(np.concatenate([x, np.linspace(x[0], x[-1], 121)]))
    out.write(f"case {name} {int(closed)} {len(knots)} {len(points)} {len(evaluation)}\n")
    out.write(" ".join(repr(float(v)) for v in knots) + "\n")
    for p in points:
        out.write(" ".join(repr(float(v)) for v in p) + "\n")
    for at in evaluation:
        values = np.concatenate([spline(at, nu) for nu in range(5)])
        out.write(" ".join(repr(float(v)) for v in (at, *values)) + "\n")


def main():
    rng = np.random.default_rng(20261124)
    n = 9
    t = np.concatenate([[0.0], np.cumsum(rng.uniform(0.3, 2.0, size=n))])
    h0, h1 = t[1] - t[0], t[-1] - t[-2]
    padded = np.concatenate([t[0] - h0 * np.arange(5, 0, -1), t, t[-1] + h1 * np.arange(1, 6)])
    with open(sys.argv[1], "w") as out:
        coefficients = rng.uniform(-1, 1, size=(n + 5, 3))
        write_case(out, "basis", False, t, coefficients, BSpline(padded, coefficients, 5), t)

        points = rng.uniform(-1, 1, size=(n + 1, 3))
        ends = (end_derivatives(t, points, True), end_derivatives(t, points, False))
        write_case(out, "open", False, t, points,
                   make_interp_spline(t, points, k=5, bc_type=ends), t)

        zero = np.zeros(3)
        natural = ([(2, zero), (3, zero)], [(2, zero), (3, zero)])
        write_case(out, "natural", False, t, points,
                   make_interp_spline(t, points, k=5, bc_type=natural), t)

        closed = np.vstack([points[:-1], points[:1]])
        write_case(out, "closed", True, t, points[:-1],
                   make_interp_spline(t, closed, k=5, bc_type="periodic"), t)
    print(f"wrote SciPy quintic spline reference values to {sys.argv[1]}")


if __name__ == "__main__":
    main()
