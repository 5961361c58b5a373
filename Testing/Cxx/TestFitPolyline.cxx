// The fitting pipeline every family shares: the automatic shape-preservation
// loop (preserveShape) and curves that approximate rather than interpolate.
#include "MathTestUtilities.h"

#include <gtest/gtest.h>

using namespace shapesplines;
using namespace shapesplines::test;

namespace
{
/**
 * A toy family with one shape parameter per span: the cubic blended with the
 * chord, s = (1 - w) cubic + w chord. w = 1 makes a span straight, which
 * breaks no criterion of Definition 1, so the loop must end with no violation.
 */
class BlendedCubic final : public Curve
{
public:
  BlendedCubic(const CleanPolyline& data, const std::vector<double>& knots, std::vector<double> weights)
    : Curve(knots, data.Closed)
    , Cubic(CubicSpline::interpolate(data.Points, knots, data.Closed))
    , Points(data.Points)
    , Weights(std::move(weights))
  {
  }

  Derivatives evaluateOnSpan(int span, double t, int order) const override
  {
    Derivatives d = this->Cubic.evaluateOnSpan(span, t, order);
    const double w = this->Weights[span];
    const Vec3& a = this->Points[span];
    const Vec3& b = this->Points[(span + 1) % this->Points.size()];
    const double h = this->Knots[span + 1] - this->Knots[span];
    for (Vec3& v : d)
    {
      v *= 1.0 - w;
    }
    d[0] += w * (a + (t - this->Knots[span]) / h * (b - a));
    if (order >= 1)
    {
      d[1] += w * (b - a) / h;
    }
    return d;
  }

  std::vector<SpanParameter> spanParameters() const override
  {
    return { { "Blend", this->Weights, true } };
  }

private:
  CubicSpline Cubic;
  std::vector<Vec3> Points;
  std::vector<double> Weights;
};

int Rounds = 0;

CurveBuilder blendedBuilder(int maxRounds)
{
  return [maxRounds](const FitContext& context) {
    std::vector<double> weights(context.Knots.size() - 1, 0.0);
    BuiltCurve built;
    built.Audit.emplace();
    Rounds = 0;
    built.Spline = preserveShape(
      context, context.Data,
      [&] {
        ++Rounds;
        return std::make_unique<BlendedCubic>(context.Data, context.Knots, weights);
      },
      [&](const std::vector<char>& failing) {
        bool changed = false;
        for (size_t j = 0; j < failing.size(); ++j)
        {
          if (failing[j] && weights[j] < 1.0)
          {
            weights[j] = std::min(1.0, weights[j] + 0.5);
            changed = true;
          }
        }
        return changed;
      },
      maxRounds, &*built.Audit);
    return built;
  };
}
} // namespace

TEST(PreserveShape, TightensOnlyFailingSpansUntilNoneFails)
{
  const FittedPolyline cubic = fitPolyline(akima(), FitOptions{}, cubicBuilder());
  ASSERT_FALSE(cubic.Audit.preserving());
  const FittedPolyline fit = fitPolyline(akima(), FitOptions{}, blendedBuilder(64));
  EXPECT_TRUE(fit.Audit.preserving()) << fit.Audit.violations();
  // Its own audit agrees with an independent one of the final curve.
  EXPECT_EQ(fit.Audit.SpanMask, auditCurve(*fit.Spline, fit.Data, fit.Shape, FitOptions{}.Tolerances,
                                  16, fit.CoordinateNoise)
                                  .SpanMask);
  const std::vector<double> weights = fit.Spline->spanParameters().at(0).Values;
  for (size_t j = 0; j < weights.size(); ++j)
  {
    // A blend changes its own span only: exactly the spans the cubic failed are tightened.
    EXPECT_EQ(weights[j] > 0.0, cubic.Audit.SpanMask[j] != 0) << "span " << j;
  }
  EXPECT_GT(*std::max_element(weights.begin(), weights.end()), 0.0);
  EXPECT_LE(Rounds, 3);
}

TEST(PreserveShape, StopsAfterMaxRounds)
{
  fitPolyline(akima(), FitOptions{}, blendedBuilder(1));
  EXPECT_EQ(Rounds, 2); // the first curve and one rebuild
  fitPolyline(akima(), FitOptions{}, blendedBuilder(0));
  EXPECT_EQ(Rounds, 1);
}

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
