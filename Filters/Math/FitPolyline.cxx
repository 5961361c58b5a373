#include "FitPolyline.h"

#include "CubicSpline.h"

#include <algorithm>
#include <stdexcept>

namespace shapesplines
{
namespace
{
std::vector<AuditSample> auditSamples(
  const CurveSamples& samples, const std::vector<FrenetFrame>& frames, bool closed)
{
  std::vector<AuditSample> audit(samples.size());
  for (int k = 0; k < samples.size(); ++k)
  {
    audit[k].Span = samples.Span[k];
    audit[k].Frame = frames[k];
  }
  markKnots(audit, closed);
  return audit;
}
} // namespace

std::vector<double> flatCurvature(const Curve& curve, const CurveSamples& samples,
  const CleanPolyline& data, double coordinateNoise)
{
  constexpr double RelativeFlatCurvature = 1e-10;
  // A spline turns a point moved by +-noise into s'' of up to ~18 noise / dt^2
  // (measured on collinear data; not-a-knot ends amplify most): bound it by 32.
  constexpr double RoundingAmplification = 32.0;
  const double diagonal = boundingBoxDiagonal(data.Points);
  const double floor = RelativeFlatCurvature / (diagonal > 0 ? diagonal : 1.0);
  const auto& knots = curve.knots();
  std::vector<double> flat(samples.size());
  for (int k = 0; k < samples.size(); ++k)
  {
    const int span = samples.Span[k];
    const double step = (knots[span + 1] - knots[span]) * samples.Values[k][1].norm();
    flat[k] = std::max(floor, RoundingAmplification * coordinateNoise / (step * step));
  }
  return flat;
}

ShapeAudit auditCurve(const Curve& curve, const CleanPolyline& data, const DiscreteShape& shape,
  const ShapeTolerances& tolerances, int subdivisions, double coordinateNoise)
{
  SamplingOptions uniform;
  uniform.Subdivisions = subdivisions;
  uniform.MeasureArcLength = false;
  const CurveSamples samples = sampleCurve(curve, uniform);
  const auto frames =
    frenetFrames(samples.Values, flatCurvature(curve, samples, data, coordinateNoise));
  return auditShape(data, shape, auditSamples(samples, frames, curve.isClosed()), tolerances);
}

void sampleAndAudit(FittedPolyline& fit, const FitOptions& options)
{
  fit.Samples = sampleCurve(*fit.Spline, options.Sampling);
  fit.Frames = frenetFrames(
    fit.Samples.Values, flatCurvature(*fit.Spline, fit.Samples, fit.Data, fit.CoordinateNoise));
  for (Derivatives& sample : fit.Samples.Values)
  {
    sample[0] += fit.Origin;
  }
  fit.Shape = discreteShape(fit.Data, options.Tolerances);
  fit.Audit = auditCurve(*fit.Spline, fit.Data, fit.Shape, options.Tolerances,
    options.AuditSubdivisions, fit.CoordinateNoise);
}

FittedPolyline fitPolyline(
  const std::vector<Vec3>& points, const FitOptions& options, const CurveBuilder& build)
{
  for (size_t i = 0; i < points.size(); ++i)
  {
    if (!points[i].allFinite())
    {
      throw std::invalid_argument("point " + std::to_string(i) + " is not finite");
    }
  }
  FittedPolyline fit;
  fit.Data = cleanPolyline(points, options.Closed);
  if (fit.Data.Points.size() < 2)
  {
    return fit;
  }
  Vec3 lo = fit.Data.Points.front();
  Vec3 hi = lo;
  for (const Vec3& p : fit.Data.Points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  fit.Origin = 0.5 * (lo + hi);
  fit.CoordinateNoise = options.CoordinatePrecision * std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  for (Vec3& p : fit.Data.Points)
  {
    p -= fit.Origin;
  }
  fit.Knots = computeKnots(fit.Data, options.Knots);
  if (fit.Data.Points.size() == 2)
  {
    fit.Spline = std::make_unique<CubicSpline>(
      CubicSpline::interpolate(fit.Data.Points, fit.Knots, false, CubicEndCondition::Natural));
  }
  else
  {
    fit.Spline = build(fit.Data, fit.Knots);
  }
  sampleAndAudit(fit, options);
  // The knot samples are the data points, exactly (not shifted there and back).
  CurveSamples& samples = fit.Samples;
  for (int k = 0; k < samples.size(); ++k)
  {
    const int span = samples.Span[k];
    if (samples.Parameter[k] == fit.Knots[span])
    {
      samples.Values[k][0] = points[fit.Data.SourceIndex[span]];
    }
  }
  if (!fit.Data.Closed)
  {
    samples.Values.back()[0] = points[fit.Data.SourceIndex.back()];
  }
  return fit;
}
} // namespace shapesplines
