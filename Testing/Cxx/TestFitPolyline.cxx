// The fitting pipeline every family shares: curves that approximate rather
// than interpolate.
#include "MathTestUtilities.h"

#include <gtest/gtest.h>

using namespace shapesplines;
using namespace shapesplines::test;

TEST(Approximation, KnotSamplesAreTheCurvesOwnAndTheAuditUsesTheReference)
{
  // The cubic through the data moved by d: it passes near, not through, the data.
  const Vec3 d(0.01, -0.02, 0.03);
  const CurveBuilder shifted = [d](const FitContext& context) {
    CleanPolyline moved = context.Data;
    for (Vec3& p : moved.Points)
    {
      p += d;
    }
    BuiltCurve built;
    built.Spline = std::make_unique<CubicSpline>(
      CubicSpline::interpolate(moved.Points, context.Knots, moved.Closed));
    built.ShapeReference = moved;
    return built;
  };
  const std::vector<Vec3> points = helix(8, 2);
  const FittedPolyline fit = fitPolyline(points, FitOptions{}, shifted);
  ASSERT_FALSE(fit.interpolates());
  // A translated polygon has the data's shape, which the cubic keeps on a helix.
  EXPECT_TRUE(fit.Audit.preserving());
  const SampledCurve sampled = sampleFit(fit);
  for (int k = 0; k < sampled.Samples.size(); ++k)
  {
    if (sampled.Samples.SpanFraction[k] == 0.0)
    {
      const Vec3 expected = fit.KnotPoints[sampled.Samples.Span[k]] + fit.Scale * d;
      EXPECT_LT((sampled.Samples.Values[k][0] - expected).norm(), 1e-12 * fit.Scale) << k;
    }
  }
}
