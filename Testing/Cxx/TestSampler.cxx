// Sampling: knots among the samples, counts, arc length against closed forms.
#include "MathTestUtilities.h"

#include "Sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace shapesplines;
using namespace shapesplines::test;

namespace
{
/// y = x^2 on x in [0, 2] at uneven knots t = x: a not-a-knot cubic is exact.
CubicSpline parabola()
{
  std::vector<Vec3> points;
  std::vector<double> t;
  for (const double x : { 0.0, 0.3, 0.5, 1.1, 1.4, 2.0 })
  {
    points.emplace_back(x, x * x, 0);
    t.push_back(x);
  }
  return CubicSpline::interpolate(points, t, false);
}

double parabolaLength(double x)
{
  return 0.5 * x * std::sqrt(1 + 4 * x * x) + 0.25 * std::asinh(2 * x);
}
/// Points 1.9^i apart: on uniform knots the speed varies by 100x within spans.
std::vector<Vec3> unevenPoints()
{
  std::vector<Vec3> points;
  for (int i = 0; i < 12; ++i)
  {
    const double x = std::pow(1.9, i);
    points.emplace_back(x, std::sin(x), 0.1 * i);
  }
  return points;
}
} // namespace

TEST(Sampler, SubdivisionsKeepTheKnots)
{
  const CubicSpline s = parabola();
  SamplingOptions options;
  options.Subdivisions = 7;
  const CurveSamples samples = sampleCurve(s, options);
  ASSERT_EQ(samples.size(), 5 * 7 + 1);
  for (int i = 0; i <= 5; ++i)
  {
    EXPECT_EQ(samples.Parameter[7 * i], s.knots()[i]);
  }
  EXPECT_EQ(samples.Span.back(), 4);
}

TEST(Sampler, ArcLengthMatchesTheClosedForm)
{
  const CubicSpline s = parabola();
  const CurveSamples samples = sampleCurve(s, SamplingOptions{});
  EXPECT_NEAR(samples.Length, parabolaLength(2.0), 1e-12);
  for (int k = 0; k < samples.size(); ++k)
  {
    EXPECT_NEAR(samples.ArcLength[k], parabolaLength(samples.Parameter[k]), 1e-12);
  }
}

TEST(Sampler, ArcLengthModeSpacesSamplesEvenlyAndKeepsKnots)
{
  const CubicSpline s = parabola();
  SamplingOptions options;
  options.SampleMode = SamplingOptions::Mode::ArcLength;
  options.TargetLength = 0.05;
  const CurveSamples samples = sampleCurve(s, options);
  for (int i = 0; i <= 5; ++i)
  {
    EXPECT_NE(std::find(samples.Parameter.begin(), samples.Parameter.end(), s.knots()[i]),
      samples.Parameter.end());
  }
  for (int k = 1; k < samples.size(); ++k)
  {
    const double gap = samples.ArcLength[k] - samples.ArcLength[k - 1];
    EXPECT_GT(gap, 0.0);
    EXPECT_LE(gap, 0.05 * (1 + 1e-9));
    // Within one span the gaps are equal to 1e-9.
    if (k >= 2 && samples.Span[k] == samples.Span[k - 2] && samples.Span[k - 1] == samples.Span[k])
    {
      EXPECT_NEAR(gap, samples.ArcLength[k - 1] - samples.ArcLength[k - 2], 1e-9);
    }
  }
  EXPECT_NEAR(samples.size(), parabolaLength(2.0) / 0.05, 6.0);
}

TEST(Sampler, SampleBudgetWidensTheSpacing)
{
  const CubicSpline s = parabola();
  SamplingOptions options;
  options.SampleMode = SamplingOptions::Mode::ArcLength;
  options.TargetLength = 1e-12;
  options.MaximumSamples = 1000;
  const SamplingPlan plan = planSamples(s, options);
  EXPECT_TRUE(plan.LengthIncreased);
  EXPECT_LE(plan.size(), 1000 + 6);
  EXPECT_EQ(sampleCurve(s, plan).size(), plan.size());
}

TEST(Sampler, ClosedCurvesDoNotRepeatTheSeam)
{
  std::vector<Vec3> square = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0) };
  const CubicSpline s = CubicSpline::interpolate(square, { 0, 1, 2, 3, 4 }, true);
  SamplingOptions options;
  options.Subdivisions = 5;
  const CurveSamples samples = sampleCurve(s, options);
  EXPECT_EQ(samples.size(), 4 * 5);
  EXPECT_LT(samples.Parameter.back(), 4.0);
  EXPECT_GT(samples.Length, samples.ArcLength.back());
}

