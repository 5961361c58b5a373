#!/usr/bin/env python3
"""Writes the seed corpus of fuzz_fit (Testing/Fuzz/corpus/) in its byte format.

Usage: python3 make_corpus.py [output directory]   (default: corpus/ next to this file)
       python3 make_corpus.py --regressions         (rewrites regressions/ next to this file)

The regressions are hand-minimised failures the fuzzer found: those in regressions/
fail the default invariants, those in regressions/extra/ only the stricter ones of
FUZZ_FIT_EXTRA=1 (RunFuzz.cmake runs them when that variable is set).

The format is documented at the top of fuzz_fit.cxx: a 17-byte header of options
followed by points encoded as doubles, floats or small integers.
"""
import math
import os
import struct
import sys

# Byte 0: knot parameterization, byte 1: cubic end condition.
UNIFORM, CHORD_LENGTH, CENTRIPETAL = 0, 1, 2
NATURAL, NOT_A_KNOT, CLAMPED = 0, 1, 2
# Byte 2: flags.
CLOSED = 1
ARC_LENGTH = 2
DOUBLES, FLOATS, SMALL_INTEGERS = 0 << 2, 1 << 2, 2 << 2
FLOAT_PRECISION = 16


def header(knots=CHORD_LENGTH, ends=NOT_A_KNOT, flags=DOUBLES, subdivisions=10,
           audit_subdivisions=16, target_length=1.0, data_tolerance=6, curve_tolerance=3,
           scale_exponent=0, offset_code=0):
    """Tolerance codes t give 10^-t (255: zero); offset_code c != 0 adds 2^(c % 64)."""
    return struct.pack("<BBBBBdBBbB", knots, ends, flags, subdivisions - 1,
                       audit_subdivisions - 1, target_length, data_tolerance,
                       curve_tolerance, scale_exponent, offset_code)


def doubles(points):
    return b"".join(struct.pack("<3d", *p) for p in points)


def floats(points):
    return b"".join(struct.pack("<3f", *p) for p in points)


def small_integers(points):
    """Coordinates in -4..4, stored as v + 4 (decoded as (b % 9) - 4)."""
    out = bytearray()
    for p in points:
        for v in p:
            if not -4 <= v <= 4:
                raise ValueError(f"small integer coordinate out of range: {v}")
            out.append(v + 4)
    return bytes(out)


def helix(points_per_turn=16, turns=2, a=2.0, b=1.0):
    n = points_per_turn * turns
    return [(a * math.cos(2 * math.pi * i / points_per_turn),
             a * math.sin(2 * math.pi * i / points_per_turn),
             b * 2 * math.pi * i / points_per_turn) for i in range(n + 1)]


AKIMA = [(x, y, 0.0) for x, y in zip(
    [0, 2, 3, 5, 6, 8, 9, 11, 12, 14, 15],
    [10, 10, 10, 10, 10, 10, 10.5, 15, 50, 60, 85])]


def seeds():
    yield "helix", header(flags=DOUBLES) + doubles(helix())
    yield "helix_float_arclength", header(
        knots=CENTRIPETAL, ends=CLAMPED, flags=FLOATS | FLOAT_PRECISION | ARC_LENGTH,
        target_length=0.5) + floats(helix(8, 3))
    yield "akima", header(ends=NOT_A_KNOT, flags=DOUBLES | ARC_LENGTH,
                          target_length=0.25) + doubles(AKIMA)
    # A straight run with a corner: criterion (i) on the run, (ii) at the corner.
    yield "collinear", header(knots=CENTRIPETAL, ends=NATURAL, flags=SMALL_INTEGERS) + \
        small_integers([(i, i, 0) for i in range(-4, 3)] + [(3, 2, 0), (4, 1, 0)])
    # Consecutive repeats (merged by the cleaning) and a repeated non-consecutive point.
    yield "repeated", header(knots=UNIFORM, ends=CLAMPED, flags=SMALL_INTEGERS) + \
        small_integers([(0, 0, 0), (0, 0, 0), (1, 0, 0), (1, 0, 0), (1, 0, 0), (1, 1, 1),
                        (0, 0, 0), (0, 0, 0), (2, 1, -1)])
    yield "closed_square", header(flags=SMALL_INTEGERS | CLOSED | ARC_LENGTH,
                                  target_length=0.1) + \
        small_integers([(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)])
    # The same square, repeated seam, tiny and far from the origin (2^-20 at 2^20).
    yield "closed_square_far", header(flags=SMALL_INTEGERS, scale_exponent=-20,
                                      offset_code=20) + \
        small_integers([(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0), (-1, -1, 0)])
    # Must make fitPolyline throw std::invalid_argument.
    yield "nonfinite", header() + doubles([(0, 0, 0), (1, float("nan"), 0), (2, 0, float("inf"))])


