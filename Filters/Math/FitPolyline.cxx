#include "FitPolyline.h"

#include "CubicSpline.h"

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

ShapeAudit auditCurve(const Curve& curve, const CleanPolyline& data, const DiscreteShape& shape,
  const ShapeTolerances& tolerances, int subdivisions)
{
  SamplingOptions uniform;
  uniform.Subdivisions = subdivisions;
  const CurveSamples samples = sampleCurve(curve, uniform);
  const auto frames = frenetFrames(samples.Values, boundingBoxDiagonal(data.Points));
  return auditShape(data, shape, auditSamples(samples, frames, curve.isClosed()), tolerances);
}

void sampleAndAudit(FittedPolyline& fit, const FitOptions& options)
{
  const double scale = boundingBoxDiagonal(fit.Data.Points);
  fit.Samples = sampleCurve(*fit.Spline, options.Sampling);
  fit.Frames = frenetFrames(fit.Samples.Values, scale);
  fit.Shape = discreteShape(fit.Data, options.Tolerances);
  fit.Audit =
    auditCurve(*fit.Spline, fit.Data, fit.Shape, options.Tolerances, options.AuditSubdivisions);
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
  return fit;
}
} // namespace shapesplines
