// ShapeSplines math core: fitting polylines with tensioned quintic B-splines,
// fixed or automatic shape parameters, interpolation or least squares.
#ifndef shapesplines_TensionQuinticFit_h
#define shapesplines_TensionQuinticFit_h

#include "FitPolyline.h"
#include "TensionQuinticSpline.h"

#include <optional>

namespace shapesplines
{
struct QuinticFitOptions
{
  QuinticContinuity Continuity = QuinticContinuity::C4;
  /// Lower the tension (gamma, and lambda for C3, by sqrt(2) per level) only on
  /// spans that fail the shape audit, starting from Gamma and Lambda
  /// (preserveShapeAutomatically); otherwise Gamma and Lambda at every knot.
  bool Automatic = true;
  double Gamma = 1.0;
  double Lambda = 1.0;
  double Floor = QuinticTensionFloor;
  int MaxRounds = 64;
  /// 0: interpolate. Otherwise approximate the line in least squares with
  /// this many knots (at least 2, distinct ones of a closed line at least 3;
  /// at most half the points, and points - 4 when open; a line too short is
  /// interpolated), or CrossValidatedKnots:
  /// as many as generalized cross-validation chooses for the fixed
  /// parameters, keeping the torsion signs of L* (approximateKeepingTorsionSigns).
  int ApproximationKnots = 0;
  /// Approximations: correct the points' parameters towards the curve
  /// (planApproximation) rather than keep the given ones.
  bool CorrectParameters = true;
};

/// The family's builder for fitPolyline and the filter.
CurveBuilder tensionQuinticBuilder(const QuinticFitOptions& quintic);

/// A least-squares approximation and the polygon whose shape it keeps.
struct QuinticApproximation
{
  /// A TensionQuinticSpline, of an open line the stretch of one fitted on
  /// knots beyond its ends (TrimmedCurve, see extendForApproximation).
  std::unique_ptr<Curve> Spline;
  std::vector<double> Knots;  ///< placed uniformly in the data parameter (closed: with the closing one)
  std::vector<Vec3> Polygon;  ///< L*, one vertex per (distinct) knot
  std::vector<double> VertexNoise; ///< per vertex of L*, how far it moves with the points' noise
  std::optional<ShapeAudit> Audit; ///< against L*, when the automatic mode made it
};

/**
 * Paper 000, section 5: the spline with numberOfKnots knots (>= 2, uniform in
 * the data parameters u) closest in least squares to the points; automatic,
 * it keeps the shape (Definition 1, torsion signs included) of L*, the
 * least-squares polygon on the same knots, lowering the tension from 1 on the
 * spans that break it (preserveShapeAutomatically), counting only what
 * stands out of what points off the curve by about pointNoise move L*'s
 * vertices by (referencePolygon, discreteShape). Closed: a closed curve
 * with numberOfKnots distinct knots (>= 3), u with the closing parameter.
 */
QuinticApproximation approximateKeepingTorsionSigns(const std::vector<Vec3>& points,
  const std::vector<double>& u, int numberOfKnots, bool closed, const QuinticFitOptions& quintic,
  const FitContext& context, double pointNoise = 0.0);
} // namespace shapesplines

#endif
