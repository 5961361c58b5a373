#include "Sampler.h"

#include <algorithm>
#include <cmath>

namespace shapesplines
{
namespace
{
// 8-point Gauss-Legendre rule on [-1, 1]: exact for polynomials of degree 15.
constexpr std::array<double, 4> GaussNodes = { 0.1834346424956498, 0.5255324099163290,
  0.7966664774136267, 0.9602898564975363 };
constexpr std::array<double, 4> GaussWeights = { 0.3626837833783620, 0.3137066458778873,
  0.2223810344533745, 0.1012285362903763 };
// Subintervals per span for the span length: |s'| is smooth but not polynomial.
constexpr int SpanPieces = 4;

double speedIntegral(const Curve& curve, int span, double a, double b)
{
  const double mid = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  double sum = 0.0;
  for (size_t k = 0; k < GaussNodes.size(); ++k)
  {
    for (const double sign : { -1.0, 1.0 })
    {
      const double t = mid + sign * half * GaussNodes[k];
      sum += GaussWeights[k] * curve.evaluateOnSpan(span, t, 1)[1].norm();
    }
  }
  return half * sum;
}

double spanLength(const Curve& curve, int span)
{
  const double t0 = curve.knots()[span];
  const double h = (curve.knots()[span + 1] - t0) / SpanPieces;
  double length = 0.0;
  for (int p = 0; p < SpanPieces; ++p)
  {
    length += speedIntegral(curve, span, t0 + p * h, t0 + (p + 1) * h);
  }
  return length;
}

/// Parameter in span where the arc length from the span start reaches target.
double parameterAtLength(const Curve& curve, int span, double target, double total)
{
  double lo = curve.knots()[span];
  double hi = curve.knots()[span + 1];
  double t = lo + (hi - lo) * target / total;
  const double tolerance = 1e-13 * std::max(total, 1e-300);
  for (int iteration = 0; iteration < 60; ++iteration)
  {
    const double excess = arcLength(curve, span, curve.knots()[span], t) - target;
    if (std::abs(excess) <= tolerance)
    {
      break;
    }
    (excess > 0 ? hi : lo) = t;
    const double speed = curve.evaluateOnSpan(span, t, 1)[1].norm();
    const double newton = speed > 0 ? t - excess / speed : lo;
    // Newton while it stays inside the bracket, bisection otherwise.
    t = (newton > lo && newton < hi) ? newton : 0.5 * (lo + hi);
  }
  return t;
}
} // namespace

double arcLength(const Curve& curve, int span, double a, double b)
{
  return speedIntegral(curve, span, a, b);
}

long SamplingPlan::size() const
{
  long count = this->Closed ? 0 : 1;
  for (const long n : this->PerSpan)
  {
    count += n;
  }
  return count;
}

SamplingPlan planSamples(const Curve& curve, const SamplingOptions& options)
{
  const int spans = curve.numberOfSpans();
  SamplingPlan plan;
  plan.Closed = curve.isClosed();
  plan.PerSpan.assign(spans, std::max(1, options.Subdivisions));
  if (options.SampleMode != SamplingOptions::Mode::ArcLength)
  {
    return plan;
  }
  plan.SpanLengths.resize(spans);
  double total = 0.0;
  for (int j = 0; j < spans; ++j)
  {
    plan.SpanLengths[j] = spanLength(curve, j);
    total += plan.SpanLengths[j];
  }
  double spacing = options.TargetLength;
  const double budget = static_cast<double>(options.MaximumSamples - spans - 1);
  if (!(spacing > 0) || total / spacing > budget)
  {
    spacing = total / std::max(budget, 1.0);
    plan.LengthIncreased = true;
  }
  for (int j = 0; j < spans; ++j)
  {
    plan.PerSpan[j] = std::max(1L, static_cast<long>(std::ceil(plan.SpanLengths[j] / spacing - 1e-9)));
  }
  return plan;
}

CurveSamples sampleCurve(const Curve& curve, const SamplingOptions& options)
{
  return sampleCurve(curve, planSamples(curve, options));
}

CurveSamples sampleCurve(const Curve& curve, const SamplingPlan& plan)
{
  const int spans = curve.numberOfSpans();
  const auto& knots = curve.knots();
  const bool byArcLength = !plan.SpanLengths.empty();
  CurveSamples samples;
  const long count = plan.size();
  samples.Parameter.reserve(count);
  samples.Span.reserve(count);
  samples.Values.reserve(count);
  samples.SpanFraction.reserve(count);
  auto addSample = [&](int span, double t) {
    samples.Parameter.push_back(t);
    samples.Span.push_back(span);
    samples.SpanFraction.push_back((t - knots[span]) / (knots[span + 1] - knots[span]));
    samples.Values.push_back(curve.evaluateOnSpan(span, t, 3));
  };
  for (int j = 0; j < spans; ++j)
  {
    const double t0 = knots[j];
    const double t1 = knots[j + 1];
    for (long k = 0; k < plan.PerSpan[j]; ++k)
    {
      const double fraction = static_cast<double>(k) / plan.PerSpan[j];
      const double t = byArcLength && k > 0
        ? parameterAtLength(curve, j, fraction * plan.SpanLengths[j], plan.SpanLengths[j])
        : t0 + fraction * (t1 - t0);
      addSample(j, t);
    }
  }
  if (!curve.isClosed())
  {
    addSample(spans - 1, knots[spans]);
  }

  samples.ArcLength.resize(samples.size(), 0.0);
  for (int k = 1; k < samples.size(); ++k)
  {
    // Consecutive samples share a span, or the later one starts the next span.
    const int span = samples.Span[k - 1];
    const double end = samples.Span[k] == span ? samples.Parameter[k] : knots[span + 1];
    samples.ArcLength[k] =
      samples.ArcLength[k - 1] + arcLength(curve, span, samples.Parameter[k - 1], end);
  }
  samples.Length = samples.ArcLength.back();
  if (curve.isClosed())
  {
    samples.Length += arcLength(curve, spans - 1, samples.Parameter.back(), knots[spans]);
  }
  return samples;
}
} // namespace shapesplines
