// libFuzzer target of the math core: fitPolyline (clean, knots, cubic spline,
// discrete shape, audit, sampling plan) and sampleFit (samples, Frenet frames),
// then auditShape on the samples. Every invariant failure calls abort().
//
// Input format (little-endian; missing header bytes read as zero):
//   byte  0      knot parameterization: b % 3 (Uniform, ChordLength, Centripetal)
//   byte  1      cubic end condition:   b % 3 (Natural, NotAKnot, Clamped)
//   byte  2      flags: bit 0 closed; bit 1 arc-length sampling; bits 2-3 point
//                encoding (0 double, 1 float, 2 and 3 small integers); bit 4 float
//                coordinate precision (FLT_EPSILON instead of DBL_EPSILON)
//   byte  3      output subdivisions: 1 + b % 32
//   byte  4      audit subdivisions:  1 + b % 32
//   bytes 5-12   target arc length (double): |x| clamped to [1e-9, 1e9], 1 if not finite or 0
//   byte  13     data tolerance:  b == 255 ? 0 : 10^-(b % 17)
//   byte  14     curve tolerance: b == 255 ? 0 : 10^-(b % 17)
//   byte  15     small integers: scale 2^e, e = (int8_t)b
//   byte  16     small integers: offset 0 if b == 0, else 2^(b % 64) added to x, y, z
//   bytes 17-    points, at most 64, each three coordinates:
//                  double encoding: 3 x 8 bytes (NaN, Inf, huge, tiny, anything)
//                  float encoding:  3 x 4 bytes
//                  small integers:  3 x 1 byte, coordinate ((b % 9) - 4) * scale + offset
//
// Setting FUZZ_FIT_EXTRA=1 in the environment adds stricter invariants that the
// specification implies but does not state (see extraChecksOn below);
// FUZZ_FIT_VERBOSE=1 prints each decoded input (to describe a reproducer).
// FUZZ_FIT_EXPONENT_LIMIT=N skips inputs with a finite non-zero coordinate outside
// [2^-N, 2^N] (e.g. N=200, about 1e+-60) to fuzz past known dynamic-range failures.
#define FUZZ_TARGET_NAME "fuzz_fit"
#include "FuzzCheck.h"

#include "CubicSpline.h"
#include "FitPolyline.h"
#include "GeneralizedCubicSpline.h"
#include "QQRSpline.h"
#include "TensionQuinticFit.h"
#include "VariableDegreeSpline.h"
#include "Parameterization.h"
#include "ShapeAnalysis.h"
#include "SparseSolve.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace ss = shapesplines;