TEST(Sampler, ArcLengthBetweenSamplesWhereTheSpeedVariesFast)
{
  // Uneven points on uniform knots: the speed varies by 100x within spans.
  // The lengths between samples (a rule on the samples' own derivatives) are
  // checked against the 8-point Gauss-Legendre rule on 64 pieces of the gap.
  const std::vector<Vec3> points = unevenPoints();
  std::vector<double> knots(points.size());
  std::iota(knots.begin(), knots.end(), 0.0);
  for (const bool closed : { false, true })
  {
    if (closed)
    {
      knots.push_back(12);
    }
    const CubicSpline s = CubicSpline::interpolate(points, knots, closed);
    const CurveSamples samples = sampleCurve(s, SamplingOptions{});
    double reference = 0.0;
    for (int k = 1; k <= samples.size(); ++k)
    {
      const int span = samples.Span[k - 1];
      const double a = samples.Parameter[k - 1];
      const double b = k < samples.size() && samples.Span[k] == span ? samples.Parameter[k]
                                                                     : s.knots()[span + 1];
      for (int piece = 0; piece < 64; ++piece)
      {
        reference += s.arcLengthOnSpan(span, a + (b - a) * piece / 64, a + (b - a) * (piece + 1) / 64);
      }
      const double computed = k < samples.size() ? samples.ArcLength[k] : samples.Length;
      if (k < samples.size() || closed)
      {
        ASSERT_NEAR(computed, reference, 1e-9 * reference) << "sample " << k << " closed " << closed;
      }
    }
  }
}

TEST(Sampler, ArcLengthModeSpacesSamplesEvenlyWhereTheSpeedVariesFast)
{
  // Uneven points on uniform knots. Within a span, the last gap up to its knot too, the gaps are equal
  // (placed by one quadrature rule from the span start, whose length differed
  // from the span's measured in pieces, they were 2.8e-5 apart here; on a noisy helix's
  // automatic variable degree spline a gap was 5% over the spacing asked for).
  const std::vector<Vec3> points = unevenPoints();
  std::vector<double> knots(points.size());
  std::iota(knots.begin(), knots.end(), 0.0);
  const CubicSpline s = CubicSpline::interpolate(points, knots, false);
  SamplingOptions options;
  options.SampleMode = SamplingOptions::Mode::ArcLength;
  options.TargetLength = 0.5;
  const CurveSamples samples = sampleCurve(s, options);
  // Each span's gaps (the samples' own arc lengths) and their mean.
  std::vector<std::vector<double>> gaps(s.numberOfSpans());
  for (int k = 1; k < samples.size(); ++k)
  {
    const double gap = samples.ArcLength[k] - samples.ArcLength[k - 1];
    EXPECT_LE(gap, options.TargetLength * (1 + 1e-9)) << "sample " << k;
    gaps[samples.Span[k - 1]].push_back(gap);
  }
  double worst = 0.0;
  for (const std::vector<double>& span : gaps)
  {
    const double mean = std::accumulate(span.begin(), span.end(), 0.0) / span.size();
    for (const double gap : span)
    {
      worst = std::max(worst, std::abs(gap / mean - 1));
    }
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(Sampler, ArcLengthWhereTheCurveStops)
{
  // x = t^2 from t = 0 (a not-a-knot cubic reproduces it): the speed is 0 at
  // the first sample, where the rule on derivatives cannot be used.
  std::vector<Vec3> points;
  std::vector<double> t;
  for (const double u : { 0.0, 0.5, 1.2, 2.0 })
  {
    points.emplace_back(u * u, 0, 0);
    t.push_back(u);
  }
  const CurveSamples samples = sampleCurve(CubicSpline::interpolate(points, t, false), SamplingOptions{});
  for (int k = 0; k < samples.size(); ++k)
  {
    EXPECT_NEAR(samples.ArcLength[k], samples.Parameter[k] * samples.Parameter[k], 1e-12);
  }
}

TEST(Sampler, ProgressIsReportedInOrderAndCanStopTheWork)
{
  std::vector<Vec3> points;
  std::vector<double> t;
  for (int i = 0; i < 3000; ++i)
  {
    points.emplace_back(std::cos(0.1 * i), std::sin(0.1 * i), 0.01 * i);
    t.push_back(i);
  }
  const CubicSpline s = CubicSpline::interpolate(points, t, false);
  const SamplingPlan plan = planSamples(s, SamplingOptions{});
  std::vector<double> fractions;
  const CurveSamples samples = sampleCurve(s, plan, [&](double fraction) {
    fractions.push_back(fraction);
    return true;
  });
  EXPECT_EQ(samples.size(), plan.size());
  // 30001 samples: every 4096 while sampling, then while measuring arc length.
  EXPECT_GE(fractions.size(), 10u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_GE(fractions.front(), 0.0);
  EXPECT_LT(fractions.back(), 1.0);
  EXPECT_GT(fractions.back(), 0.9);
  int calls = 0;
  EXPECT_THROW(sampleCurve(s, plan, [&](double) { return ++calls < 3; }), FitAborted);
  EXPECT_EQ(calls, 3);
}
