// ShapeSplines math core: the path from raw polyline points to a sampled,
// framed and audited curve, shared by every spline family.
#ifndef shapesplines_FitPolyline_h
#define shapesplines_FitPolyline_h

#include "Curve.h"
#include "FrenetFrame.h"
#include "Parameterization.h"
#include "Sampler.h"
#include "ShapeAnalysis.h"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace shapesplines
{
struct FitOptions
{
  Parameterization Knots = Parameterization::ChordLength;
  bool Closed = false; ///< close the line even if its last point is not its first
  SamplingOptions Sampling;
  ShapeTolerances Tolerances;
  /// Samples per span of the shape audit, independent of the output sampling.
  int AuditSubdivisions = 16;
  /// Relative precision of the input coordinates (FLT_EPSILON for float input):
  /// curvature within their rounding counts as zero.
  double CoordinatePrecision = 2.220446049250313e-16;
  /// Progress of the shape audits of one line (see ProgressCallback); none by default.
  ProgressCallback Progress;
};

/**
 * What a family's builder gets: the cleaned data in the normalised frame (at
 * least three points), its knots (one per point, plus the closing knot of a
 * closed line), the options and the rounding of the coordinates.
 */
struct FitContext
{
  const CleanPolyline& Data;
  const std::vector<double>& Knots;
  const FitOptions& Options;
  double CoordinateNoise = 0.0;
  /// A user's value per cleaned point (e.g. a starting tension), or empty.
  const std::vector<double>& PointValues;
  /// The steps the line's coordinates were written with (coordinateSteps),
  /// normalised: a turn or twist that rounding can make is no shape.
  Vec3 RoundingSteps = Vec3::Zero();

  /// The audit of a curve against the Definition 1 shape of reference, a
  /// polygon with one vertex per knot of the curve: the data for an
  /// interpolation, the least-squares polygon for an approximation (whose
  /// vertices move by referenceNoise, one per vertex, with the noise, see
  /// discreteShape).
  ShapeAudit audit(const Curve& curve, const CleanPolyline& reference,
    const std::vector<double>& referenceNoise = {}) const;
};

/**
 * A context that reports its progress to [from, to] of another's: for a
 * builder that runs several searches on one line, so that the line's
 * progress moves on from one to the next rather than each counting from 0.
 */
class ProgressPart
{
public:
  ProgressPart(const FitContext& whole, double from, double to);
  ProgressPart(const ProgressPart&) = delete;
  ProgressPart& operator=(const ProgressPart&) = delete;
  const FitContext& context() const { return this->Context; }

private:
  FitOptions Options;
  FitContext Context; ///< refers to Options
};

/// A family's curve and, for an approximation, the polygon whose shape it keeps.
struct BuiltCurve
{
  std::unique_ptr<Curve> Spline;
  /// Approximations only: the polygon (normalised frame, one vertex per knot
  /// of Spline) whose discrete shape the curve keeps, e.g. L* of Cravero, Manni & Sampoli or
  /// psi of Costantini & Manni (VDPS). Empty for an interpolation: its reference is the data.
  std::optional<CleanPolyline> ShapeReference;
  /// The audit of Spline against its reference, when the builder has made it.
  std::optional<ShapeAudit> Audit;
  /// Approximations: the parameter of each data point on the curve, when the
  /// builder corrected the given ones (planApproximation).
  std::optional<std::vector<double>> DataParameters;
  /// Approximations: the points' root-mean-square distance from the curve
  /// (normalised frame), and per vertex of ShapeReference how far it can
  /// move with that noise (see discreteShape).
  double NoiseLevel = 0.0;
  std::vector<double> ReferenceNoise;
  /// Approximations: a span of the knots holds too few points to decide it
  /// (ApproximationPlan::StarvedSpan): NoiseLevel is not estimated.
  bool StarvedSpan = false;
};

using CurveBuilder = std::function<BuiltCurve(const FitContext& context)>;

/**
 * A family's curve through one polyline, audited, with its sampling planned
 * but not done: a FitSampler samples it when its output is written, so that
 * no more than a block of samples per thread is ever held.
 */
struct FittedPolyline
{
  /// The cleaned points in a normalised frame, (p - Origin) / Scale: centred on
  /// their bounding box and of unit extent. The spline is fitted there, so
  /// rounding scales with the line's size, not with its distance from the
  /// coordinate origin, and no coordinate size (1e-160 or 1e160) over- or
  /// underflows. sampleFit() returns data units.
  CleanPolyline Data;
  Vec3 Origin = Vec3::Zero();
  double Scale = 1.0;           ///< largest extent of the bounding box
  double ParameterScale = 1.0;  ///< data-unit parameter per normalised parameter
  std::vector<Vec3> KnotPoints; ///< the cleaned points in input coordinates
  double CoordinateNoise = 0.0; ///< rounding of the input coordinates, normalised
  Vec3 RoundingSteps = Vec3::Zero(); ///< their written digits' steps, normalised (see FitContext)
  /// Normalised parameter of each cleaned point (for an approximation, where
  /// it sits on the curve: corrected, see planApproximation).
  std::vector<double> Knots;
  std::unique_ptr<Curve> Spline; ///< null when the data has fewer than two distinct points
  /// Approximations: the polygon whose shape the curve keeps (see BuiltCurve).
  std::optional<CleanPolyline> ShapeReference;
  DiscreteShape Shape; ///< of the reference: the data, or ShapeReference
  ShapeAudit Audit;    ///< against that shape
  /// Approximations: the points' root-mean-square distance from the curve, data units.
  double NoiseLevel = 0.0;
  /// Approximations: a span of the knots holds too few points to decide it (BuiltCurve::StarvedSpan).
  bool StarvedSpan = false;
  /// Interpolations: the points look noisy to a least squares (looksNoisy)
  /// and fewer than half sit on exactly straight runs (designed points):
  /// the curve's curvature and torsion follow the noise.
  bool LooksNoisy = false;
  SamplingPlan Plan;

  /// Whether the curve passes through the data at its knots.
  bool interpolates() const { return !this->ShapeReference; }
};

/// A fitted curve's samples and their Frenet frames, in data units (positions,
/// parameter, arc length, curvature, torsion); derivatives stay normalised.
struct SampledCurve
{
  CurveSamples Samples;
  std::vector<FrenetFrame> Frames;
};

/**
 * Samples a fitted curve as planned, a block of at most blockSamples samples
 * at a time, into Block: a long curve's samples are never all held. The
 * blocks come in order along the curve and hold what sampleFit() gives,
 * whatever their size: the arc length and the frames' transport run on from
 * block to block. A sample's curvature is flat (its Frenet normal and torsion
 * undefined) at or below 1e-10 of the inverse bounding-box diagonal, or what
 * the data's rounding can cause: an acceleration across the tangent of
 * 32 noise / dt^2 on a span of parameter length dt, that is a curvature of
 * 32 noise / (dt |s'|)^2. The fit must have a Spline and outlive the sampler.
 */
class FitSampler
{
public:
  FitSampler(const FittedPolyline& fit, long blockSamples);

  /// Samples the next block into Block; false when the curve is done.
  bool next(const ProgressCallback& progress = {});

  /// The block last sampled; Block.Samples.First is where it starts on the curve.
  SampledCurve Block;

private:
  /// Frames block's samples, with what it needs of the blocks around it.
  void frame(SampledCurve& block, const FrameNeighbours& neighbours);
  /// The neighbours of block b in the order the blocks come.
  FrameNeighbours neighbours(long b) const;
  /// When block 0 has no normal: the first block that has one, and from it
  /// back, the normal each block before it takes its samples' normals from.
  void findLeadingNormals(const ProgressCallback& progress);
  void sampleBlock(SampledCurve& block, long b, const ProgressCallback& progress) const;

  const FittedPolyline& Fit;
  BlockSampler Sampler;
  long BlockSamples;
  long Blocks;
  long Next = 0;
  double Diagonal;
  std::vector<double> Thresholds; ///< of the block last framed
  Vec3 LastTangent, LastNormal;   ///< of the block last given
  long FirstDefinedBlock = 0;     ///< the blocks before it have no normal of their own
  std::vector<Vec3> NextNormals;  ///< per block before it: the first normal after the block
};

/// What a CurveAuditor measures besides the audit and each span's distance
/// from the reference: nothing (a fixed curve's audit); the figures an
/// automatic mode's bounds read (largestCurvature, lowestSpeed), looked for
/// between the samples too; and with them every sample's curvature
/// (sampleCurvatures), which only a bound on the change of curvature needs.
enum class AuditFigures
{
  None,
  Bounds,
  BoundsAndSampleCurvatures
};

/**
 * The shape audit of a curve against its reference polygon, kept span by
 * span: an automatic mode audits the whole curve once, then again only the
 * spans a change can move. Each span is sampled uniformly (subdivisions + 1
 * samples, both knots included); besides its findings it keeps the span's
 * largest distance from the reference polygon and, asked for (figures), its
 * largest curvature and its lowest speed relative to its chord, the bounds
 * an automatic mode must not cross. The reference and shape must outlive it.
 */
class CurveAuditor
{
public:
  CurveAuditor(const CleanPolyline& reference, const DiscreteShape& shape,
    const ShapeTolerances& tolerances, int subdivisions, double coordinateNoise,
    AuditFigures figures = AuditFigures::None);

  /// (Re-)audits span j of curve, forgetting what the span's samples found before.
  void audit(const Curve& curve, int span);
  void auditAll(const Curve& curve, const ProgressCallback& progress = {});
  /// Forgets what span j's samples found, as if it had none: no findings,
  /// curvature 0, speed 1, deviation 0 (sample curvatures, when kept, stay).
  void forget(int span);
  /// The audit, straying spans (beyond MaximumPolygonDeviation) included.
  ShapeAudit result() const;

  /// Largest curvature on span j's samples (the curve's units), at the
  /// bottom of a dip in its speed, where a near-cusp's spike can hide between
  /// them, and between samples that turn the tangent more than their
  /// curvature explains (a tension's boundary layer at a knot).
  double largestCurvature(int span) const { return this->Curvature[span]; }
  /// Lowest |s'| on span j's samples (and dip) over its chord speed |s(t_j+1) - s(t_j)| / h_j.
  double lowestSpeed(int span) const { return this->Speed[span]; }
  /// Largest distance of span j's samples from the reference's segment j,
  /// over the longest of that segment and its neighbours.
  double largestDeviation(int span) const { return this->Deviation[span]; }
  /// The curvature at span j's samples, from its start to its end (when kept).
  const std::vector<double>& sampleCurvatures(int span) const { return this->SampleCurvatures[span]; }

private:
  ShapeAuditor Auditor;
  int Subdivisions;
  double CoordinateNoise;
  double Diagonal;
  const CleanPolyline& Reference;
  bool BoundFigures;
  std::vector<double> Curvature;
  std::vector<double> Speed;
  std::vector<double> Deviation;
  std::vector<double> LocalLength;
  std::vector<std::vector<double>> SampleCurvatures; ///< per span, when kept
  // One span's samples, thresholds and frames, reused from span to span.
  std::vector<Derivatives> Values;
  std::vector<double> Speeds;
  std::vector<double> Thresholds;
  std::vector<FrenetFrame> Frames;
};

/// Audits a curve through data on a uniform sampling.
ShapeAudit auditCurve(const Curve& curve, const CleanPolyline& data, const DiscreteShape& shape,
  const ShapeTolerances& tolerances, int subdivisions, double coordinateNoise,
  const ProgressCallback& progress = {});

/// An approximation's knot count chosen from the data (planApproximation in
/// Approximation.h).
constexpr int CrossValidatedKnots = -1;

/// Coordinates beyond this are refused: a curve through them (its overshoot,
/// its arc length) can leave the double range.
constexpr double LargestCoordinate = 1e300;

/// Arc-length sampling takes at most the samples this many times the
/// polyline's length would: a curve longer than that has left its data (its
/// audit says so), and sampling it all would take minutes for nothing.
constexpr double RunawayLengthFactor = 100.0;

/// A curvature this many times over the line's bounding box diagonal is a
/// cusp or a kink, not the data's shape (a circle through the box has about
/// 2): the filters warn about it, and no automatic mode raises one past it.
constexpr double CuspCurvature = 1e6;

/// Lines whose distinct points span less than this are refused: in the
/// subnormal range their differences lose every digit.
constexpr double SmallestExtent = 1e-300;

/**
 * Cleans the points, computes knots, builds the curve (two distinct points
 * give the straight segment whatever the family), audits its shape and plans
 * its sampling. pointValues, one per input point or none, reach the builder
 * as FitContext::PointValues, one per cleaned point. Throws std::invalid_argument for non-finite points,
 * coordinates beyond LargestCoordinate and distinct points within SmallestExtent.
 */
FittedPolyline fitPolyline(const std::vector<Vec3>& points, const FitOptions& options,
  const CurveBuilder& build, const std::vector<double>& pointValues = {});

/**
 * Samples a fitted curve as planned, with Frenet frames, curvature and torsion
 * from its exact derivatives; the knot samples of an interpolation are the
 * data points, exactly. Written once for every family: one FitSampler block.
 * The fit must have a Spline.
 */
SampledCurve sampleFit(const FittedPolyline& fit, const ProgressCallback& progress = {});
} // namespace shapesplines

#endif
