#include "TensionQuinticFit.h"

#include "AutomaticShape.h"

#include <algorithm>
#include <cmath>

namespace shapesplines
{
namespace
{
/// The automatic mode's ladder of parameters: each level halves gamma (and
/// lambda, C3) at the knots of the span, down to the floor.
QuinticParameters loweredParameters(
  const QuinticFitOptions& quintic, const std::vector<int>& levels, bool closed)
{
  const std::vector<int> perKnot = knotLevels(levels, closed);
  const int knots = static_cast<int>(perKnot.size());
  QuinticParameters parameters =
    QuinticParameters::uniform(quintic.Continuity, knots, quintic.Gamma, quintic.Lambda);
  for (int i = 0; i < knots; ++i)
  {
    const double factor = std::ldexp(1.0, -perKnot[i]);
    parameters.Gamma[i] = std::max(quintic.Floor, std::min(quintic.Gamma, 1.0) * factor);
    parameters.Lambda[i] = std::max(quintic.Floor, std::min(quintic.Lambda, 1.0) * factor);
    if (perKnot[i] == 0)
    {
      parameters.Gamma[i] = quintic.Gamma;
      parameters.Lambda[i] = quintic.Lambda;
    }
  }
  return parameters;
}

ShapeLadder quinticLadder(const QuinticFitOptions& quintic)
{
  ShapeLadder ladder;
  ladder.TopLevel = static_cast<int>(std::ceil(std::log2(1.0 / quintic.Floor)));
  ladder.MaxRounds = quintic.MaxRounds;
  ladder.Reach = 3; // a knot's parameter moves the spans on both sides and the global solve
  return ladder;
}

BuiltCurve interpolate(const FitContext& context, const QuinticFitOptions& quintic)
{
  const CleanPolyline& data = context.Data;
  ShapeLadder ladder = quinticLadder(quintic);
  ladder.Build = [&](const std::vector<int>& levels) -> std::unique_ptr<Curve> {
    return std::make_unique<TensionQuinticSpline>(TensionQuinticSpline::interpolate(
      data.Points, context.Knots, loweredParameters(quintic, levels, data.Closed), data.Closed));
  };
  return fixedOrAutomatic(quintic.Automatic, context, data, ladder);
}
} // namespace

QuinticApproximation approximateKeepingTorsionSigns(const std::vector<Vec3>& points,
  const std::vector<double>& u, int numberOfKnots, bool closed, const QuinticFitOptions& quintic,
  const FitContext& context)
{
  QuinticApproximation result;
  result.Knots = uniformKnots(u, closed ? numberOfKnots + 1 : numberOfKnots);
  CleanPolyline reference;
  reference.Points = leastSquaresPolygon(points, u, result.Knots, closed);
  reference.Closed = closed;
  ShapeLadder ladder = quinticLadder(quintic);
  ladder.Build = [&](const std::vector<int>& levels) -> std::unique_ptr<Curve> {
    return std::make_unique<TensionQuinticSpline>(TensionQuinticSpline::approximate(
      points, u, result.Knots, loweredParameters(quintic, levels, closed), closed));
  };
  BuiltCurve built = fixedOrAutomatic(quintic.Automatic, context, reference, ladder);
  result.Spline.reset(static_cast<TensionQuinticSpline*>(built.Spline.release()));
  result.Audit = std::move(built.Audit);
  result.Polygon = std::move(reference.Points);
  return result;
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
        return approximateKeepingTorsionSigns(points, u, knots, closed, quintic, context);
      });
    if (!approximation)
    {
      return interpolate(context, quintic);
    }
    BuiltCurve built;
    built.Spline = std::move(approximation->Spline);
    built.Audit = std::move(approximation->Audit);
    CleanPolyline reference;
    reference.Points = std::move(approximation->Polygon);
    reference.Closed = closed;
    built.ShapeReference = std::move(reference);
    return built;
  };
}
} // namespace shapesplines