namespace
{
constexpr size_t MaximumPoints = 64;
// Arc-length sampling costs ~0.1 ms per sample here (Newton steps, each a Gauss-Legendre
// quadrature): 512 samples keep the worst input near 50 ms and still hit the budget.
constexpr long MaximumSamples = 512;
constexpr double UnitTolerance = 1e-6;

bool environmentFlag(const char* name)
{
  const char* value = std::getenv(name);
  return value != nullptr && value[0] != '\0' && value[0] != '0';
}

bool extraChecks()
{
  static const bool enabled = environmentFlag("FUZZ_FIT_EXTRA");
  return enabled;
}

bool verbose()
{
  static const bool enabled = environmentFlag("FUZZ_FIT_VERBOSE");
  return enabled;
}

/// Reads the input front to back; bytes past the end read as zero.
class Reader
{
public:
  Reader(const uint8_t* data, size_t size)
    : Data(data)
    , Size(size)
  {
  }
  uint8_t byte()
  {
    return this->Offset < this->Size ? this->Data[this->Offset++] : (++this->Offset, 0);
  }
  template <typename T>
  T value()
  {
    unsigned char bytes[sizeof(T)] = {};
    for (size_t i = 0; i < sizeof(T); ++i)
    {
      bytes[i] = this->byte();
    }
    T out;
    std::memcpy(&out, bytes, sizeof(T)); // x86-64 and the corpus script are little-endian
    return out;
  }
  size_t remaining() const { return this->Offset < this->Size ? this->Size - this->Offset : 0; }

private:
  const uint8_t* Data;
  size_t Size;
  size_t Offset = 0;
};

double tolerance(uint8_t b)
{
  return b == 255 ? 0.0 : std::pow(10.0, -static_cast<double>(b % 17));
}

struct Input
{
  ss::FitOptions Options;
  ss::CubicEndCondition Ends = ss::CubicEndCondition::NotAKnot;
  /// 0: the cubic; 1: the qqr interpolation, automatic; 2: the variable
  /// degree spline (by the end byte: automatic with polynomial ends,
  /// automatic clamped, fixed degree 40 with natural ends); 3: the C4
  /// tensioned quintic, automatic; 4-7: the generalized cubic, automatic
  /// exponential, trigonometric and variable degree (polynomial ends), and
  /// fixed exponential tension 50 with natural ends.
  int Family = 0;
  std::vector<ss::Vec3> Points;
};

Input decode(const uint8_t* data, size_t size)
{
  Reader in(data, size);
  Input input;
  ss::FitOptions& o = input.Options;
  o.Knots = static_cast<ss::Parameterization>(in.byte() % 3);
  input.Ends = static_cast<ss::CubicEndCondition>(in.byte() % 3);
  const uint8_t flags = in.byte();
  o.Closed = (flags & 1) != 0;
  o.Sampling.SampleMode =
    (flags & 2) != 0 ? ss::SamplingOptions::Mode::ArcLength : ss::SamplingOptions::Mode::Subdivisions;
  const int encoding = (flags >> 2) & 3;
  input.Family = (flags >> 5) & 7;
  if ((flags & 16) != 0)
  {
    o.CoordinatePrecision = FLT_EPSILON;
  }
  o.Sampling.Subdivisions = 1 + in.byte() % 32;
  o.AuditSubdivisions = 1 + in.byte() % 32;
  double length = std::abs(in.value<double>());
  o.Sampling.TargetLength =
    std::isfinite(length) && length > 0 ? std::min(std::max(length, 1e-9), 1e9) : 1.0;
  o.Sampling.MaximumSamples = MaximumSamples;
  o.Tolerances.Data = tolerance(in.byte());
  o.Tolerances.Curve = tolerance(in.byte());
  const double scale = std::ldexp(1.0, static_cast<int8_t>(in.byte()));
  const uint8_t offsetCode = in.byte();
  const double offset = offsetCode == 0 ? 0.0 : std::ldexp(1.0, offsetCode % 64);

  const size_t pointSize = encoding == 0 ? 24 : (encoding == 1 ? 12 : 3);
  const size_t count = std::min(in.remaining() / pointSize, MaximumPoints);
  input.Points.reserve(count);
  for (size_t i = 0; i < count; ++i)
  {
    ss::Vec3 p;
    for (int c = 0; c < 3; ++c)
    {
      if (encoding == 0)
      {
        p[c] = in.value<double>();
      }
      else if (encoding == 1)
      {
        p[c] = static_cast<double>(in.value<float>());
      }
      else
      {
        p[c] = (static_cast<int>(in.byte() % 9) - 4) * scale + offset;
      }
    }
    input.Points.push_back(p);
  }
  return input;
}

void print(const Input& input)
{
  const ss::FitOptions& o = input.Options;
  static const char* const knots[] = { "Uniform", "ChordLength", "Centripetal" };
  static const char* const ends[] = { "Natural", "NotAKnot", "Clamped" };
  std::fprintf(stderr,
    "fuzz_fit input: family %d, knots %s, ends %s, closed %d, sampling %s, subdivisions %d, "
    "audit subdivisions %d, target length %.17g, maximum samples %ld, tolerances data %g "
    "curve %g, coordinate precision %g, %zu points:\n",
    input.Family, knots[static_cast<int>(o.Knots)], ends[static_cast<int>(input.Ends)],
    static_cast<int>(o.Closed),
    o.Sampling.SampleMode == ss::SamplingOptions::Mode::ArcLength ? "ArcLength" : "Subdivisions",
    o.Sampling.Subdivisions, o.AuditSubdivisions, o.Sampling.TargetLength,
    o.Sampling.MaximumSamples, o.Tolerances.Data, o.Tolerances.Curve, o.CoordinatePrecision,
    input.Points.size());
  for (size_t i = 0; i < input.Points.size(); ++i)
  {
    const ss::Vec3& p = input.Points[i];
    std::fprintf(stderr, "  %2zu: %.17g %.17g %.17g\n", i, p.x(), p.y(), p.z());
  }
}

int exponentLimit()
{
  static const int limit = [] {
    const char* value = std::getenv("FUZZ_FIT_EXPONENT_LIMIT");
    return value != nullptr ? std::atoi(value) : 0;
  }();
  return limit;
}

bool outsideExponentLimit(const std::vector<ss::Vec3>& points)
{
  const int limit = exponentLimit();
  if (limit <= 0)
  {
    return false;
  }
  for (const ss::Vec3& p : points)
  {
    for (int c = 0; c < 3; ++c)
    {
      int exponent = 0;
      if (std::isfinite(p[c]) && p[c] != 0.0)
      {
        std::frexp(p[c], &exponent);
        if (std::abs(exponent) > limit)
        {
          return true;
        }
      }
    }
  }
  return false;
}

bool isUnit(const ss::Vec3& v)
{
  return std::abs(v.norm() - 1.0) <= UnitTolerance;
}

void checkFrame(const ss::FrenetFrame& f, int k)
{
  CHECK(f.Tangent.allFinite() && f.Normal.allFinite() && f.Binormal.allFinite(),
    "sample %d: non-finite frame T=(%g %g %g) N=(%g %g %g) B=(%g %g %g)", k, f.Tangent.x(),
    f.Tangent.y(), f.Tangent.z(), f.Normal.x(), f.Normal.y(), f.Normal.z(), f.Binormal.x(),
    f.Binormal.y(), f.Binormal.z());
  CHECK(std::isfinite(f.Curvature), "sample %d: curvature %g", k, f.Curvature);
  CHECK(std::isfinite(f.Torsion), "sample %d: torsion %g", k, f.Torsion);
  CHECK(f.Curvature >= 0, "sample %d: negative curvature %g", k, f.Curvature);
  CHECK(isUnit(f.Tangent) && isUnit(f.Normal) && isUnit(f.Binormal),
    "sample %d: frame not unit: |T|-1=%g |N|-1=%g |B|-1=%g", k, f.Tangent.norm() - 1,
    f.Normal.norm() - 1, f.Binormal.norm() - 1);
  CHECK(std::abs(f.Tangent.dot(f.Normal)) <= UnitTolerance &&
      std::abs(f.Tangent.dot(f.Binormal)) <= UnitTolerance &&
      std::abs(f.Normal.dot(f.Binormal)) <= UnitTolerance,
    "sample %d: frame not orthogonal: T.N=%g T.B=%g N.B=%g", k, f.Tangent.dot(f.Normal),
    f.Tangent.dot(f.Binormal), f.Normal.dot(f.Binormal));
}

void checkAudit(const ss::ShapeAudit& audit, int spans, const char* which)
{
  CHECK(audit.violations() >= 0, "%s: %d violations", which, audit.violations());
  for (size_t c = 0; c < audit.Failures.size(); ++c)
  {
    CHECK(audit.Failures[c] >= 0, "%s: criterion %zu has %d failures", which, c, audit.Failures[c]);
  }
  CHECK(static_cast<int>(audit.SpanMask.size()) == spans, "%s: %zu span masks for %d spans", which,
    audit.SpanMask.size(), spans);
}

/// Invariants of the cleaning and knots alone, also on non-finite input (no throw, no UB).
void checkCleaning(const std::vector<ss::Vec3>& points, const ss::FitOptions& options)
{
  const ss::CleanPolyline line = ss::cleanPolyline(points, options.Closed);
  CHECK(line.Points.size() == line.SourceIndex.size(), "cleanPolyline: %zu points, %zu indices",
    line.Points.size(), line.SourceIndex.size());
  CHECK(line.Points.size() <= points.size(), "cleanPolyline: more points out than in");
  if (line.Points.empty())
  {
    return;
  }
  const std::vector<double> knots = ss::computeKnots(line, options.Knots);
  CHECK(static_cast<int>(knots.size()) == line.numberOfSpans() + 1,
    "computeKnots: %zu knots for %d spans", knots.size(), line.numberOfSpans());
}

void extraChecksOn(const std::vector<ss::Vec3>& points, const ss::FittedPolyline& fit,
  const ss::SampledCurve* sampled)
{
  // Two distinct finite points give a curve (FitPolyline.h: the spline is null only
  // when the data has fewer than two distinct points).
  if (!fit.Spline)
  {
    for (size_t i = 1; i < points.size(); ++i)
    {
      CHECK(points[i] == points[0],
        "extra: no spline although points 0 and %zu differ: (%g %g %g) (%g %g %g)", i,
        points[0].x(), points[0].y(), points[0].z(), points[i].x(), points[i].y(), points[i].z());
    }
    return;
  }
  for (size_t i = 0; i < fit.Knots.size(); ++i)
  {
    CHECK(std::isfinite(fit.Knots[i]), "extra: knot %zu is %g", i, fit.Knots[i]);
  }
  const ss::DiscreteShape& s = fit.Shape;
  for (size_t i = 0; i < s.Curvature.size(); ++i)
  {
    CHECK(std::isfinite(s.Curvature[i]) && s.Binormal[i].allFinite(),
      "extra: discrete shape at point %zu: curvature %g binormal (%g %g %g)", i, s.Curvature[i],
      s.Binormal[i].x(), s.Binormal[i].y(), s.Binormal[i].z());
  }
  for (size_t i = 0; i < s.Torsion.size(); ++i)
  {
    CHECK(std::isfinite(s.Torsion[i]), "extra: discrete torsion of segment %zu is %g", i,
      s.Torsion[i]);
  }
  if (sampled != nullptr)
  {
    const ss::CurveSamples& c = sampled->Samples;
    for (int k = 0; k < c.size(); ++k)
    {
      CHECK(std::isfinite(c.ArcLength[k]) && (k == 0 || c.ArcLength[k] >= c.ArcLength[k - 1]),
        "extra: arc length of sample %d is %g (previous %g)", k, c.ArcLength[k],
        k > 0 ? c.ArcLength[k - 1] : 0.0);
    }
    CHECK(std::isfinite(c.Length), "extra: curve length %g", c.Length);
  }
}
} // namespace

