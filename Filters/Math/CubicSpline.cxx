#include "CubicSpline.h"

#include "SparseSolve.h"

#include <stdexcept>

namespace shapesplines
{
namespace
{
Vec3 row(const Eigen::MatrixX3d& m, int i)
{
  return m.row(i).transpose();
}

/// Derivative at t0 of the parabola through (t0,p0), (t1,p1), (t2,p2).
Vec3 parabolaDerivative(double t0, double t1, double t2, const Vec3& p0, const Vec3& p1,
  const Vec3& p2)
{
  const double h0 = t1 - t0;
  const double h1 = t2 - t1;
  // Newton form: p0 + (t - t0) [p0,p1] + (t - t0)(t - t1) [p0,p1,p2].
  const Vec3 d01 = (p1 - p0) / h0;
  const Vec3 d12 = (p2 - p1) / h1;
  const Vec3 d012 = (d12 - d01) / (t2 - t0);
  return d01 + (t0 - t1) * d012;
}

/**
 * The second derivatives M_i at the knots (a closed spline has n of them,
 * M_n = M_0): the tridiagonal (cyclic when closed) system of C2 continuity
 * plus two end conditions. clamped is used by CubicEndCondition::Clamped only.
 */
Eigen::MatrixX3d solveMoments(const std::vector<Vec3>& points, const std::vector<double>& h,
  bool closed, CubicEndCondition ends, const CubicSpline::EndDerivatives& clamped,
  DeferredCondition& condition)
{
  const int n = static_cast<int>(points.size());
  const int spans = static_cast<int>(h.size());
  auto slope = [&](int i) -> Vec3 { return (points[(i + 1) % n] - points[i]) / h[i]; };
  Triplets a;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(n, 3);
  const int firstInterior = closed ? 0 : 1;
  const int lastInterior = closed ? n - 1 : n - 2;
  for (int i = firstInterior; i <= lastInterior; ++i)
  {
    const int prev = (i - 1 + spans) % spans;
    a.emplace_back(i, (i - 1 + n) % n, h[prev]);
    a.emplace_back(i, i, 2.0 * (h[prev] + h[i]));
    a.emplace_back(i, (i + 1) % n, h[i]);
    rhs.row(i) = 6.0 * (slope(i) - slope(prev)).transpose();
  }
  if (!closed)
  {
    const int last = n - 1;
    if (n == 2 || ends == CubicEndCondition::Natural)
    {
      // M = 0, scaled like the other rows (2h on the diagonal) so that pivoting
      // keeps these rows and the end moments come out exactly zero.
      a.emplace_back(0, 0, 2.0 * h[0]);
      a.emplace_back(last, last, 2.0 * h[spans - 1]);
    }
    else if (ends == CubicEndCondition::NotAKnot)
    {
      // Equal third derivatives on both sides of t_1 and of t_{n-2}.
      a.emplace_back(0, 0, h[1]);
      a.emplace_back(0, 1, -(h[0] + h[1]));
      a.emplace_back(0, 2, h[0]);
      const int s = spans - 1;
      a.emplace_back(last, last - 2, h[s]);
      a.emplace_back(last, last - 1, -(h[s - 1] + h[s]));
      a.emplace_back(last, last, h[s - 1]);
    }
    else
    {
      const int s = spans - 1;
      a.emplace_back(0, 0, 2.0 * h[0]);
      a.emplace_back(0, 1, h[0]);
      rhs.row(0) = 6.0 * (slope(0) - clamped.first).transpose();
      a.emplace_back(last, last - 1, h[s]);
      a.emplace_back(last, last, 2.0 * h[s]);
      rhs.row(last) = 6.0 * (clamped.second - slope(s)).transpose();
    }
  }
  return solveSparse(n, a, rhs, &condition);
}
} // namespace

CubicSpline::CubicSpline(std::vector<double> knots, bool closed)
  : Curve(std::move(knots), closed)
{
}

CubicSpline::EndDerivatives CubicSpline::parabolaEndDerivatives(
  const std::vector<Vec3>& points, const std::vector<double>& knots)
{
  const size_t n = points.size();
  if (n < 3)
  {
    const Vec3 slope = (points.back() - points.front()) / (knots.back() - knots.front());
    return { slope, slope };
  }
  const Vec3 start =
    parabolaDerivative(knots[0], knots[1], knots[2], points[0], points[1], points[2]);
  const Vec3 end = parabolaDerivative(
    knots[n - 1], knots[n - 2], knots[n - 3], points[n - 1], points[n - 2], points[n - 3]);
  return { start, end };
}

CubicSpline CubicSpline::interpolate(const std::vector<Vec3>& points,
  const std::vector<double>& knots, bool closed, CubicEndCondition ends,
  const std::optional<EndDerivatives>& clamped)
{
  const int n = static_cast<int>(points.size());
  const int spans = closed ? n : n - 1;
  if (n < 2 || (closed && n < 3) || static_cast<int>(knots.size()) != spans + 1)
  {
    throw std::invalid_argument("cubic spline: too few points or knots of the wrong size");
  }
  auto y = [&](int i) { return points[i % n]; };
  const std::vector<double> h = knotSpacings(knots, "cubic spline");
  auto slope = [&](int i) -> Vec3 { return (y(i + 1) - y(i)) / h[i]; };

  Eigen::MatrixX3d moments(n, 3);
  DeferredCondition condition;
  if (!closed && n == 3 && ends == CubicEndCondition::NotAKnot)
  {
    // One parabola: every moment is its second derivative, set exactly so that
    // the cubic coefficients (and a planar curve's torsion) are exactly zero.
    const Vec3 second = 2.0 * (slope(1) - slope(0)) / (h[0] + h[1]);
    moments.rowwise() = second.transpose();
  }
  else
  {
    const bool needEnds = ends == CubicEndCondition::Clamped && !clamped;
    // Read for clamped ends only; zero otherwise, not left uninitialised.
    const EndDerivatives d = needEnds
      ? parabolaEndDerivatives(points, knots)
      : clamped.value_or(EndDerivatives{ Vec3::Zero(), Vec3::Zero() });
    moments = solveMoments(points, h, closed, ends, d, condition);
  }

  CubicSpline spline(knots, closed);
  spline.Condition = std::move(condition);
  spline.Coefficients.resize(spans);
  for (int i = 0; i < spans; ++i)
  {
    const Vec3 m0 = row(moments, i);
    const Vec3 m1 = row(moments, (i + 1) % n);
    spline.Coefficients[i] = { y(i), slope(i) - h[i] * (2.0 * m0 + m1) / 6.0, 0.5 * m0,
      (m1 - m0) / (6.0 * h[i]) };
  }
  return spline;
}

Derivatives CubicSpline::evaluateOnSpan(int span, double t, int order) const
{
  const auto& c = this->Coefficients[span];
  const double d = t - this->Knots[span];
  Derivatives out;
  out.fill(Vec3::Zero());
  out[0] = c[0] + d * (c[1] + d * (c[2] + d * c[3]));
  if (order >= 1)
  {
    out[1] = c[1] + d * (2.0 * c[2] + 3.0 * d * c[3]);
  }
  if (order >= 2)
  {
    out[2] = 2.0 * c[2] + 6.0 * d * c[3];
  }
  if (order >= 3)
  {
    out[3] = 6.0 * c[3];
  }
  return out;
}
} // namespace shapesplines
