// ShapeSplines math core: sampling a curve, written once for every family.
#ifndef shapesplines_Sampler_h
#define shapesplines_Sampler_h

#include "Curve.h"

#include <functional>
#include <stdexcept>
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
  std::vector<long> PerSpan;
  std::vector<double> SpanLengths; ///< in arc-length mode: where the samples go
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
  std::vector<double> Parameter;
  std::vector<int> Span;
  std::vector<double> SpanFraction; ///< (t - t_span) / (t_span+1 - t_span), in [0, 1]
  std::vector<Derivatives> Values; ///< position and derivatives 1..3 (4th left zero)
  std::vector<double> ArcLength;   ///< from the first sample, by quadrature between samples (~1e-9 relative)
  double Length = 0.0;             ///< whole curve, including a closed curve's seam span

  int size() const { return static_cast<int>(this->Parameter.size()); }
};

/// Arc length of curve between parameters a <= b inside one span (Gauss-Legendre).
double arcLength(const Curve& curve, int span, double a, double b);

CurveSamples sampleCurve(
  const Curve& curve, const SamplingPlan& plan, const ProgressCallback& progress = {});
CurveSamples sampleCurve(const Curve& curve, const SamplingOptions& options);
} // namespace shapesplines

#endif