/**
 * The curve stays with its data: the audit's PolygonDeviation is finite, a
 * span beyond MaximumPolygonDeviation is counted and makes the line not
 * shape-preserving; and where the output samples are the audit's (same
 * subdivisions of every span, an interpolation whose condition is trusted),
 * the deviation measured again on them, in data units, is the audit's. The
 * knot samples are the data points: an untrusted curve (fuzz: qqr with a
 * condition estimate of 2e12 on spans 1e-12 of their neighbours) may miss
 * them by far, which the audit sees and the knot samples do not.
 */
void checkDeviation(
  const ss::FittedPolyline& fit, const ss::CurveSamples& samples, const ss::FitOptions& options)
{
  const ss::ShapeAudit& audit = fit.Audit;
  CHECK(std::isfinite(audit.PolygonDeviation) && audit.PolygonDeviation >= 0.0,
    "PolygonDeviation %g", audit.PolygonDeviation);
  CHECK((audit.PolygonDeviation > ss::MaximumPolygonDeviation) == (audit.StrayingSpans > 0),
    "PolygonDeviation %g with %d straying spans", audit.PolygonDeviation, audit.StrayingSpans);
  CHECK(audit.StrayingSpans == 0 || (!audit.preserving() && audit.violations() > 0),
    "%d straying spans on a line called shape-preserving", audit.StrayingSpans);
  if (!fit.interpolates() || fit.Spline->conditionEstimate() > ss::UntrustedCondition ||
    options.Sampling.SampleMode != ss::SamplingOptions::Mode::Subdivisions ||
    options.Sampling.Subdivisions != options.AuditSubdivisions ||
    std::any_of(fit.Plan.PerSpan.begin(), fit.Plan.PerSpan.end(),
      [&](long perSpan) { return perSpan != options.AuditSubdivisions; }))
  {
    return; // samples elsewhere than the audit's (or capped by the budget)
  }
  // Measured in units of the data's largest coordinate (a power of two:
  // exact), where squared lengths neither overflow nor underflow.
  double largestCoordinate = 0.0;
  for (const ss::Vec3& p : fit.KnotPoints)
  {
    largestCoordinate = std::max(largestCoordinate, p.cwiseAbs().maxCoeff());
  }
  const double unit = largestCoordinate > 0.0 ? std::ldexp(1.0, std::ilogb(largestCoordinate)) : 1.0;
  std::vector<ss::Vec3> points;
  for (const ss::Vec3& p : fit.KnotPoints)
  {
    points.push_back(p / unit);
  }
  const int spans = fit.Data.numberOfSpans();
  const auto segment = [&](int j) { return points[(j + 1) % points.size()] - points[j]; };
  double largest = 0.0;
  double shortestLocal = std::numeric_limits<double>::infinity();
  double farthest = 0.0; // coordinate size: the output's rounding scales with it
  for (int k = 0; k < samples.size(); ++k)
  {
    const int j = samples.Span[k];
    double local = 0.0;
    for (const int i : { j - 1, j, j + 1 })
    {
      if (fit.Data.Closed || (i >= 0 && i < spans))
      {
        local = std::max(local, segment(((i % spans) + spans) % spans).norm());
      }
    }
    const ss::Vec3 ab = segment(j);
    const ss::Vec3 x = samples.Values[k][0] / unit;
    const double along =
      ab.squaredNorm() > 0.0 ? std::clamp((x - points[j]).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    const double distance = (x - (points[j] + along * ab)).norm();
    largest = std::max(largest, local > 0.0 ? distance / local : distance);
    shortestLocal = std::min(shortestLocal, local > 0.0 ? local : 1.0);
    farthest = std::max(farthest, x.cwiseAbs().maxCoeff());
  }
  // The audit measures in the normalised frame; the samples are rounded in
  // data units, far from the origin by up to their coordinates' rounding. The
  // deviation is a distance over a local length, both off by that rounding:
  // where segments are 1e-12 of the coordinates, so is the deviation's error
  // relative (a 5.5e7 deviation differed by 186, 3.4e-6).
  const double rounding = 64 * DBL_EPSILON * farthest / shortestLocal;
  CHECK(std::abs(largest - audit.PolygonDeviation) <=
      1e-6 * std::max(1.0, largest) + rounding * (1.0 + largest),
    "deviation on the output samples %.17g, the audit's %.17g (rounding %.3g)", largest,
    audit.PolygonDeviation, rounding);
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const Input input = decode(data, size);
  if (verbose())
  {
    print(input);
  }
  const std::vector<ss::Vec3>& points = input.Points;
  const ss::FitOptions& options = input.Options;
  if (outsideExponentLimit(points))
  {
    return -1; // libFuzzer: do not add this input to the corpus
  }
  bool finite = true;
  // Refused: coordinates beyond ss::LargestCoordinate, and distinct points
  // spanning less than ss::SmallestExtent (measured as fitPolyline does).
  bool inRange = true;
  ss::Vec3 lo = ss::Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const ss::Vec3& p : points)
  {
    finite = finite && p.allFinite();
    inRange = inRange && !(p.cwiseAbs().maxCoeff() > ss::LargestCoordinate);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = (0.5 * hi - 0.5 * lo).cwiseAbs().maxCoeff() * 2.0;
  inRange = inRange && (points.empty() || lo == hi || extent >= ss::SmallestExtent);

  checkCleaning(points, options);

  const ss::CubicEndCondition ends = input.Ends;
  ss::CurveBuilder build = [ends](const ss::FitContext& context) {
    ss::BuiltCurve built;
    built.Spline = std::make_unique<ss::CubicSpline>(ss::CubicSpline::interpolate(
      context.Data.Points, context.Knots, context.Data.Closed, ends));
    return built;
  };
  if (input.Family == 1)
  {
    build = ss::qqrBuilder(ss::QQROptions{});
  }
  if (input.Family == 2)
  {
    ss::VariableDegreeOptions variable;
    const int choice = static_cast<int>(ends);
    const ss::VariableDegreeEnds variableEnds[] = { ss::VariableDegreeEnds::Polynomial,
      ss::VariableDegreeEnds::Clamped, ss::VariableDegreeEnds::Natural };
    variable.Ends = variableEnds[choice];
    variable.Automatic = choice != 2;
    variable.Degree = choice == 2 ? 40.0 : 5.0;
    build = ss::variableDegreeBuilder(variable);
  }
  if (input.Family == 3)
  {
    build = ss::tensionQuinticBuilder(ss::QuinticFitOptions{});
  }
  if (input.Family >= 4)
  {
    ss::GeneralizedCubicOptions generalized;
    const ss::SpaceKind kinds[] = { ss::SpaceKind::Exponential, ss::SpaceKind::Trigonometric,
      ss::SpaceKind::VariableDegree, ss::SpaceKind::Exponential };
    generalized.Kind = kinds[input.Family - 4];
    generalized.Automatic = input.Family != 7;
    generalized.Tension = input.Family == 7 ? 50.0 : 0.0;
    if (input.Family == 7)
    {
      generalized.Ends = ss::GeneralizedCubicEnds::Natural;
    }
    build = ss::generalizedCubicBuilder(generalized);
  }

  ss::FittedPolyline fit;
  try
  {
    fit = ss::fitPolyline(points, options, build);
  }
  catch (const std::invalid_argument& e)
  {
    CHECK(!finite || !inRange,
      "fitPolyline threw std::invalid_argument on finite input in range (%zu points): %s",
      points.size(), e.what());
    return 0;
  }
  catch (const std::domain_error& e)
  {
    // The quintic's documented refusal of knots its abscissae cannot follow.
    CHECK(input.Family == 3 && finite && inRange, "fitPolyline refused (family %d): %s",
      input.Family, e.what());
    return 0;
  }
  catch (const std::exception& e)
  {
    fuzzFail("fitPolyline threw an unexpected exception (%zu points, finite %d): %s", points.size(),
      static_cast<int>(finite), e.what());
  }
  catch (...)
  {
    fuzzFail("fitPolyline threw a non-standard exception");
  }
  CHECK(finite && inRange,
    "fitPolyline accepted non-finite or out-of-range input without std::invalid_argument");

  const int n = static_cast<int>(fit.Data.Points.size());
  if (!fit.Spline)
  {
    CHECK(n < 2, "no spline although the cleaned data has %d points", n);
    if (extraChecks())
    {
      extraChecksOn(points, fit, nullptr);
    }
    return 0;
  }
  const int spans = fit.Data.numberOfSpans();
  CHECK(fit.Spline->numberOfSpans() == spans, "spline has %d spans, data %d",
    fit.Spline->numberOfSpans(), spans);
  CHECK(static_cast<int>(fit.Knots.size()) == spans + 1, "%zu knots for %d spans",
    fit.Knots.size(), spans);
  CHECK(fit.KnotPoints.size() == fit.Data.Points.size(), "%zu knot points for %d data points",
    fit.KnotPoints.size(), n);
  CHECK(static_cast<int>(fit.Plan.PerSpan.size()) == spans, "plan has %zu spans, data %d",
    fit.Plan.PerSpan.size(), spans);
  checkAudit(fit.Audit, spans, "fit.Audit");

  ss::SampledCurve sampled;
  try
  {
    sampled = ss::sampleFit(fit);
  }
  catch (const std::exception& e)
  {
    fuzzFail("sampleFit threw: %s", e.what());
  }
  const ss::CurveSamples& samples = sampled.Samples;
  const int count = samples.size();
  CHECK(count == fit.Plan.size(), "%d samples, plan says %ld", count, fit.Plan.size());
  CHECK(sampled.Frames.size() == static_cast<size_t>(count), "%zu frames for %d samples",
    sampled.Frames.size(), count);
  CHECK(samples.Values.size() == static_cast<size_t>(count) &&
      samples.Span.size() == static_cast<size_t>(count) &&
      samples.ArcLength.size() == static_cast<size_t>(count),
    "sample arrays of different sizes");

  for (int k = 0; k < count; ++k)
  {
    const ss::Vec3& x = samples.Values[k][0];
    CHECK(x.allFinite(), "sample %d (span %d, t=%g): position (%g %g %g)", k, samples.Span[k],
      samples.Parameter[k], x.x(), x.y(), x.z());
    CHECK(samples.Span[k] >= 0 && samples.Span[k] < spans, "sample %d on span %d of %d", k,
      samples.Span[k], spans);
    checkFrame(sampled.Frames[k], k);
  }

  // The knot samples are the data points, exactly.
  long index = 0;
  for (int j = 0; j < spans; ++j)
  {
    CHECK(index < count, "knot %d has no sample", j);
    // Parameter is in data units; where the sample sits in its span is exact.
    CHECK(samples.Span[index] == j && samples.SpanFraction[index] == 0.0,
      "sample %ld should be knot %d but is span %d at fraction %.17g", index, j,
      samples.Span[index], samples.SpanFraction[index]);
    const ss::Vec3& x = samples.Values[index][0];
    const ss::Vec3& p = fit.KnotPoints[j];
    CHECK(x == p, "knot sample %ld (%.17g %.17g %.17g) is not data point %d (%.17g %.17g %.17g)",
      index, x.x(), x.y(), x.z(), j, p.x(), p.y(), p.z());
    index += fit.Plan.PerSpan[j];
  }
  if (!fit.Data.Closed)
  {
    CHECK(index == count - 1, "open curve: last knot sample %ld of %d", index, count);
    CHECK(samples.Values.back()[0] == fit.KnotPoints.back(), "last sample is not the last point");
  }
  else
  {
    CHECK(index == count, "closed curve: %ld samples planned, %d made", index, count);
  }

  checkDeviation(fit, samples, options);

  // The audit of the output samples, one sample at a time.
  std::vector<ss::AuditSample> auditSamples(count);
  for (int k = 0; k < count; ++k)
  {
    auditSamples[k].Span = samples.Span[k];
    auditSamples[k].Frame = sampled.Frames[k];
  }
  ss::markKnots(auditSamples, fit.Data.Closed);
  checkAudit(ss::auditShape(fit.Data, fit.Shape, auditSamples, options.Tolerances), spans,
    "auditShape");

  if (extraChecks())
  {
    extraChecksOn(points, fit, &sampled);
  }
  return 0;
}
