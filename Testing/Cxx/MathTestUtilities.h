// Shared data sets and measurements for the math core's unit tests.
#ifndef shapesplines_MathTestUtilities_h
#define shapesplines_MathTestUtilities_h

#include "CubicSpline.h"
#include "Curve.h"
#include "FitPolyline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace shapesplines::test
{
constexpr double Pi = 3.14159265358979323846;

/// Helix (a cos t, a sin t, b t): curvature a / (a^2 + b^2), torsion b / (a^2 + b^2).
inline std::vector<Vec3> helix(int pointsPerTurn, int turns, double a = 2.0, double b = 1.0)
{
  std::vector<Vec3> points;
  const int n = pointsPerTurn * turns;
  for (int i = 0; i <= n; ++i)
  {
    const double t = 2.0 * Pi * i / pointsPerTurn;
    points.emplace_back(a * std::cos(t), a * std::sin(t), b * t);
  }
  return points;
}

/// Points of a planar function graph (x_i, y_i, 0).
inline std::vector<Vec3> planar(const std::vector<double>& x, const std::vector<double>& y)
{
  std::vector<Vec3> points;
  for (size_t i = 0; i < x.size(); ++i)
  {
    points.emplace_back(x[i], y[i], 0.0);
  }
  return points;
}

inline std::vector<Vec3> akima()
{
  return planar({ 0, 2, 3, 5, 6, 8, 9, 11, 12, 14, 15 },
    { 10, 10, 10, 10, 10, 10, 10.5, 15, 50, 60, 85 });
}

/// RPN 15A, Fritsch & Carlson (1980): monotone data a cubic makes wiggle.
inline std::vector<Vec3> rpn15a()
{
  return planar({ 7.99, 8.09, 8.19, 8.7, 9.2, 10, 12, 15, 20 },
    { 0, 2.76429e-5, 4.37498e-2, 0.169183, 0.469428, 0.943740, 0.998636, 0.999919, 0.999994 });
}

/// Titanium heat data, de Boor, A Practical Guide to Splines.
inline std::vector<Vec3> titanium()
{
  std::vector<double> x;
  for (int i = 0; i < 49; ++i)
  {
    x.push_back(595.0 + 10.0 * i);
  }
  return planar(x, { .644, .622, .638, .649, .652, .639, .646, .657, .652, .655, .644, .663, .663,
                      .668, .676, .676, .686, .679, .678, .683, .694, .699, .710, .730, .763, .812,
                      .907, 1.044, 1.336, 1.881, 2.169, 2.075, 1.598, 1.211, .916, .746, .672,
                      .627, .615, .607, .606, .609, .603, .601, .603, .601, .611, .601, .608 });
}

inline CurveBuilder cubicBuilder(CubicEndCondition ends = CubicEndCondition::NotAKnot)
{
  return [ends](const FitContext& context) {
    BuiltCurve built;
    built.Spline = std::make_unique<CubicSpline>(
      CubicSpline::interpolate(context.Data.Points, context.Knots, context.Data.Closed, ends));
    return built;
  };
}

/// |left - right| relative to the larger of the two: the jump of a derivative at a knot.
inline double relativeJump(const Vec3& left, const Vec3& right)
{
  return (left - right).norm() / std::max({ left.norm(), right.norm(), 1e-300 });
}

struct RelativeErrors
{
  double Curvature = 0.0;
  double Torsion = 0.0;
};

/// The largest |s''(t) - second(t)| at 1001 evenly spaced parameters from
/// the curve's first knot to its last.
template <class SecondDerivative>
double largestSecondDerivativeError(const Curve& curve, SecondDerivative second)
{
  double largest = 0.0;
  for (int k = 0; k <= 1000; ++k)
  {
    const double t =
      curve.firstParameter() + (curve.lastParameter() - curve.firstParameter()) * k / 1000.0;
    largest = std::max(largest, (curve.evaluate(t, 2)[2] - second(t)).norm());
  }
  return largest;
}

/// Expects the fit with polynomial ends to reproduce a polynomial curve
/// (s'' within tolerance of second everywhere) and the one with natural ends
/// not to (an s'' error above 1, the curve's own s'' being larger at an end).
template <class SecondDerivative>
void expectPolynomialEndsReproduce(const char* curve, const Curve& polynomial,
  const Curve& natural, SecondDerivative second, double tolerance)
{
  const double polynomialError = largestSecondDerivativeError(polynomial, second);
  const double naturalError = largestSecondDerivativeError(natural, second);
  std::printf("%s: largest s'' error %.3g with polynomial ends, %.3g natural\n", curve,
    polynomialError, naturalError);
  EXPECT_LT(polynomialError, tolerance) << curve;
  EXPECT_GT(naturalError, 1.0) << curve;
}

/// Largest relative curvature and torsion errors of samples whose span lies
/// at least `margin` spans away from both ends.
inline RelativeErrors interiorErrors(
  const FittedPolyline& fit, double curvature, double torsion, int margin)
{
  RelativeErrors errors;
  const int spans = fit.Data.numberOfSpans();
  const SampledCurve sampled = sampleFit(fit);
  for (int k = 0; k < sampled.Samples.size(); ++k)
  {
    const int span = sampled.Samples.Span[k];
    if (span < margin || span >= spans - margin)
    {
      continue;
    }
    errors.Curvature =
      std::max(errors.Curvature, std::abs(sampled.Frames[k].Curvature - curvature) / curvature);
    errors.Torsion = std::max(errors.Torsion, std::abs(sampled.Frames[k].Torsion - torsion) / torsion);
  }
  return errors;
}
/// Gaussian noise of standard deviation sigma added to every coordinate.
inline std::vector<Vec3> withNoise(std::vector<Vec3> points, double sigma, unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  for (Vec3& p : points)
  {
    p += Vec3(noise(random), noise(random), noise(random));
  }
  return points;
}

/// count points of a helix a = 1, b = 0.25 at perTurn points per turn, with
/// noise of the radius' fraction `noise`.
inline std::vector<Vec3> noisyHelixPoints(int count, double perTurn, double noise, unsigned seed)
{
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i)
  {
    const double t = 2.0 * Pi * i / perTurn;
    points.emplace_back(std::cos(t), std::sin(t), 0.25 * t);
  }
  return withNoise(points, noise, seed);
}