def tiny_corner(size):
    """Three points of a right angle with legs `size`: a planar curve."""
    return [(0.0, 0.0, 0.0), (size, 0.0, 0.0), (size, size, 0.0)]


def regressions():
    # Chord-length knots on data of size L: s''' ~ 1/L^2 and s'' x s''' ~ 1/L^3
    # overflow below L ~ 1e-103, so the torsion det(s', s'', s''') / |s' x s''|^2 is
    # NaN (0 * inf) although the curve is planar (torsion 0).
    yield "torsion_nan_tiny_chord_length", header(ends=NATURAL) + doubles(tiny_corner(1e-120))
    # Below L ~ 1e-154 the cubic coefficient (M1 - M0) / (6 h) itself overflows: the
    # sample positions are +-inf.
    yield "position_inf_tiny_chord_length", header(ends=NATURAL) + doubles(tiny_corner(1e-160))
    # A hairpin out to x = 1 and back to the origin, missed by 1e-320 in y and 1e-321
    # in z: at the apex s' is a subnormal vector, whose few significant bits make
    # s' / |s'| 1 + 2.7e-5 long however |s'| is computed (scale it by a power of two
    # first, or treat |s'| below DBL_MIN as a stationary point).
    yield "tangent_not_unit_subnormal_speed", header(ends=NOT_A_KNOT) + doubles(
        [(0, 0, 0), (1, 0, 0), (0, 1e-320, 1e-321)])


def extra_regressions():
    # A polyline that doubles back exactly (I_{i+1} = I_{i-1}): the Menger curvature
    # 2 |B_i| / |I_{i+1} - I_{i-1}| is 0 / 0 = NaN (written by vtkPolylineShapeAnalysis).
    yield "discrete_curvature_nan_reversal", header(flags=SMALL_INTEGERS) + \
        small_integers([(0, 0, 0), (1, 0, 0), (0, 0, 0), (0, 1, 0)])
    # Data of size 1e110: the triple product (~L^3) and |a x b| |b x c| (~L^4, through
    # Eigen's norm()) overflow, so the discrete torsion is inf / inf = NaN.
    yield "discrete_torsion_nan_huge", header() + doubles(
        [(0, 0, 0), (1e110, 0, 0), (1e110, 1e110, 0), (0, 1e110, 1e110)])
    # Data of extent >= ~1e154 (or <= ~1e-162): Eigen's norm() squares and overflows
    # (underflows), the bounding-box diagonal is inf (0) and cleanPolyline merges every
    # point into the first: no curve and no error for four distinct points.
    yield "no_curve_huge", header() + doubles(
        [(0, 0, 0), (1e155, 0, 0), (1e155, 1e155, 0), (0, 1e155, 1e155)])
    yield "no_curve_tiny", header() + doubles(
        [(0, 0, 0), (1e-163, 0, 0), (1e-163, 1e-163, 0), (0, 1e-163, 1e-163)])


def write(directory, files):
    os.makedirs(directory, exist_ok=True)
    for name, data in files:
        with open(os.path.join(directory, name), "wb") as f:
            f.write(data)
        print(f"{os.path.join(directory, name)}: {len(data)} bytes")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    if sys.argv[1:] == ["--regressions"]:
        write(os.path.join(here, "regressions"), regressions())
        write(os.path.join(here, "regressions", "extra"), extra_regressions())
        return
    write(sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "corpus"), seeds())


if __name__ == "__main__":
    main()
