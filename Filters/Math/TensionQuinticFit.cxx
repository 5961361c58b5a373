#include "TensionQuinticFit.h"

#include <algorithm>

namespace shapesplines
{
namespace
{
std::vector<char> failingSpans(const ShapeAudit& audit, unsigned criteria)
{
  std::vector<char> failing(audit.SpanMask.size());
  for (size_t j = 0; j < failing.size(); ++j)
  {
    failing[j] = (audit.SpanMask[j] & criteria) != 0;
  }
  return failing;
}

BuiltCurve interpolate(const FitContext& context, const QuinticFitOptions& quintic)
{
  const CleanPolyline& data = context.Data;
  const int count = static_cast<int>(data.Points.size());
  QuinticParameters parameters =
    QuinticParameters::uniform(quintic.Continuity, count, quintic.Gamma, quintic.Lambda);
  auto build = [&]() -> std::unique_ptr<Curve> {
    auto spline = std::make_unique<TensionQuinticSpline>(
      TensionQuinticSpline::interpolate(data.Points, context.Knots, parameters, data.Closed));
    // Lower from the parameters used: (34) may have pulled some towards 1.
    parameters = spline->parameters();
    return spline;
  };
  return fixedOrPreserved(
    quintic.Automatic, context, data, build,
    [&](const std::vector<char>& failing) {
      return lowerQuinticTension(parameters, failing, data.Closed, quintic.Floor);
    },
    quintic.MaxRounds);
}
} // namespace

QuinticApproximation approximateKeepingTorsionSigns(const std::vector<Vec3>& points,
  const std::vector<double>& u, int numberOfKnots, bool closed, const QuinticFitOptions& quintic,
  const FitOptions& fit, double coordinateNoise)
{
  QuinticApproximation result;
  result.Knots = uniformKnots(u, closed ? numberOfKnots + 1 : numberOfKnots);
  result.Polygon = leastSquaresPolygon(points, u, result.Knots, closed);
  CleanPolyline reference;
  reference.Points = result.Polygon;
  reference.Closed = closed;
  const DiscreteShape shape = discreteShape(reference, fit.Tolerances);
  constexpr unsigned torsion = (1u << static_cast<int>(ShapeCriterion::TorsionSignAtKnot)) |
    (1u << static_cast<int>(ShapeCriterion::TorsionSignOnSpan));
  QuinticParameters parameters =
    QuinticParameters::uniform(quintic.Continuity, numberOfKnots, quintic.Gamma, quintic.Lambda);
  for (int round = 0;; ++round)
  {
    result.Spline = std::make_unique<TensionQuinticSpline>(
      TensionQuinticSpline::approximate(points, u, result.Knots, parameters, closed));
    const ShapeAudit audit = auditCurve(
      *result.Spline, reference, shape, fit.Tolerances, fit.AuditSubdivisions, coordinateNoise);
    result.TorsionSignViolations =
      audit.Failures[static_cast<int>(ShapeCriterion::TorsionSignAtKnot)] +
      audit.Failures[static_cast<int>(ShapeCriterion::TorsionSignOnSpan)];
    parameters = result.Spline->parameters();
    if (!quintic.Automatic || result.TorsionSignViolations == 0 || round == quintic.MaxRounds ||
      !lowerQuinticTension(parameters, failingSpans(audit, torsion), closed, quintic.Floor))
    {
      return result;
    }
  }
}

CurveBuilder tensionQuinticBuilder(const QuinticFitOptions& quintic)
{
  return [quintic](const FitContext& context) {
    const int count = static_cast<int>(context.Data.Points.size());
    // At least two points per knot, as the variable degree family: with more
    // knots the least squares fit the noise (measured on a noisy helix of 49
    // points: 37 knots give curvature 7.5 for 0.4, 45 a condition of 8e18);
    // and the n + 5 de Boor points of n spans need n + 5 points. A closed
    // curve needs three distinct knots (its n spans have n de Boor points).
    const bool closed = context.Data.Closed;
    const int highest = closed ? count / 2 : std::min(count / 2, count - 4);
    const std::vector<Vec3>& points = context.Data.Points;
    const std::vector<double>& u = context.Knots;
    std::optional<QuinticApproximation> approximation = fitWithKnotCount(
      quintic.ApproximationKnots, closed, highest,
      [&] { return crossValidatedKnotCount(points, u, highest, closed); },
      [&](int knots) {
        return approximateKeepingTorsionSigns(
          points, u, knots, closed, quintic, context.Options, context.CoordinateNoise);
      });
    if (!approximation)
    {
      return interpolate(context, quintic);
    }
    BuiltCurve built;
    built.Spline = std::move(approximation->Spline);
    CleanPolyline reference;
    reference.Points = std::move(approximation->Polygon);
    reference.Closed = closed;
    built.ShapeReference = std::move(reference);
    return built;
  };
}
} // namespace shapesplines
