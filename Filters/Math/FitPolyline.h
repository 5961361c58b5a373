// ShapeSplines math core: the path from raw polyline points to a sampled,
// framed and audited curve, shared by every spline family.
#ifndef shapesplines_FitPolyline_h
#define shapesplines_FitPolyline_h

#include "Curve.h"
#include "FrenetFrame.h"
#include "Parameterization.h"
#include "Sampler.h"
#include "ShapeAnalysis.h"

#include <functional>
#include <memory>
#include <vector>

namespace shapesplines
{
struct FitOptions
{
  Parameterization Knots = Parameterization::ChordLength;
  bool Closed = false; ///< close the line even if its last point is not its first
  SamplingOptions Sampling;
  ShapeTolerances Tolerances;
  /// Samples per span of the shape audit, independent of the output sampling.
  int AuditSubdivisions = 16;
  /// Relative precision of the input coordinates (FLT_EPSILON for float input):
  /// curvature within their rounding counts as zero.
  double CoordinatePrecision = 2.220446049250313e-16;
};

/// Builds a family's curve through the cleaned data (at least three points).
using CurveBuilder =
  std::function<std::unique_ptr<Curve>(const CleanPolyline& data, const std::vector<double>& knots)>;

/**
 * A family's curve through one polyline, audited, with its sampling planned
 * but not done: sampleFit() samples it when its output is written, so that
 * no more than one line's samples per thread are ever held.
 */
struct FittedPolyline
{
  /// The cleaned points in a normalised frame, (p - Origin) / Scale: centred on
  /// their bounding box and of unit extent. The spline is fitted there, so
  /// rounding scales with the line's size, not with its distance from the
  /// coordinate origin, and no coordinate size (1e-160 or 1e160) over- or
  /// underflows. sampleFit() returns data units.
  CleanPolyline Data;
  Vec3 Origin = Vec3::Zero();
  double Scale = 1.0;           ///< largest extent of the bounding box
  double ParameterScale = 1.0;  ///< data-unit parameter per normalised parameter
  std::vector<Vec3> KnotPoints; ///< the cleaned points in input coordinates
  double CoordinateNoise = 0.0; ///< rounding of the input coordinates, normalised
  std::vector<double> Knots;    ///< normalised parameter
  std::unique_ptr<Curve> Spline; ///< null when the data has fewer than two distinct points
  DiscreteShape Shape;
  ShapeAudit Audit;
  SamplingPlan Plan;
};

/// A fitted curve's samples and their Frenet frames, in data units (positions,
/// parameter, arc length, curvature, torsion); derivatives stay normalised.
struct SampledCurve
{
  CurveSamples Samples;
  std::vector<FrenetFrame> Frames;
};

/**
 * Per sample, the curvature indistinguishable from zero, where the Frenet
 * normal and the torsion are not defined: 1e-10 of the inverse
 * bounding-box diagonal, or what the data's rounding (coordinateNoise) can cause:
 * an acceleration across the tangent of 32 noise / dt^2 on a span of parameter
 * length dt, that is a curvature of 32 noise / (dt |s'|)^2.
 */
std::vector<double> flatCurvature(const Curve& curve, const CurveSamples& samples,
  const CleanPolyline& data, double coordinateNoise);

/// Audits a curve through data on a uniform sampling (for automatic tension loops).
ShapeAudit auditCurve(const Curve& curve, const CleanPolyline& data, const DiscreteShape& shape,
  const ShapeTolerances& tolerances, int subdivisions, double coordinateNoise);

/// Coordinates beyond this are refused: a curve through them (its overshoot,
/// its arc length) can leave the double range.
constexpr double LargestCoordinate = 1e300;

/**
 * Cleans the points, computes knots, builds the curve (two distinct points
 * give the straight segment whatever the family), audits its shape and plans
 * its sampling. Throws std::invalid_argument for non-finite points and for
 * coordinates beyond LargestCoordinate.
 */
FittedPolyline fitPolyline(
  const std::vector<Vec3>& points, const FitOptions& options, const CurveBuilder& build);

/**
 * Samples a fitted curve as planned, with Frenet frames, curvature and torsion
 * from its exact derivatives; the knot samples are the data points, exactly.
 * Written once for every family. The fit must have a Spline.
 */
SampledCurve sampleFit(const FittedPolyline& fit);
} // namespace shapesplines

#endif
