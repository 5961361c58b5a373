"""Noisy, unevenly spaced points on curves with known curvature and torsion,
and how far a fit's curvature and torsion are from the curve's: shared by the
noisy-approximation test and the benchmark.

    from noisy_curves import CURVES, Truth, cases, errors
    truth = Truth("trefoil")
    points, sigma = truth.sample(150, 0.002, np.random.default_rng(1))
    ... fit points ...
    curvature_error, torsion_error, length_error = errors(truth, samples, k, tau, arc)

The points lie at random parameter values (sorted), with Gaussian noise of a
fraction of the bounding-box diagonal. Errors are medians of the relative
errors over the middle half of the fit (by its arc length), each sample
compared with the curve's nearest point; the length error is relative to the
curve's length between the first and last point's parameters.
"""
import numpy as np
from scipy.spatial import cKDTree


def helix(t, a=1.0, b=0.25):
    s, c = np.sin(t), np.cos(t)
    z = np.zeros_like(t)
    return [np.stack(v, -1) for v in ((a * c, a * s, b * t), (-a * s, a * c, b + z),
                                       (-a * c, -a * s, z), (a * s, -a * c, z))]


def trefoil(t):
    s1, c1, s2, c2, s3, c3 = np.sin(t), np.cos(t), np.sin(2 * t), np.cos(2 * t), np.sin(3 * t), np.cos(3 * t)
    return [np.stack(v, -1) for v in ((s1 + 2 * s2, c1 - 2 * c2, -s3), (c1 + 4 * c2, -s1 + 4 * s2, -3 * c3),
                                       (-s1 - 8 * s2, -c1 + 8 * c2, 9 * s3),
                                       (-c1 - 16 * c2, s1 - 16 * s2, 27 * c3))]


def viviani(t):
    s, c, sh, ch = np.sin(t), np.cos(t), np.sin(t / 2), np.cos(t / 2)
    return [np.stack(v, -1) for v in ((1 + c, s, 2 * sh), (-s, c, ch), (-c, -s, -sh / 2), (s, -c, -ch / 4))]


def spiral(t):
    """A conical spiral whose radius grows: curvature and torsion vary along it."""
    r, dr = 0.5 + 0.25 * t, 0.25
    s, c = np.sin(t), np.cos(t)
    z = np.zeros_like(t)
    return [np.stack(v, -1) for v in ((r * c, r * s, 0.3 * t), (dr * c - r * s, dr * s + r * c, 0.3 + z),
                                       (-2 * dr * s - r * c, 2 * dr * c - r * s, z),
                                       (-3 * dr * c + r * s, -3 * dr * s - r * c, z))]


CURVES = {"helix": (helix, 0.0, 4 * np.pi), "trefoil": (trefoil, 0.0, 2 * np.pi * 0.999),
          "viviani": (viviani, -0.95 * np.pi, 0.95 * np.pi), "spiral": (spiral, 0.0, 4 * np.pi)}


def curvature_torsion(d1, d2, d3):
    cross = np.cross(d1, d2)
    cross2 = np.einsum("ij,ij->i", cross, cross)
    return np.sqrt(cross2) / np.linalg.norm(d1, axis=1) ** 3, np.einsum("ij,ij->i", cross, d3) / cross2


class Truth:
    """A curve of CURVES, densely sampled with its curvature and torsion."""

    def __init__(self, name, dense=20000):
        self.curve, self.first, self.last = CURVES[name]
        self.t = np.linspace(self.first, self.last, dense)
        x, d1, d2, d3 = self.curve(self.t)
        self.x = x
        self.curvature, self.torsion = curvature_torsion(d1, d2, d3)
        self.diagonal = np.linalg.norm(x.max(0) - x.min(0))
        self.tree = cKDTree(x)
        self.sample_length = None

    def sample(self, count, noise, rng):
        """count points at random parameters, noise a fraction of the diagonal; and the noise's sigma."""
        t = np.sort(rng.uniform(self.first, self.last, count))
        inside = (self.t >= t[0]) & (self.t <= t[-1])
        self.sample_length = np.linalg.norm(np.diff(self.x[inside], axis=0), axis=1).sum()
        sigma = noise * self.diagonal
        return self.curve(t)[0] + rng.normal(0.0, sigma, (count, 3)), sigma


def errors(truth, points, curvature, torsion, arc_length=None):
    """Median relative curvature and torsion errors over the middle half, and the length error."""
    if arc_length is None:
        arc_length = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(points, axis=0), axis=1))])
    length = arc_length[-1]
    middle = (arc_length >= 0.25 * length) & (arc_length <= 0.75 * length)
    _, nearest = truth.tree.query(points[middle])
    k, tau = truth.curvature[nearest], truth.torsion[nearest]
    return (np.median(np.abs(curvature[middle] - k) / np.abs(k)),
            np.median(np.abs(torsion[middle] - tau) / np.abs(tau)),
            length / truth.sample_length - 1.0)


def cases(counts=(60, 150, 400), seeds=(1, 2), salt=()):
    """The noisy cases: every curve of CURVES, 60, 150 and 400 points, noise
    0.1%, 0.2% and 0.5% of the diagonal, two seeds; yields (name, count,
    noise, seed, truth, points, sigma), the same points on every call.
    Other counts, seeds or a salt give cases the defaults were never tuned on."""
    for name in CURVES:
        truth = Truth(name)
        for count in counts:
            for noise in (0.001, 0.002, 0.005):
                for seed in seeds:
                    rng = np.random.default_rng([count, int(noise * 1e4), seed, len(name), *salt])
                    points, sigma = truth.sample(count, noise, rng)
                    yield name, count, noise, seed, truth, points, sigma


def splprep_route(points, s, samples=2000):
    """SciPy's smoothing spline (k = 5, smoothing s) with its curvature and torsion."""
    from scipy.interpolate import splev, splprep
    tck, _ = splprep(points.T, k=5, s=s)
    u = np.linspace(0, 1, samples)
    d = [np.array(splev(u, tck, der=n)).T for n in range(4)]
    k, tau = curvature_torsion(d[1], d[2], d[3])
    return d[0], k, tau
