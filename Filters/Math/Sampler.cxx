#include "Sampler.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shapesplines
{
namespace
{
// Progress: a block's samples (3/4 of its work), then their arc lengths.
constexpr long ProgressEvery = 4096;

/// The Gauss-Legendre rule on halves, recursively, until the halves agree with
/// their whole to 1e-10: a span through a near-stop (a kink in the speed)
/// needs it, one application can be off by 1e-4 there. At most `budget`
/// splits, so a speed that is rounding noise everywhere costs no more than that.
double adaptiveSpeedIntegral(
  const Curve& curve, int span, double a, double b, double whole, int& budget)
{
  const double middle = 0.5 * (a + b);
  const double left = curve.arcLengthOnSpan(span, a, middle);
  const double right = curve.arcLengthOnSpan(span, middle, b);
  const double halves = left + right;
  if (--budget <= 0 || !std::isfinite(halves) || std::abs(halves - whole) <= 1e-10 * halves)
  {
    return halves;
  }
  const double first = adaptiveSpeedIntegral(curve, span, a, middle, left, budget);
  return first + adaptiveSpeedIntegral(curve, span, middle, b, right, budget);
}

/// Start of piece p of a span (SamplingPlan::SpanPieces; |s'| is smooth but not polynomial).
double pieceStart(const Curve& curve, int span, int p)
{
  const double t0 = curve.knots()[span];
  const double t1 = curve.knots()[span + 1];
  return p == SamplingPlan::SpanPieces ? t1 : t0 + p * ((t1 - t0) / SamplingPlan::SpanPieces);
}

SpeedJet speedJet(const Derivatives& d)
{
  const double speed = d[1].norm();
  const double first = d[1].dot(d[2]) / speed;
  return { speed, first, (d[2].squaredNorm() + d[1].dot(d[3]) - first * first) / speed };
}

/**
 * Arc length between two samples a < b of one span, from the speed jets of
 * the values the samples already hold (s', s'', s''' at both ends, b's taken
 * on this span) and the speed at the middle: the symmetric rule exact for polynomials of
 * degree 7 (weights derived on [-1, 1]: 19/35 for the end values, 4/35 and
 * 1/105 for their first and second derivatives, 32/35 for the middle).
 * Where it differs from the quintic Hermite rule (the same without the middle)
 * by more than 1e-7 of the length (the degree 7 rule is then measured within
 * ~1e-9, on qqr spans whose speed varies fastest), or the curve stops at an
 * end, the 8-point Gauss-Legendre rule is used instead: as it is, where it
 * agrees with the degree 7 rule to 1e-8 (two rules exact to degrees 7 and
 * 15 that agree: the speed is smooth there, the latter far closer; raised
 * variable degree spans, whose speed is steep near a knot, spend a sixth of
 * their automatic mode's time otherwise), else on halves until they agree.
 * Two evaluations per sample instead of nine on smooth spans.
 */
double sampledArcLength(
  const Curve& curve, int span, double a, const SpeedJet& left, double b, const SpeedJet& right)
{
  const double half = 0.5 * (b - a);
  const double ends = left.Value + right.Value;
  const double slopes = half * (left.First - right.First);
  const double bends = half * half * (left.Second + right.Second);
  const double hermite = half * (ends + 0.4 * slopes + bends / 15.0);
  const double middle = curve.evaluateOnSpan(span, a + half, 1)[1].norm();
  const double withMiddle =
    half * (19.0 / 35.0 * ends + 4.0 / 35.0 * slopes + bends / 105.0 + 32.0 / 35.0 * middle);
  // Neither rule is trusted where the curve stops at an end.
  const bool moving = std::isfinite(withMiddle) && left.Value > 0 && right.Value > 0;
  if (moving && std::abs(withMiddle - hermite) <= 1e-7 * withMiddle)
  {
    return withMiddle;
  }
  const double gauss = curve.arcLengthOnSpan(span, a, b);
  if (moving && std::abs(gauss - withMiddle) <= 1e-8 * gauss)
  {
    return gauss;
  }
  int budget = 64;
  return adaptiveSpeedIntegral(curve, span, a, b, gauss, budget);
}

/**
 * Parameter in span where the arc length from the span start reaches that
 * fraction of the span's length, measured as the plan measured the span:
 * whole pieces, then the one it ends in from that piece's start. One rule from
 * the span start would disagree with the span's length where the speed is
 * steep (a raised degree, a tension's boundary layer) and misplace samples
 * there (a gap 5% over the spacing asked for on a noisy helix's automatic
 * variable degree spline).
 */
double parameterAtLength(const Curve& curve, int span, double fraction, const double* pieces)
{
  double total = 0.0;
  for (int q = 0; q < SamplingPlan::SpanPieces; ++q)
  {
    total += pieces[q];
  }
  const double target = fraction * total;
  int p = 0;
  double before = 0.0;
  while (p + 1 < SamplingPlan::SpanPieces && before + pieces[p] < target)
  {
    before += pieces[p++];
  }
  const double start = pieceStart(curve, span, p);
  double lo = start;
  double hi = pieceStart(curve, span, p + 1);
  const double goal = target - before;
  double t = pieces[p] > 0 ? lo + (hi - lo) * std::clamp(goal / pieces[p], 0.0, 1.0) : lo;
  const double tolerance = 1e-13 * std::max(total, 1e-300);
  for (int iteration = 0; iteration < 60; ++iteration)
  {
    const double excess = curve.arcLengthOnSpan(span, start, t) - goal;
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

void reportProgress(const ProgressCallback& progress, long step, long every, double fraction)
{
  if (progress && step % every == 0 && !progress(fraction))
  {
    throw FitAborted();
  }
}

ProgressCallback progressWithin(const ProgressCallback& whole, double from, double to)
{
  if (!whole)
  {
    return {};
  }
  return [whole, from, to](double fraction) { return whole(from + (to - from) * fraction); };
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
  plan.PieceLengths.resize(static_cast<size_t>(spans) * SamplingPlan::SpanPieces);
  std::vector<double> spanLengths(spans, 0.0);
  double total = 0.0;
  for (int j = 0; j < spans; ++j)
  {
    for (int p = 0; p < SamplingPlan::SpanPieces; ++p)
    {
      const double piece =
        curve.arcLengthOnSpan(j, pieceStart(curve, j, p), pieceStart(curve, j, p + 1));
      plan.PieceLengths[j * SamplingPlan::SpanPieces + p] = piece;
      spanLengths[j] += piece;
    }
    total += spanLengths[j];
  }
  if (!std::isfinite(total))
  {
    throw std::invalid_argument("the curve's length is not finite: it left the double range");
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
    plan.PerSpan[j] = std::max(1L, static_cast<long>(std::ceil(spanLengths[j] / spacing - 1e-9)));
  }
  return plan;
}

CurveSamples sampleCurve(const Curve& curve, const SamplingOptions& options)
{
  return sampleCurve(curve, planSamples(curve, options));
}

CurveSamples sampleCurve(const Curve& curve, const SamplingPlan& plan, const ProgressCallback& progress)
{
  BlockSampler sampler(curve, plan);
  CurveSamples samples;
  sampler.sample(0, sampler.size(), samples, progress);
  sampler.measure(samples, progress);
  return samples;
}

BlockSampler::BlockSampler(const Curve& curve, const SamplingPlan& plan)
  : TheCurve(curve)
  , Plan(plan)
  , SpanStart(plan.PerSpan.size() + 1, 0)
{
  for (size_t j = 0; j < plan.PerSpan.size(); ++j)
  {
    this->SpanStart[j + 1] = this->SpanStart[j] + plan.PerSpan[j];
  }
}

double BlockSampler::parameter(int j, long k) const
{
  const auto& knots = this->TheCurve.knots();
  const double fraction = static_cast<double>(k) / this->Plan.PerSpan[j];
  const std::vector<double>& pieces = this->Plan.PieceLengths;
  if (pieces.empty() || k == 0)
  {
    return knots[j] + fraction * (knots[j + 1] - knots[j]);
  }
  return parameterAtLength(
    this->TheCurve, j, fraction, pieces.data() + static_cast<size_t>(j) * SamplingPlan::SpanPieces);
}

std::pair<int, double> BlockSampler::locate(long i) const
{
  const int spans = this->TheCurve.numberOfSpans();
  if (i >= this->SpanStart.back())
  {
    return { spans - 1, this->TheCurve.knots()[spans] }; // an open curve's end
  }
  const auto after = std::upper_bound(this->SpanStart.begin(), this->SpanStart.end(), i);
  const int j = static_cast<int>(after - this->SpanStart.begin()) - 1;
  return { j, this->parameter(j, i - this->SpanStart[j]) };
}

void BlockSampler::sample(
  long first, long count, CurveSamples& samples, const ProgressCallback& progress) const
{
  const auto& knots = this->TheCurve.knots();
  const double total = static_cast<double>(this->size());
  samples.First = first;
  samples.Parameter.resize(count);
  samples.Span.resize(count);
  samples.SpanFraction.resize(count);
  samples.Values.resize(count);
  samples.ArcLength.resize(count);
  // Span by span from the block's first sample, as sampleCurve would have it.
  auto [span, t] = this->locate(first);
  long inSpan = first - this->SpanStart[span];
  for (long k = 0; k < count; ++k)
  {
    reportProgress(progress, first + k, ProgressEvery, (first + 0.75 * k) / total);
    if (k > 0)
    {
      if (++inSpan == this->Plan.PerSpan[span] && span + 1 < this->TheCurve.numberOfSpans())
      {
        ++span;
        inSpan = 0;
      }
      t = inSpan < this->Plan.PerSpan[span] ? this->parameter(span, inSpan) : knots[span + 1];
    }
    samples.Parameter[k] = t;
    samples.Span[k] = span;
    samples.SpanFraction[k] = (t - knots[span]) / (knots[span + 1] - knots[span]);
    samples.Values[k] = this->TheCurve.evaluateOnSpan(span, t, 3);
  }
}

void BlockSampler::measure(CurveSamples& samples, const ProgressCallback& progress)
{
  const Curve& curve = this->TheCurve;
  const auto& knots = curve.knots();
  const int count = samples.size();
  const double total = static_cast<double>(this->size());
  if (samples.First != this->Measured || count == 0)
  {
    throw std::logic_error("BlockSampler: a block measured out of order");
  }
  // Consecutive samples share a span, or the later one starts the next span:
  // then the span's own values at its end are needed (the third derivative
  // can jump at the knot). Each sample's speed jet serves both its intervals.
  this->Jets.resize(count);
  std::transform(samples.Values.begin(), samples.Values.end(), this->Jets.begin(), speedJet);
  auto lengthTo = [&](int from, int span, double end, const SpeedJet* atEnd) {
    return sampledArcLength(curve, span, samples.Parameter[from], this->Jets[from], end,
      atEnd ? *atEnd : speedJet(curve.evaluateOnSpan(span, end, 3)));
  };
  samples.ArcLength[0] = this->Length;
  for (int k = 1; k < count; ++k)
  {
    reportProgress(progress, samples.First + k, ProgressEvery,
      (samples.First + 0.75 * count + 0.25 * k) / total);
    const int span = samples.Span[k - 1];
    const bool sameSpan = samples.Span[k] == span;
    samples.ArcLength[k] = samples.ArcLength[k - 1] +
      lengthTo(k - 1, span, sameSpan ? samples.Parameter[k] : knots[span + 1],
        sameSpan ? &this->Jets[k] : nullptr);
  }
  // On to the next sample, or round a closed curve's seam span.
  const int last = count - 1;
  const int span = samples.Span[last];
  this->Measured = samples.First + count;
  this->Length = samples.ArcLength[last];
  if (this->Measured < this->size())
  {
    const auto [nextSpan, t] = this->locate(this->Measured);
    this->Length += lengthTo(last, span, nextSpan == span ? t : knots[span + 1], nullptr);
  }
  else if (curve.isClosed())
  {
    this->Length += lengthTo(last, span, knots[span + 1], nullptr);
  }
  samples.Length = this->Length;
}
} // namespace shapesplines
