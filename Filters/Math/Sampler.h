// ShapeSplines math core: sampling a curve, written once for every family.
#ifndef shapesplines_Sampler_h
#define shapesplines_Sampler_h

#include "Curve.h"

#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace shapesplines
{
/**
 * Called now and then during long work on one line (sampling, shape audit)
 * with the fraction of that work done (an automatic mode audits many curves,
 * so the fraction can start over); returning false stops the work with
 * FitAborted.
 */
using ProgressCallback = std::function<bool(double fraction)>;

/// Thrown when a ProgressCallback asks to stop.
class FitAborted : public std::runtime_error
{
public:
  FitAborted()
    : std::runtime_error("aborted")
  {
  }
};

/// Calls progress, if any, with fraction when step is a multiple of every;
/// throws FitAborted when it says stop.
void reportProgress(const ProgressCallback& progress, long step, long every, double fraction);

/// A part of the work whole reports on: its fractions mapped to [from, to] (none without whole).
ProgressCallback progressWithin(const ProgressCallback& whole, double from, double to);

struct SamplingOptions
{
  enum class Mode
  {
    Subdivisions, ///< the same number of samples on every span
    ArcLength     ///< samples about TargetLength apart along the curve
  };
  Mode SampleMode = Mode::Subdivisions;
  int Subdivisions = 10;
  double TargetLength = 1.0;
  /// Upper bound on samples per curve; the arc-length spacing grows to respect it.
  long MaximumSamples = 10000000;
};

/// How many samples each span gets: decided before sampling, so that a caller
/// can place every curve's samples in one output before computing any.
struct SamplingPlan
{
  /// Arc length: each span measured in this many equal parameter pieces.
  static constexpr int SpanPieces = 4;

  std::vector<long> PerSpan;
  /// In arc-length mode, where the samples go: the pieces' lengths, span by span.
  std::vector<double> PieceLengths;
  bool LengthIncreased = false;    ///< the spacing was widened to respect MaximumSamples
  bool Closed = false;

  /// Number of samples: a closed curve does not repeat its seam point.
  long size() const;
};

SamplingPlan planSamples(const Curve& curve, const SamplingOptions& options);

/**
 * Samples of a curve: every knot is a sample, the samples of span j start at
 * its knot t_j, and a closed curve does not repeat its seam point.
 */
struct CurveSamples
{
  long First = 0; ///< index of the first of these samples on the curve (a block of them)
  std::vector<double> Parameter;
  std::vector<int> Span;
  std::vector<double> SpanFraction; ///< (t - t_span) / (t_span+1 - t_span), in [0, 1]
  std::vector<Derivatives> Values; ///< position and derivatives 1..3 (4th left zero)
  std::vector<double> ArcLength;   ///< from the first sample, by quadrature between samples (~1e-9 relative)
  /// Up to the sample after these: the whole curve, including a closed
  /// curve's seam span, after its last sample.
  double Length = 0.0;

  int size() const { return static_cast<int>(this->Parameter.size()); }
};

/// Speed |s'| and its first two derivatives in t, from s', s'' and s'''.
struct SpeedJet
{
  double Value, First, Second;
};

/**
 * Samples a curve as planned, a block of consecutive samples at a time, into
 * storage the caller reuses: a long curve's samples need never be held all
 * at once. A block's values do not depend on the blocks (sampleCurve samples
 * one): the arc length runs on from block to block. The curve and plan must
 * outlive the sampler.
 */
class BlockSampler
{
public:
  BlockSampler(const Curve& curve, const SamplingPlan& plan);

  /// Samples of the whole curve.
  long size() const { return this->SpanStart.back() + (this->Plan.Closed ? 0 : 1); }

  /// Samples first..first + count - 1 of the curve into samples, all but
  /// their arc lengths; any block, in any order.
  void sample(
    long first, long count, CurveSamples& samples, const ProgressCallback& progress = {}) const;

  /// The arc lengths of the block just sampled into samples, and its Length:
  /// blocks are measured in order along the curve, from its first sample.
  void measure(CurveSamples& samples, const ProgressCallback& progress = {});

private:
  /// Span and parameter of sample i of the curve.
  std::pair<int, double> locate(long i) const;
  /// The parameter of the k-th sample of span j.
  double parameter(int j, long k) const;

  const Curve& TheCurve;
  const SamplingPlan& Plan;
  /// Each span's first sample, then the samples before an open curve's end.
  std::vector<long> SpanStart;
  std::vector<SpeedJet> Jets;  ///< of the block being measured, reused
  long Measured = 0;           ///< samples measured so far
  double Length = 0.0;         ///< arc length to sample Measured
};

CurveSamples sampleCurve(
  const Curve& curve, const SamplingPlan& plan, const ProgressCallback& progress = {});
CurveSamples sampleCurve(const Curve& curve, const SamplingOptions& options);
} // namespace shapesplines

#endif