/// The middle value (the upper one of an even count).
inline double median(std::vector<double> values)
{
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

/// Relative curvature and torsion errors of the samples on the middle half
/// (by arc length) of a fit of a curve of constant curvature and torsion.
struct MiddleHalfErrors
{
  std::vector<double> Curvature, Torsion;
};
inline MiddleHalfErrors middleHalfErrors(const FittedPolyline& fit, double curvature, double torsion)
{
  const SampledCurve sampled = sampleFit(fit);
  MiddleHalfErrors errors;
  const double length = sampled.Samples.Length;
  for (int k = 0; k < sampled.Samples.size(); ++k)
  {
    const double s = sampled.Samples.ArcLength[k];
    if (s >= 0.25 * length && s <= 0.75 * length)
    {
      errors.Curvature.push_back(std::abs(sampled.Frames[k].Curvature - curvature) / curvature);
      errors.Torsion.push_back(std::abs(sampled.Frames[k].Torsion - torsion) / torsion);
    }
  }
  return errors;
}

/// Median relative curvature error on the middle half of a fit of a helix a = 1, b = 0.25.
inline double medianCurvatureError(const FittedPolyline& fit)
{
  return median(middleHalfErrors(fit, 1.0 / (1.0 + 0.0625), 0.25 / (1.0 + 0.0625)).Curvature);
}

/// count sorted random values in [from, to]: points at random places along a curve.
inline std::vector<double> randomParameters(int count, double from, double to, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> parameter(from, to);
  std::vector<double> t(count);
  for (double& value : t)
  {
    value = parameter(random);
  }
  std::sort(t.begin(), t.end());
  return t;
}

/// count exact points at random places along two turns of the helix a = 1, b
/// (b = 0: the unit circle): close pairs among them.
inline std::vector<Vec3> randomlySpacedHelix(int count, double b, unsigned seed)
{
  std::vector<Vec3> points;
  for (const double t : randomParameters(count, 0.0, 4.0 * Pi, seed))
  {
    points.emplace_back(std::cos(t), std::sin(t), b * t);
  }
  return points;
}

/// The same on the helix b = 0.25, with noise of the radius' fraction `noise`.
inline std::vector<Vec3> unevenNoisyHelixPoints(int count, double noise, unsigned seed)
{
  return withNoise(randomlySpacedHelix(count, 0.25, seed), noise, seed + 1000);
}

/// count exact points along three turns of the helix a = 1, b = 0.2 with
/// heavy-tailed gaps (cubes of exponential variates): from 1e-11 of a turn
/// to two turns.
inline std::vector<Vec3> heavyTailedHelixPoints(int count, unsigned seed)
{
  std::mt19937 random(seed);
  std::exponential_distribution<double> gap;
  std::vector<double> t(count, 0.0);
  for (int i = 1; i < count; ++i)
  {
    t[i] = t[i - 1] + std::pow(gap(random), 3.0);
  }
  std::vector<Vec3> points;
  for (const double s : t)
  {
    const double angle = 6.0 * Pi * s / t.back();
    points.emplace_back(std::cos(angle), std::sin(angle), 0.2 * angle);
  }
  return points;
}

/// The trefoil knot at t (period 2 pi, size about 3).
inline Vec3 trefoilPoint(double t)
{
  return { std::sin(t) + 2.0 * std::sin(2.0 * t), std::cos(t) - 2.0 * std::cos(2.0 * t),
    -std::sin(3.0 * t) };
}

/// count points of one period of the trefoil knot (an open line: the period
/// is not closed), with noise of a fraction of its size 3.
inline std::vector<Vec3> noisyTrefoilPoints(int count, double noise, unsigned seed)
{
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i)
  {
    points.push_back(trefoilPoint(2.0 * Pi * i / count));
  }
  return withNoise(points, 3.0 * noise, seed);
}

