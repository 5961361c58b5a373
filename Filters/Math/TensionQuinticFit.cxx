#include "TensionQuinticFit.h"

#include "Approximation.h"
#include "AutomaticShape.h"
#include "SparseSolve.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace shapesplines
{
namespace
{
/// Levels per halving of gamma: halving at each level overshot what a span
/// needed (1000 noisy helices: 201 violations left, 3.0x the fixed mode's
/// time; in two steps 132, 2.6x; 200 random polylines 300 -> 276).
constexpr double StepsPerHalving = 2.0;
/// The automatic mode's ladder of parameters: each level divides gamma (and
/// lambda, C3) at the knots of the span by sqrt(2), down to the floor.
QuinticParameters loweredParameters(
  const QuinticFitOptions& quintic, const std::vector<int>& levels, bool closed)
{
  const std::vector<int> perKnot = knotLevels(levels, closed);
  const int knots = static_cast<int>(perKnot.size());
  QuinticParameters parameters =
    QuinticParameters::uniform(quintic.Continuity, knots, quintic.Gamma, quintic.Lambda);
  for (int i = 0; i < knots; ++i)
  {
    const double factor = std::exp2(-perKnot[i] / StepsPerHalving);
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

/**
 * make()'s curve of the ladder's levels. A lowered gamma can leave the
 * abscissae X(t) not increasing on very uneven knots (refused with
 * std::domain_error): no curve at those levels, which the automatic search
 * takes as it takes a singular system; level 0 is refused as the fixed mode is.
 */
template <class Make>
std::unique_ptr<Curve> builtAt(const std::vector<int>& levels, const Make& make)
{
  try
  {
    return make();
  }
  catch (const std::domain_error&)
  {
    if (std::any_of(levels.begin(), levels.end(), [](int level) { return level != 0; }))
    {
      throw SingularSystem();
    }
    throw;
  }
}

ShapeLadder quinticLadder(const QuinticFitOptions& quintic)
{
  ShapeLadder ladder;
  ladder.TopLevel = static_cast<int>(std::ceil(StepsPerHalving * std::log2(1.0 / quintic.Floor)));
  ladder.MaxRounds = quintic.MaxRounds;
  ladder.Reach = 3; // a knot's parameter moves the spans on both sides and the global solve
  return ladder;
}

BuiltCurve interpolate(const FitContext& context, const QuinticFitOptions& quintic)
{
  const CleanPolyline& data = context.Data;
  ShapeLadder ladder = quinticLadder(quintic);
  ladder.RetryFromCommonLevel = true;
  ladder.RefineBackToLevelZero = false;
  // The same at every level: solved once, not in each of the search's builds.
  const auto ends = data.Closed
    ? std::nullopt
    : std::optional(TensionQuinticSpline::dataEnds(data.Points, context.Knots));
  // A search's builds change a few knots at a time; a fixed build needs no
  // copy of its weights (a line of 1e6 points: 288 MB).
  TensionQuinticSpline::WeightsMemo memo;
  TensionQuinticSpline::WeightsMemo* const kept = quintic.Automatic ? &memo : nullptr;
  ladder.Build = [&](const std::vector<int>& levels) {
    return builtAt(levels, [&] {
      return std::make_unique<TensionQuinticSpline>(TensionQuinticSpline::interpolate(data.Points,
        context.Knots, loweredParameters(quintic, levels, data.Closed), data.Closed,
        ends ? &*ends : nullptr, kept));
    });
  };
  return fixedOrAutomatic(quintic.Automatic, context, data, ladder);
}
} // namespace

QuinticApproximation approximateKeepingTorsionSigns(const std::vector<Vec3>& points,
  const std::vector<double>& u, int numberOfKnots, bool closed, const QuinticFitOptions& quintic,
  const FitContext& context, double pointNoise)
{
  const ExtendedData data = extendForApproximation(points, u, numberOfKnots, closed);
  const int spans = closed ? numberOfKnots : numberOfKnots - 1;
  ReferencePolygon reference = referencePolygon(data, closed, pointNoise);
  ShapeLadder ladder = quinticLadder(quintic);
  ladder.ReferenceNoise = reference.VertexNoise;
  ladder.Bounds.CurvatureChange = 2.0; // keeping L*'s shape must not flatten the fit
  TensionQuinticSpline::WeightsMemo memo; // as the interpolation's
  TensionQuinticSpline::WeightsMemo* const kept = quintic.Automatic ? &memo : nullptr;
  ladder.Build = [&](const std::vector<int>& levels) {
    return builtAt(levels, [&]() -> std::unique_ptr<Curve> {
      const std::vector<int> all = data.Extra > 0 ? extendedLevels(levels, data.Extra) : levels;
      auto whole = std::make_unique<TensionQuinticSpline>(
        TensionQuinticSpline::approximate(data.Points, data.Parameters, data.Knots,
          loweredParameters(quintic, all, closed), closed, kept));
      if (data.Extra == 0)
      {
        return whole;
      }
      return std::make_unique<TrimmedCurve>(std::move(whole), data.Extra, spans);
    });
  };
  BuiltCurve built = fixedOrAutomatic(quintic.Automatic, context, reference.Polygon, ladder);
  QuinticApproximation result;
  result.Spline = std::move(built.Spline);
  result.Audit = std::move(built.Audit);
  result.Knots = std::vector<double>(data.Knots.begin() + data.Extra, data.Knots.end() - data.Extra);
  result.Polygon = std::move(reference.Polygon.Points);
  result.VertexNoise = std::move(reference.VertexNoise);
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
    std::optional<BuiltCurve> approximation = approximateWithPlan(points, context.Knots,
      quintic.ApproximationKnots, closed, highest, quintic.CorrectParameters, context.Options.Progress,
      [&](const ApproximationPlan& plan, int knots) {
        QuinticApproximation fitted = approximateKeepingTorsionSigns(
          points, plan.Parameters, knots, closed, quintic, context, plan.NoiseLevel);
        BuiltCurve built;
        built.Spline = std::move(fitted.Spline);
        built.Audit = std::move(fitted.Audit);
        CleanPolyline reference;
        reference.Points = std::move(fitted.Polygon);
        reference.Closed = closed;
        built.ShapeReference = std::move(reference);
        built.ReferenceNoise = std::move(fitted.VertexNoise);
        return built;
      });
    return approximation ? std::move(*approximation) : interpolate(context, quintic);
  };
}
} // namespace shapesplines
