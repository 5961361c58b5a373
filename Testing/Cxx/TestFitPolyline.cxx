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

namespace
{
/// One span, t in [0, 1], of s = (u^2, u^3 + e u, 0), u = t - t0: a
/// near-cusp at t0, speed e and curvature 2 / e^2 there.
class NearCusp final : public Curve
{
public:
  NearCusp(double t0, double e)
    : Curve({ 0.0, 1.0 }, false)
    , T0(t0)
    , E(e)
  {
  }

  Derivatives evaluateOnSpan(int, double t, int order) const override
  {
    const double u = t - this->T0;
    Derivatives d;
    d.fill(Vec3::Zero());
    d[0] = Vec3(u * u, u * u * u + this->E * u, 0.0);
    d[1] = order >= 1 ? Vec3(2.0 * u, 3.0 * u * u + this->E, 0.0) : Vec3::Zero();
    d[2] = order >= 2 ? Vec3(2.0, 6.0 * u, 0.0) : Vec3::Zero();
    d[3] = order >= 3 ? Vec3(0.0, 6.0, 0.0) : Vec3::Zero();
    return d;
  }

private:
  double T0, E;
};
} // namespace

TEST(CurveAuditor, FindsANearCuspBetweenItsSamples)
{
  // Midway between two of the 16 samples the curvature of the near-cusp is
  // 2e6, at the samples 16: the automatic modes' bounds did not see it (a
  // quintic on the aorta kept one, 7.6e4 times the data's curvature). Its
  // dip in speed spans several samples: refined there, the bounds see it.
  const double e = 1e-3;
  const NearCusp curve(0.5 + 1.0 / 32.0, e);
  const CleanPolyline reference =
    cleanPolyline({ curve.evaluate(0.0, 0)[0], curve.evaluate(1.0, 0)[0] }, false);
  const DiscreteShape shape = discreteShape(reference); // the auditor keeps a reference
  CurveAuditor auditor(reference, shape, ShapeTolerances{}, 16, 0.0, AuditFigures::Bounds);
  auditor.audit(curve, 0);
  EXPECT_NEAR(auditor.largestCurvature(0), 2.0 / (e * e), 0.01 * 2.0 / (e * e));
  const double chordSpeed = reference.segment(0).norm();
  EXPECT_NEAR(auditor.lowestSpeed(0) * chordSpeed, e, 1e-3 * e);
}

TEST(CurveAuditor, ForgettingASpanDropsWhatItFoundUntilItIsAuditedAgain)
{
  // The automatic modes' refining leaves the spans a trial cannot mend
  // without findings, to count the trial's violations from below.
  const CleanPolyline reference = cleanPolyline(
    { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(4, 1, 0), Vec3(4.5, 3, 0) },
    false);
  const DiscreteShape shape = discreteShape(reference);
  const std::vector<double> knots = computeKnots(reference, Parameterization::ChordLength);
  const CubicSpline cubic = CubicSpline::interpolate(reference.Points, knots, false);
  CurveAuditor auditor(reference, shape, ShapeTolerances{}, 16, 0.0, AuditFigures::Bounds);
  auditor.auditAll(cubic);
  const ShapeAudit whole = auditor.result();
  ASSERT_GT(whole.violations(), 0); // the cubic overshoots where the straight run meets the turn
  const int spans = reference.numberOfSpans();
  for (int j = 0; j < spans; ++j)
  {
    if (whole.SpanMask[j] == 0)
    {
      continue;
    }
    auditor.forget(j);
    // A failure at a knot is found from both its spans: it may stay.
    EXPECT_LE(auditor.result().violations(), whole.violations()) << j;
    EXPECT_EQ(auditor.largestCurvature(j), 0.0) << j;
    EXPECT_EQ(auditor.largestDeviation(j), 0.0) << j;
    auditor.audit(cubic, j);
    const ShapeAudit again = auditor.result();
    EXPECT_EQ(again.violations(), whole.violations()) << j;
    EXPECT_EQ(again.SpanMask, whole.SpanMask) << j;
  }
  int previous = whole.violations();
  for (int j = 0; j < spans; ++j)
  {
    auditor.forget(j);
    const int now = auditor.result().violations();
    EXPECT_LE(now, previous) << j;
    previous = now;
  }
  EXPECT_EQ(previous, 0);
}

TEST(ProgressPart, ReportsItsFractionsWithinItsPartOfTheWhole)
{
  // A builder that runs several searches gives each a part of the line's
  // progress (qqr: a quarter each), and an abort from the whole stops a part.
  std::vector<double> reported;
  bool stop = false;
  FitOptions options;
  options.Progress = [&](double fraction) {
    reported.push_back(fraction);
    return !stop;
  };
  CleanPolyline data;
  data.Points = helix(8, 1);
  const std::vector<double> knots = computeKnots(data, Parameterization::ChordLength);
  const std::vector<double> noValues;
  const FitContext whole{ data, knots, options, 0.0, noValues };
  const ProgressPart part(whole, 0.25, 0.5);
  EXPECT_EQ(&part.context().Data, &data);
  reportProgress(part.context().Options.Progress, 0, 1, 0.0);
  reportProgress(part.context().Options.Progress, 0, 1, 0.5);
  reportProgress(part.context().Options.Progress, 0, 1, 1.0);
  EXPECT_EQ(reported, (std::vector<double>{ 0.25, 0.375, 0.5 }));
  stop = true;
  EXPECT_THROW(reportProgress(part.context().Options.Progress, 0, 1, 0.75), FitAborted);
  const FitOptions quiet;
  const FitContext silent{ data, knots, quiet, 0.0, noValues };
  EXPECT_FALSE(ProgressPart(silent, 0.0, 0.5).context().Options.Progress);
}