/// count exact points of one period of the trefoil knot (open), each moved
/// along it by up to jitter / 2 of the mean spacing: spacings from 1 - jitter
/// to 1 + jitter of it, neighbours' ratios up to 40 at jitter 0.95. The
/// trefoil's torsion changes sign six times a period.
inline std::vector<Vec3> unevenTrefoilPoints(int count, double jitter, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> shift(-0.5 * jitter, 0.5 * jitter);
  const double spacing = 0.999 * 2.0 * Pi / (count - 1);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i)
  {
    points.push_back(trefoilPoint(spacing * (i + (i > 0 && i < count - 1 ? shift(random) : 0.0))));
  }
  return points;
}

/// A random 3D polyline: steps of random direction and length 0.5 to 1.5.
inline std::vector<Vec3> randomWalk(int count, unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> length(0.5, 1.5);
  std::vector<Vec3> points = { Vec3::Zero() };
  while (static_cast<int>(points.size()) < count)
  {
    const Vec3 direction(normal(random), normal(random), normal(random));
    points.push_back(points.back() + length(random) * direction.normalized());
  }
  return points;
}

/// A 3D staircase: runs of perRun equal steps along the axes, each run
/// turning 90 degrees from the last (collinear points inside every run).
inline std::vector<Vec3> staircase(int runs, int perRun, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> length(1.0, 3.0);
  std::vector<Vec3> points = { Vec3::Zero() };
  int axis = -1;
  for (int r = 0; r < runs; ++r)
  {
    axis = (axis + 1 + static_cast<int>(random() % 2)) % 3;
    Vec3 direction = Vec3::Zero();
    direction[axis] = random() % 2 ? 1.0 : -1.0;
    const double step = length(random) / perRun;
    for (int k = 0; k < perRun; ++k)
    {
      points.push_back(points.back() + step * direction);
    }
  }
  return points;
}

/// A named line of the data users have, generated here, none tuned to.
struct UsersData
{
  std::string Name;
  std::vector<Vec3> Points;
};

/**
 * Noisy helices (25 to 200 points, 0.1% to 1% noise), noisy trefoils, random
 * 3D polylines and staircases.
 */
