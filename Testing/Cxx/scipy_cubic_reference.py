#!/usr/bin/python3
"""Reference values of the C2 cubic interpolating spline from SciPy.

Writes, for random 3D data with uneven knots, SciPy's CubicSpline values and
first three derivatives at many parameters, for each end condition, so the
C++ test compares our spline with an independent implementation.

Usage: /usr/bin/python3 scipy_cubic_reference.py OUTPUT.txt
"""
import sys

import numpy as np
from scipy.interpolate import CubicSpline


def parabola_end_derivatives(t, p):
    """Derivatives at the ends of the parabolas through the first and last three points."""
    def derivative(ts, ps, at):
        return np.array([np.polyval(np.polyder(np.polyfit(ts, ps[:, k], 2)), at)
                         for k in range(3)])
    return derivative(t[:3], p[:3], t[0]), derivative(t[-3:], p[-3:], t[-1])


def write_case(out, name, t, p, spline):
    evaluation = np.unique(np.concatenate([t, np.linspace(t[0], t[-1], 97)]))
    out.write(f"case {name} {int(name == 'periodic')} {len(t)} {len(evaluation)}\n")
    for ti, pi in zip(t, p):
        out.write(" ".join(repr(float(v)) for v in (ti, *pi)) + "\n")
    for x in evaluation:
        values = [spline(x, nu) for nu in range(4)]
        out.write(" ".join(repr(float(v)) for v in (x, *np.concatenate(values))) + "\n")


def main():
    rng = np.random.default_rng(20261123)
    n = 14
    p = rng.uniform(-1, 1, size=(n, 3))
    t = np.concatenate([[0.0], np.cumsum(rng.uniform(0.1, 2.0, size=n - 1))])
    d0, dn = parabola_end_derivatives(t, p)
    with open(sys.argv[1], "w") as out:
        write_case(out, "not-a-knot", t, p, CubicSpline(t, p, bc_type="not-a-knot"))
        write_case(out, "natural", t, p, CubicSpline(t, p, bc_type="natural"))
        write_case(out, "clamped", t, p, CubicSpline(t, p, bc_type=((1, d0), (1, dn))))
        closed_t = np.append(t, t[-1] + 0.8)
        closed_p = np.vstack([p, p[:1]])
        write_case(out, "periodic", closed_t, closed_p,
                   CubicSpline(closed_t, closed_p, bc_type="periodic"))
    print(f"wrote SciPy cubic spline reference values to {sys.argv[1]}")


if __name__ == "__main__":
    main()
