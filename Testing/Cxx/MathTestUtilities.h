// Shared data sets and measurements for the math core's unit tests.
#ifndef shapesplines_MathTestUtilities_h
#define shapesplines_MathTestUtilities_h

#include "CubicSpline.h"
#include "Curve.h"
#include "FitPolyline.h"

#include <algorithm>
#include <cmath>
#include <memory>
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
} // namespace shapesplines::test

#endif