inline std::vector<UsersData> usersData()
{
  std::vector<UsersData> lines;
  unsigned seed = 1;
  for (const int count : { 25, 50, 100, 200 })
  {
    for (const double noise : { 0.001, 0.005, 0.01 })
    {
      lines.push_back({ "helix " + std::to_string(count) + " points, noise " + std::to_string(noise),
        noisyHelixPoints(count, 16.0, noise, seed++) });
    }
  }
  for (const int count : { 40, 100 })
  {
    for (const double noise : { 0.001, 0.01 })
    {
      lines.push_back({ "trefoil " + std::to_string(count) + " points, noise " + std::to_string(noise),
        noisyTrefoilPoints(count, noise, seed++) });
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    lines.push_back({ "random walk " + std::to_string(k), randomWalk(60, seed++) });
  }
  for (int k = 0; k < 3; ++k)
  {
    lines.push_back({ "staircase " + std::to_string(k), staircase(6, 4, seed++) });
  }
  return lines;
}

/// What the automatic modes bound (ShapeBounds), measured on a fit.
struct BoundFigures
{
  /// Largest curvature on the samples, or between them where the automatic
  /// modes' audit finds a peak (FitOptions' defaults), over the reference
  /// polygon's largest discrete curvature.
  double Curvature = 0.0;
  /// Lowest |s'| (64 samples a span) over the span's chord speed.
  double Speed = 1.0;
  /// Farthest a span strays from its segment of the reference (ShapeAudit::PolygonDeviation).
  double Deviation = 0.0;
  bool StraightRuns = false;
};

/// Whether the fit's reference has straight runs (the looser curvature bound).
inline bool hasStraightRuns(const FittedPolyline& fit)
{
  return std::any_of(
    fit.Shape.Collinear.begin(), fit.Shape.Collinear.end(), [](char c) { return c; });
}

inline BoundFigures boundFigures(const FittedPolyline& fit)
{
  BoundFigures figures;
  double largest = 0.0;
  for (const FrenetFrame& frame : sampleFit(fit).Frames)
  {
    largest = std::max(largest, frame.Curvature * fit.Scale); // normalised, as the shape
  }
  const double turn = *std::max_element(fit.Shape.Curvature.begin(), fit.Shape.Curvature.end());
  figures.Deviation = fit.Audit.PolygonDeviation;
  figures.StraightRuns = hasStraightRuns(fit);
  const Curve& curve = *fit.Spline;
  // A fixed curve's spike between the output's samples counts as the automatic curve's does.
  const CleanPolyline& reference = fit.ShapeReference ? *fit.ShapeReference : fit.Data;
  if (reference.numberOfSpans() == curve.numberOfSpans())
  {
    const FitOptions defaults;
    CurveAuditor auditor(reference, fit.Shape, defaults.Tolerances, defaults.AuditSubdivisions,
      fit.CoordinateNoise, AuditFigures::Bounds);
    for (int j = 0; j < curve.numberOfSpans(); ++j)
    {
      auditor.audit(curve, j);
      largest = std::max(largest, auditor.largestCurvature(j));
    }
  }
  figures.Curvature = largest / std::max(turn, 1e-300);
  const auto& knots = curve.knots();
  for (int j = 0; j < curve.numberOfSpans(); ++j)
  {
    const double h = knots[j + 1] - knots[j];
    const double chord =
      (curve.evaluateOnSpan(j, knots[j + 1], 0)[0] - curve.evaluateOnSpan(j, knots[j], 0)[0]).norm() / h;
    for (int s = 0; s <= 64; ++s)
    {
      const double speed = curve.evaluateOnSpan(j, knots[j] + h * s / 64.0, 1)[1].norm();
      figures.Speed = std::min(figures.Speed, chord > 0.0 ? speed / chord : 1.0);
    }
  }
  return figures;
}

/// Whether a fit keeps the automatic modes' bounds: no degenerate curve.
inline bool withinBounds(const BoundFigures& figures)
{
  return figures.Curvature <= (figures.StraightRuns ? 1e4 : 1e3) && figures.Speed >= 1e-3 &&
    figures.Deviation <= MaximumPolygonDeviation;
}

/// Each of an automatic curve's figures within its bound, or no worse than
/// its fixed curve's (as the automatic modes judge them, one by one), but
/// for the 5% ripple a global solve moves level-0 spans by, which settling
/// lets pass after its second rebuild.
inline bool withinBoundsOrNoWorse(const BoundFigures& automatic, const BoundFigures& fixed)
{
  constexpr double Ripple = 0.05;
  const double curvatureBound = automatic.StraightRuns ? 1e4 : 1e3;
  return (automatic.Curvature <= curvatureBound ||
           automatic.Curvature <= fixed.Curvature * (1.0 + Ripple)) &&
    (automatic.Speed >= 1e-3 || automatic.Speed >= fixed.Speed * (1.0 - Ripple)) &&
    (automatic.Deviation <= MaximumPolygonDeviation ||
      automatic.Deviation <= fixed.Deviation * (1.0 + Ripple));
}
} // namespace shapesplines::test

#endif
