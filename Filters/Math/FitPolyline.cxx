#include "FitPolyline.h"

#include "Approximation.h"
#include "CubicSpline.h"
#include "ExtendedIndex.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace shapesplines
{
namespace
{
/// The curvature indistinguishable from zero on a span (see FitSampler).
class FlatnessThreshold
{
public:
  FlatnessThreshold(const Curve& curve, double diagonal, double coordinateNoise)
    : Knots(curve.knots())
    , Noise(coordinateNoise)
  {
    constexpr double RelativeFlatCurvature = 1e-10;
    this->Floor = RelativeFlatCurvature / (diagonal > 0 ? diagonal : 1.0);
  }

  double operator()(int span, const Vec3& firstDerivative) const
  {
    // A spline turns a point moved by +-noise into s'' of up to ~18 noise / dt^2
    // (measured on collinear data; not-a-knot ends amplify most): bound it by 32.
    constexpr double RoundingAmplification = 32.0;
    const double step = (this->Knots[span + 1] - this->Knots[span]) * firstDerivative.norm();
    return std::max(this->Floor, RoundingAmplification * this->Noise / (step * step));
  }

private:
  const std::vector<double>& Knots;
  double Noise;
  double Floor = 0.0;
};

/// Where f is least on [lo, hi], by golden section (f unimodal there): the
/// bracket shrinks to 5e-4 of its width.
template <class F>
double goldenSectionMinimum(const F& f, double lo, double hi)
{
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  constexpr int Steps = 16;
  for (int step = 0; step < Steps; ++step)
  {
    if (f1 < f2)
    {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = f(x1);
    }
    else
    {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = f(x2);
    }
  }
  return 0.5 * (lo + hi);
}

/**
 * The curvature and speed |s'| at the bottom of span j's deepest speed dip,
 * {0, infinity} without one: a sample slower than its neighbours (a knot
 * sample: than its one neighbour) and than 3/4 of the span's fastest,
 * refined by golden section between its neighbours. A near-cusp's curvature
 * spike can fall between samples, the dip in speed around it is wider; next
 * to a knot it can lie between the knot's sample and its neighbour (a
 * variable degree span at degree 35 slowed to 4% of its speed at 97% of it,
 * where its curvature peaked at 1.7e4 times the data's, 630 at its samples;
 * another, on a planar spiral, peaked at 9.8e4 where the sample next to the
 * dip still ran at half the span's fastest).
 */
std::pair<double, double> speedDip(
  const Curve& curve, int j, const std::vector<double>& speeds, double start, double h)
{
  const int last = static_cast<int>(speeds.size()) - 1;
  int slowest = -1;
  for (int k = 0; k <= last; ++k)
  {
    const bool dip =
      (k == 0 || speeds[k] < speeds[k - 1]) && (k == last || speeds[k] <= speeds[k + 1]);
    if (dip && (slowest < 0 || speeds[k] < speeds[slowest]))
    {
      slowest = k;
    }
  }
  constexpr double SlowFraction = 0.75;
  const double fastest = *std::max_element(speeds.begin(), speeds.end());
  if (slowest < 0 || speeds[slowest] >= SlowFraction * fastest)
  {
    return { 0.0, std::numeric_limits<double>::infinity() };
  }
  auto speedAt = [&](double x) { return curve.evaluateOnSpan(j, x, 1)[1].norm(); };
  const double x = goldenSectionMinimum(speedAt, start + h * std::max(slowest - 1, 0) / last,
    start + h * std::min(slowest + 1, last) / last);
  const Derivatives bottom = curve.evaluateOnSpan(j, x, 2);
  return { curvature(bottom[1], bottom[2]), bottom[1].norm() };
}

/**
 * The largest curvature on span j between its samples, where a spike can
 * hide far narrower than their spacing:
 * - between two samples that turn the tangent more than their curvatures
 *   explain (twice the larger over the chord between them, and more than
 *   1e-3 rad): a near-cusp, or a boundary layer that turns a lot. (A
 *   generalized cubic span next to one 18 times shorter showed 3.2 at its
 *   16 samples and turned by 0.5 rad at 0.5% of it, with a curvature of 7.8e5.)
 * - next to a knot sample more than 4 times as curved as its neighbour: a
 *   tension's boundary layer that turns little. (A generalized cubic span at
 *   tension 256 showed 12.8 at its knot and peaked at 4.5e4 within 0.25% of
 *   it, where it runs at 5% of its speed; a quintic span's knot sample, at
 *   36, ran faster than its neighbour and the peak, 1.2e4, lay between them.)
 * The interval is probed closer and closer to its ends (down to 2^-14 of
 * it; a layer's from its knot only, at every other power of two) and
 * refined by golden section between the neighbours of the highest probe (a
 * layer's only where a probe stands above the knot).
 */
double curvatureBetweenSamples(const Curve& curve, int j, const std::vector<Derivatives>& values,
  const std::vector<FrenetFrame>& frames, double start, double h)
{
  auto curvatureAt = [&](double fraction) {
    const Derivatives d = curve.evaluateOnSpan(j, start + h * fraction, 2);
    return curvature(d[1], d[2]);
  };
  constexpr int Closest = 14;
  const int last = static_cast<int>(frames.size()) - 1;
  const double width = 1.0 / last;
  std::vector<std::pair<double, double>> seen; // fraction of the span, curvature
  // Interval k's probes, from its start and/or its end.
  auto probe = [&](int k, bool fromStart, bool fromEnd, int step) {
    const double from = k * width;
    seen = { { from, frames[k].Curvature }, { from + width, frames[k + 1].Curvature } };
    for (int m = 1; m <= Closest; m += step)
    {
      const double offset = std::ldexp(width, -m);
      for (const double fraction : { fromStart ? from + offset : -1.0,
             fromEnd ? from + width - offset : -1.0 })
      {
        if (fraction >= 0.0)
        {
          seen.emplace_back(fraction, curvatureAt(fraction));
        }
      }
    }
    std::sort(seen.begin(), seen.end());
    return std::max_element(seen.begin(), seen.end(),
             [](const auto& p, const auto& q) { return p.second < q.second; }) -
      seen.begin();
  };
  auto refine = [&](size_t i) {
    const double x = goldenSectionMinimum([&](double u) { return -curvatureAt(u); },
      seen[i > 0 ? i - 1 : 0].first, seen[std::min(i + 1, seen.size() - 1)].first);
    return std::max(seen[i].second, curvatureAt(x));
  };
  constexpr double UnexplainedTurn = 2.0, SmallestTurn = 1e-3;
  double peak = 0.0;
  for (int k = 0; k < last; ++k)
  {
    const Vec3& a = frames[k].Tangent;
    const Vec3& b = frames[k + 1].Tangent;
    const double explained = std::max(SmallestTurn,
      UnexplainedTurn * (values[k + 1][0] - values[k][0]).norm() *
        std::max(frames[k].Curvature, frames[k + 1].Curvature));
    // The turn is at most its tangent (sine over cosine): most pairs pass without an atan2.
    const double sine = a.cross(b).norm(), cosine = a.dot(b);
    if ((cosine > 0.0 && sine <= explained * cosine) || std::atan2(sine, cosine) <= explained)
    {
      continue;
    }
    peak = std::max(peak, refine(probe(k, true, true, 1)));
  }
  constexpr double LayerCurvatureRatio = 4.0;
  for (const int knot : { 0, last })
  {
    const int inner = knot == 0 ? 1 : last - 1;
    if (frames[knot].Curvature > LayerCurvatureRatio * frames[inner].Curvature)
    {
      const int interval = knot == 0 ? 0 : last - 1;
      const size_t i = probe(interval, knot == 0, knot == last, 2);
      const bool aboveKnot = i != (knot == 0 ? 0 : seen.size() - 1);
      peak = std::max(peak, aboveKnot ? refine(i) : seen[i].second);
    }
  }
  return peak;
}

/**
 * A curvature or torsion back in data units. At a hairpin of a line only
 * 1e-100 wide the true value exceeds the double range: it saturates at the
 * largest double instead of becoming Inf.
 */
double toDataUnits(double perNormalisedLength, double scale)
{
  const double value = perNormalisedLength / scale;
  constexpr double largest = std::numeric_limits<double>::max();
  return std::isfinite(value) ? value : std::copysign(largest, perNormalisedLength);
}

/// Whether some sample of a block framed with these thresholds has a Frenet normal.
bool hasNormal(const std::vector<FrenetFrame>& frames, const std::vector<double>& thresholds)
{
  for (size_t k = 0; k < frames.size(); ++k)
  {
    if (frames[k].Curvature > thresholds[k])
    {
      return true;
    }
  }
  return false;
}
} // namespace

CurveAuditor::CurveAuditor(const CleanPolyline& reference, const DiscreteShape& shape,
  const ShapeTolerances& tolerances, int subdivisions, double coordinateNoise,
  AuditFigures figures)
  : Auditor(reference, shape, tolerances)
  , Subdivisions(std::max(subdivisions, 1))
  , CoordinateNoise(coordinateNoise)
  , Diagonal(boundingBoxDiagonal(reference.Points))
  , Reference(reference)
  , BoundFigures(figures != AuditFigures::None)
  , Curvature(std::max(reference.numberOfSpans(), 0), 0.0)
  , Speed(std::max(reference.numberOfSpans(), 0), 1.0)
  , Deviation(std::max(reference.numberOfSpans(), 0), 0.0)
  , LocalLength(std::max(reference.numberOfSpans(), 0), 1.0)
  , SampleCurvatures(
      figures == AuditFigures::BoundsAndSampleCurvatures ? std::max(reference.numberOfSpans(), 0) : 0)
{
  // The longest of a segment and its neighbours: how far a curve near the
  // polygon may stray from it there.
  const int spans = reference.numberOfSpans();
  for (int j = 0; j < spans; ++j)
  {
    double longest = 0.0;
    for (const int k : { j - 1, j, j + 1 })
    {
      if (reference.Closed || (k >= 0 && k < spans))
      {
        longest = std::max(longest, reference.segment(wrapIndex(k, spans)).norm());
      }
    }
    this->LocalLength[j] = longest > 0.0 ? longest : 1.0;
  }
}

void CurveAuditor::audit(const Curve& curve, int j)
{
  // Span by span: the audit keeps no samples, so auditing costs no memory traffic.
  const FlatnessThreshold flat(curve, this->Diagonal, this->CoordinateNoise);
  const auto& knots = curve.knots();
  const int subdivisions = this->Subdivisions;
  std::vector<Derivatives>& values = this->Values;
  std::vector<double>& speeds = this->Speeds;
  std::vector<double>& thresholds = this->Thresholds;
  values.resize(subdivisions + 1);
  speeds.resize(subdivisions + 1);
  thresholds.resize(subdivisions + 1);
  const double h = knots[j + 1] - knots[j];
  // Both ends of the span, so that its frames see both knots.
  for (int k = 0; k <= subdivisions; ++k)
  {
    values[k] = curve.evaluateOnSpan(j, knots[j] + h * k / subdivisions, 3);
  }
  // In a loop of their own, the samples' square roots and divisions overlap.
  for (int k = 0; k <= subdivisions; ++k)
  {
    speeds[k] = values[k][1].norm();
    thresholds[k] = flat(j, values[k][1]);
  }
  // A flat sample's normal only continues the frames (parallel transport):
  // the audit reads no normal where the curvature vanishes.
  frenetFrames(values, thresholds, this->Frames);
  const std::vector<FrenetFrame>& frames = this->Frames;
  const double chordSpeed = (values[subdivisions][0] - values[0][0]).norm() / h;
  // Distances from the reference's segment j, set up once for the span's samples.
  const Vec3& a = this->Reference.Points[j];
  const Vec3 ab = this->Reference.segment(j);
  const double squared = ab.squaredNorm();
  auto distanceToSegment = [&](const Vec3& p) {
    const double along = squared > 0.0 ? std::clamp((p - a).dot(ab) / squared, 0.0, 1.0) : 0.0;
    return (p - (a + along * ab)).norm();
  };
  double curvature = 0.0, speed = std::numeric_limits<double>::infinity(), deviation = 0.0;
  this->Auditor.forget(j);
  // Subdivisions + 1 doubles a span, more than the curve holds: kept only when asked for.
  std::vector<double>* sampleCurvatures =
    this->SampleCurvatures.empty() ? nullptr : &this->SampleCurvatures[j];
  if (sampleCurvatures)
  {
    sampleCurvatures->resize(subdivisions + 1);
  }
  // Both ends of every span: torsion is one-sided at a knot (the third
  // derivative jumps), so each knot is audited from both sides, and the
  // audit, and the automatic modes driven by it, do not depend on the
  // direction of the line.
  for (int k = 0; k <= subdivisions; ++k)
  {
    AuditSample sample;
    sample.Span = j;
    sample.Knot = k == 0 ? j : (k == subdivisions ? j + 1 : -1);
    sample.Frame = frames[k];
    sample.Flat = frames[k].Curvature <= thresholds[k];
    this->Auditor.add(sample);
    curvature = std::max(curvature, frames[k].Curvature);
    if (sampleCurvatures)
    {
      (*sampleCurvatures)[k] = frames[k].Curvature;
    }
    speed = std::min(speed, speeds[k]);
    deviation = std::max(deviation, distanceToSegment(values[k][0]));
  }
  this->Deviation[j] = deviation / this->LocalLength[j];
  if (!this->BoundFigures)
  {
    return;
  }
  const auto [dipCurvature, dipSpeed] = speedDip(curve, j, speeds, knots[j], h);
  const double between = curvatureBetweenSamples(curve, j, values, frames, knots[j], h);
  this->Curvature[j] = std::max({ curvature, dipCurvature, between });
  this->Speed[j] = chordSpeed > 0.0 ? std::min(speed, dipSpeed) / chordSpeed : 1.0;
}

ShapeAudit CurveAuditor::result() const
{
  ShapeAudit audit = this->Auditor.result();
  // A straying span fails outside Definition 1's criteria: the bit after them.
  constexpr unsigned StrayBit = 1u << static_cast<int>(ShapeCriterion::Count);
  for (size_t j = 0; j < this->Deviation.size(); ++j)
  {
    const double deviation = this->Deviation[j];
    if (deviation > audit.PolygonDeviation || audit.DeviationSpan < 0)
    {
      audit.PolygonDeviation = deviation;
      audit.DeviationSpan = static_cast<int>(j);
    }
    if (deviation > MaximumPolygonDeviation)
    {
      ++audit.StrayingSpans;
      audit.SpanMask[j] |= StrayBit;
      audit.SpanDeficiency[j] += deviation - MaximumPolygonDeviation;
    }
  }
  return audit;
}

void CurveAuditor::forget(int span)
{
  this->Auditor.forget(span);
  this->Curvature[span] = 0.0;
  this->Speed[span] = 1.0;
  this->Deviation[span] = 0.0;
}

void CurveAuditor::auditAll(const Curve& curve, const ProgressCallback& progress)
{
  const int spans = curve.numberOfSpans();
  for (int j = 0; j < spans; ++j)
  {
    reportProgress(progress, j, 1024, static_cast<double>(j) / spans);
    this->audit(curve, j);
  }
}

ShapeAudit auditCurve(const Curve& curve, const CleanPolyline& data, const DiscreteShape& shape,
  const ShapeTolerances& tolerances, int subdivisions, double coordinateNoise,
  const ProgressCallback& progress)
{
  CurveAuditor auditor(data, shape, tolerances, subdivisions, coordinateNoise);
  auditor.auditAll(curve, progress);
  return auditor.result();
}

ProgressPart::ProgressPart(const FitContext& whole, double from, double to)
  : Options(whole.Options)
  , Context{ whole.Data, whole.Knots, this->Options, whole.CoordinateNoise, whole.PointValues,
      whole.RoundingSteps }
{
  this->Options.Progress = progressWithin(whole.Options.Progress, from, to);
}

ShapeAudit FitContext::audit(const Curve& curve, const CleanPolyline& reference,
  const std::vector<double>& referenceNoise) const
{
  return auditCurve(curve, reference,
    discreteShape(reference, this->Options.Tolerances, referenceNoise, this->CoordinateNoise,
      this->RoundingSteps),
    this->Options.Tolerances, this->Options.AuditSubdivisions, this->CoordinateNoise,
    this->Options.Progress);
}

FitSampler::FitSampler(const FittedPolyline& fit, long blockSamples)
  : Fit(fit)
  , Sampler(*fit.Spline, fit.Plan)
  , BlockSamples(std::max(blockSamples, 1L))
  , Blocks((Sampler.size() + BlockSamples - 1) / BlockSamples)
  , Diagonal(boundingBoxDiagonal(fit.Data.Points))
{
}

void FitSampler::sampleBlock(SampledCurve& block, long b, const ProgressCallback& progress) const
{
  const long first = b * this->BlockSamples;
  this->Sampler.sample(
    first, std::min(this->BlockSamples, this->Sampler.size() - first), block.Samples, progress);
}

void FitSampler::frame(SampledCurve& block, const FrameNeighbours& neighbours)
{
  const FlatnessThreshold flat(*this->Fit.Spline, this->Diagonal, this->Fit.CoordinateNoise);
  const CurveSamples& samples = block.Samples;
  this->Thresholds.resize(samples.size());
  for (int k = 0; k < samples.size(); ++k)
  {
    this->Thresholds[k] = flat(samples.Span[k], samples.Values[k][1]);
  }
  frenetFrames(samples.Values, this->Thresholds, block.Frames, neighbours);
}

FrameNeighbours FitSampler::neighbours(long b) const
{
  FrameNeighbours around;
  around.PreviousTangent = b > 0 ? &this->LastTangent : nullptr;
  if (b > this->FirstDefinedBlock)
  {
    around.PreviousNormal = &this->LastNormal;
  }
  else if (b < this->FirstDefinedBlock)
  {
    around.NextNormal = &this->NextNormals[b];
  }
  return around;
}

void FitSampler::findLeadingNormals(const ProgressCallback& progress)
{
  // The curve framed at once transports its first normal back over the flat
  // samples before it: find it, block by block forwards (a tangent can carry
  // over), then carry it back block by block. Only a curve whose first block
  // is flat pays this second sampling.
  SampledCurve scan;
  std::vector<Vec3> lastTangents{ this->Block.Frames.back().Tangent };
  long b = 1;
  for (; b < this->Blocks; ++b)
  {
    this->sampleBlock(scan, b, progress);
    this->frame(scan, FrameNeighbours{ &lastTangents.back() });
    if (hasNormal(scan.Frames, this->Thresholds))
    {
      break;
    }
    lastTangents.push_back(scan.Frames.back().Tangent);
  }
  if (b == this->Blocks)
  {
    return; // no normal anywhere: block 0's first tangent chose them all
  }
  this->FirstDefinedBlock = b;
  this->NextNormals.resize(b);
  this->NextNormals[b - 1] = scan.Frames.front().Normal;
  for (long a = b - 1; a > 0; --a)
  {
    this->sampleBlock(scan, a, progress);
    this->frame(scan, FrameNeighbours{ &lastTangents[a - 1], nullptr, &this->NextNormals[a] });
    this->NextNormals[a - 1] = scan.Frames.front().Normal;
  }
}

bool FitSampler::next(const ProgressCallback& progress)
{
  if (this->Next == this->Blocks)
  {
    return false;
  }
  const long b = this->Next++;
  SampledCurve& block = this->Block;
  CurveSamples& samples = block.Samples;
  this->sampleBlock(block, b, progress);
  this->Sampler.measure(samples, progress);
  this->frame(block, this->neighbours(b));
  if (b == 0 && this->Blocks > 1 && !hasNormal(block.Frames, this->Thresholds))
  {
    this->findLeadingNormals(progress);
    if (this->FirstDefinedBlock > 0)
    {
      this->frame(block, this->neighbours(0));
    }
  }
  this->LastTangent = block.Frames.back().Tangent;
  this->LastNormal = block.Frames.back().Normal;
  // Back to data units. The knot samples of an interpolation are the data points, exactly.
  const FittedPolyline& fit = this->Fit;
  const long end = this->Sampler.size() - 1;
  for (int k = 0; k < samples.size(); ++k)
  {
    const int span = samples.Span[k];
    const bool atKnot = fit.interpolates() &&
      (samples.SpanFraction[k] == 0.0 || (!fit.Data.Closed && samples.First + k == end));
    const int knot = samples.SpanFraction[k] == 0.0 ? span : span + 1;
    samples.Values[k][0] =
      atKnot ? fit.KnotPoints[knot] : Vec3(fit.Origin + fit.Scale * samples.Values[k][0]);
    samples.Parameter[k] *= fit.ParameterScale;
    samples.ArcLength[k] *= fit.Scale;
    block.Frames[k].Curvature = toDataUnits(block.Frames[k].Curvature, fit.Scale);
    block.Frames[k].Torsion = toDataUnits(block.Frames[k].Torsion, fit.Scale);
  }
  samples.Length *= fit.Scale;
  return true;
}

SampledCurve sampleFit(const FittedPolyline& fit, const ProgressCallback& progress)
{
  FitSampler sampler(fit, fit.Plan.size());
  sampler.next(progress);
  return std::move(sampler.Block);
}

namespace
{
/// Refuses what fitPolyline cannot fit: non-finite points, coordinates
/// beyond LargestCoordinate, point values that are not one per point.
void checkPoints(const std::vector<Vec3>& points, const std::vector<double>& pointValues)
{
  if (!pointValues.empty() && pointValues.size() != points.size())
  {
    throw std::invalid_argument("point values do not match the points");
  }
  for (size_t i = 0; i < points.size(); ++i)
  {
    if (!points[i].allFinite())
    {
      throw std::invalid_argument("point " + std::to_string(i) + " is not finite");
    }
    if (points[i].cwiseAbs().maxCoeff() > LargestCoordinate)
    {
      throw std::invalid_argument("point " + std::to_string(i) +
        " has a coordinate beyond 1e300, where the curve can leave the double range");
    }
  }
}

/// The sampling options for the fit's normalised curve (a target length in
/// its units), arc-length samples capped at RunawayLengthFactor polylines.
SamplingOptions normalisedSampling(
  SamplingOptions sampling, const FittedPolyline& fit, const CleanPolyline& reference)
{
  sampling.TargetLength /= fit.Scale;
  if (sampling.SampleMode == SamplingOptions::Mode::ArcLength && sampling.TargetLength > 0.0)
  {
    const double runaway = RunawayLengthFactor * reference.length() / sampling.TargetLength;
    if (runaway < static_cast<double>(sampling.MaximumSamples))
    {
      sampling.MaximumSamples =
        std::max(static_cast<long>(std::ceil(runaway)), 2L * fit.Spline->numberOfSpans() + 2);
    }
  }
  return sampling;
}

/// Whether at least half the points sit inside exactly straight runs
/// (Definition 1's collinear points): designed points (tool paths, CAD
/// staircases), whose corners a least squares cannot follow either, so its
/// noise verdict would be wrong. Measured points are not collinear to 1e-6;
/// voxel paths of helices are at 34-41%, staircases of 4-step runs at 75%.
bool mostlyStraightRuns(const DiscreteShape& shape)
{
  const auto collinear = std::count(shape.Collinear.begin(), shape.Collinear.end(), 1);
  return 2 * collinear >= static_cast<long>(shape.Collinear.size());
}
} // namespace

FittedPolyline fitPolyline(const std::vector<Vec3>& points, const FitOptions& options,
  const CurveBuilder& build, const std::vector<double>& pointValues)
{
  checkPoints(points, pointValues);
  FittedPolyline fit;
  fit.Data = cleanPolyline(points, options.Closed);
  if (fit.Data.Points.size() < 2)
  {
    return fit;
  }
  fit.KnotPoints = fit.Data.Points;
  const auto [lo, hi] = boundingBox(fit.Data.Points);
  // Extents, not norms: squares of 1e-170 or 1e170 under- or overflow.
  fit.Origin = 0.5 * lo + 0.5 * hi;
  fit.Scale = (0.5 * hi - 0.5 * lo).cwiseAbs().maxCoeff() * 2.0;
  if (!(fit.Scale >= SmallestExtent))
  {
    throw std::invalid_argument("the distinct points span less than 1e-300, where their "
                                "differences lose every digit");
  }
  fit.CoordinateNoise = options.CoordinatePrecision *
    std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff()) / fit.Scale;
  fit.RoundingSteps = coordinateSteps(fit.Data.Points, options.CoordinatePrecision) / fit.Scale;
  for (Vec3& p : fit.Data.Points)
  {
    p = (p - fit.Origin) / fit.Scale;
  }
  fit.ParameterScale = options.Knots == Parameterization::ChordLength ? fit.Scale
    : options.Knots == Parameterization::Centripetal                 ? std::sqrt(fit.Scale)
                                                                      : 1.0;
  fit.Knots = computeKnots(fit.Data, options.Knots);
  // A span below the resolution of the cumulative parameter (1e-24 after a
  // span of 1) is a repeated point too: merge it rather than fail the solve.
  for (size_t i = 1; i < fit.Knots.size() && fit.Data.Points.size() > 2; ++i)
  {
    if (!(fit.Knots[i] > fit.Knots[i - 1]))
    {
      const size_t drop = i % fit.Data.Points.size(); // the closing span drops point 0
      fit.Data.Points.erase(fit.Data.Points.begin() + drop);
      fit.Data.SourceIndex.erase(fit.Data.SourceIndex.begin() + drop);
      fit.KnotPoints.erase(fit.KnotPoints.begin() + drop);
      ++fit.Data.MergedPoints;
      fit.Data.Closed = fit.Data.Closed && fit.Data.Points.size() >= 3;
      fit.Knots = computeKnots(fit.Data, options.Knots);
      i = 0;
    }
  }
  BuiltCurve built;
  if (fit.Data.Points.size() == 2)
  {
    built.Spline = std::make_unique<CubicSpline>(
      CubicSpline::interpolate(fit.Data.Points, fit.Knots, false, CubicEndCondition::Natural));
  }
  else
  {
    std::vector<double> values;
    for (size_t i = 0; i < fit.Data.SourceIndex.size() && !pointValues.empty(); ++i)
    {
      values.push_back(pointValues[fit.Data.SourceIndex[i]]);
    }
    built = build(
      FitContext{ fit.Data, fit.Knots, options, fit.CoordinateNoise, values, fit.RoundingSteps });
  }
  fit.Spline = std::move(built.Spline);
  fit.ShapeReference = std::move(built.ShapeReference);
  if (built.DataParameters)
  {
    fit.Knots = std::move(*built.DataParameters);
  }
  fit.NoiseLevel = built.NoiseLevel * fit.Scale;
  fit.StarvedSpan = built.StarvedSpan;
  const CleanPolyline& reference = fit.ShapeReference ? *fit.ShapeReference : fit.Data;
  fit.Shape = discreteShape(
    reference, options.Tolerances, built.ReferenceNoise, fit.CoordinateNoise, fit.RoundingSteps);
  fit.LooksNoisy = !fit.ShapeReference && !mostlyStraightRuns(fit.Shape) &&
    looksNoisy(fit.Data.Points, fit.Knots, fit.Data.Closed);
  fit.Audit = built.Audit ? *std::move(built.Audit)
                          : auditCurve(*fit.Spline, reference, fit.Shape, options.Tolerances,
                              options.AuditSubdivisions, fit.CoordinateNoise, options.Progress);
  fit.Plan = planSamples(*fit.Spline, normalisedSampling(options.Sampling, fit, reference));
  return fit;
}
} // namespace shapesplines
