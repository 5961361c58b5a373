// ShapeSplines math core: the discrete shape of a polyline and the shape audit
// of a curve against it (Costantini & Manni (VDPS), section 4, Definition 1).
#ifndef shapesplines_ShapeAnalysis_h
#define shapesplines_ShapeAnalysis_h

#include "FrenetFrame.h"
#include "Parameterization.h"

#include <array>
#include <utility>
#include <vector>

namespace shapesplines
{
struct ShapeTolerances
{
  /// epsilon_1: |B_i| and the normalised triple product below this count as zero
  /// (collinear points, coplanar segments; the latter only where the planes
  /// at the segment's ends also turn by at most epsilon_2).
  double Data = 1e-6;
  /// epsilon_2: allowed sine of the angle between the curve's tangent (binormal)
  /// and the data's segment (binormal); and how far a scale-free signed curvature
  /// K.B_i * diagonal or torsion tau * Delta_i-sign * diagonal may fall below zero.
  double Curve = 1e-3;
};

/**
 * Discrete shape of the data polygon I_0..I_m (closed lines wrap around).
 * Per point: binormal B_i, Menger curvature, collinearity flag. Per segment
 * L_i = I_{i+1} - I_i: the signed discrete torsion Delta_i and a coplanarity flag.
 * Entries that the definition leaves undefined (ends of open lines) are zero.
 */
struct DiscreteShape
{
  std::vector<Vec3> Binormal;
  std::vector<double> Curvature;
  std::vector<char> Collinear; ///< criterion (i) applies at this point
  std::vector<char> Convex;    ///< B_i != 0: criterion (ii.1) applies
  /// The line runs straight back at this point (its segments opposite, B_i
  /// = 0 within tolerance): a smooth curve through it stops there and turns
  /// (a cusp), whatever the family; no criterion applies. Streamlines
  /// oscillating about a critical point and retraced paths have them.
  std::vector<char> Reversal;
  /// Per segment (0, and neither Coplanar nor Twisted, where an end point is
  /// straight, B_i = 0: no plane there, the span is (i)'s).
  std::vector<double> Torsion;
  /// Per segment: criterion (iii) applies (not where TorsionCrossing).
  std::vector<char> Coplanar;
  std::vector<char> Twisted;   ///< per segment: Delta_i != 0, criterion (iv.2) applies
  /// Per segment: the torsion changes sign near it (the segments on either
  /// side twist opposite ways, and its own Delta_i is 0, or under a third of
  /// the other sign's or of the largest of its own sign within two segments on
  /// its side): no criterion on it, and the curve's torsion may change sign
  /// once from either of its knots on the segments next to it.
  std::vector<char> TorsionCrossing;
};

/**
 * The step each coordinate (x, y, z) of points was written with, to within
 * precision, their relative rounding (12.345 read as a float has three
 * decimals). Text formats round coordinates, to a fixed number of decimals
 * (PDB files to 1e-3 angstrom, "%.3f") or of significant digits ("%.5e",
 * ParaView's CSV export; "%g"), and a turn or twist within that rounding is
 * no shape to keep. For decimals, 10^-d for the fewest digits d >= 2 after
 * the decimal point every value has; for significant digits, the step of
 * the largest values at the fewest digits (>= 3) every value has; of two
 * ways that fit, the one more values use all digits of (equally: the
 * finer). 0 for a coordinate whose values need more digits than their type
 * holds, or none (integers, tenths: designed values, taken as exact), or
 * keeps one value along the line (a z-level). The
 * filters read each line's points: a line is one rank's in a distributed
 * run, and files that mix formats keep each line's.
 */
Vec3 coordinateSteps(const std::vector<Vec3>& points, double precision);

/**
 * The discrete shape of data. vertexNoise, one per point (the reference
 * polygon of an approximation, whose vertices move by about that much with
 * the noise of the points; empty: none): a turn or a twist counts only where
 * it stands out of what that noise can make, NoiseSignificance times the
 * change it causes in the turning sine (a segment's direction turns by its
 * vertices' noise over its length) or in the normalised triple product;
 * below (but above tolerances.Data), the point is neither convex nor
 * collinear, the segment neither twisted nor coplanar: no criterion applies
 * there. coordinateNoise, the rounding of the input coordinates in the
 * data's units (FitContext::CoordinateNoise), is every vertex's least noise:
 * float coordinates leave a segment of 1e-4 of the diagonal a direction
 * known to about 0.1, and a turn or twist within that is no shape to keep.
 * roundingSteps, the steps the coordinates were written with in the data's
 * units (see coordinateSteps; FitContext::RoundingSteps), move each point by
 * up to half of them on each axis: a bound, not a spread. A turn or twist counts only
 * beyond the most that rounding can make of it (a straight run or a plane given to three decimals turns and
 * twists by their rounding, either way, and keeping those signs bent the
 * curve), while the small turns of data given to a few decimals above that
 * (the titanium data's flat stretches) still count.
 */
DiscreteShape discreteShape(const CleanPolyline& data, const ShapeTolerances& tolerances = {},
  const std::vector<double>& vertexNoise = {}, double coordinateNoise = 0.0,
  const Vec3& roundingSteps = Vec3::Zero());

/// How far a curve may stray from its reference polygon: a fraction of the
/// longest of the segment and its neighbours (see ShapeAudit::PolygonDeviation).
constexpr double MaximumPolygonDeviation = 0.5;

/// How many times the change noise can cause a turn or twist must exceed to count.
constexpr double NoiseSignificance = 3.0;

enum class ShapeCriterion : int
{
  Collinearity = 0,   ///< (i)
  ConvexityAtKnot,    ///< (ii.1)
  ConvexityOnSpan,    ///< (ii.2)
  Coplanarity,        ///< (iii)
  TorsionSignAtKnot,  ///< (iv.1)
  TorsionSignOnSpan,  ///< (iv.2)
  Count
};
const char* shapeCriterionName(ShapeCriterion criterion);

/// The criterion's bit in ShapeAudit::SpanMask.
constexpr unsigned criterionBit(ShapeCriterion criterion)
{
  return 1u << static_cast<int>(criterion);
}

/// What the audit needs of one curve sample.
struct AuditSample
{
  int Span = 0;
  int Knot = -1; ///< index of the data point this sample sits on, or -1
  FrenetFrame Frame;
  /// The curvature is within rounding of zero: the frame's normal and
  /// binormal are only carried over (frenetFrames), so the sample has no
  /// sign of curvature or torsion to check.
  bool Flat = false;
};

/// Marks the knots of samples ordered along a curve: the first sample of each
/// span, and the last sample of an open curve.
void markKnots(std::vector<AuditSample>& samples, bool closed);

/// One failure of Definition 1: a criterion at a knot (knot criteria) or on a span.
struct ShapeFailure
{
  ShapeCriterion Criterion = ShapeCriterion::Collinearity;
  int Where = 0; ///< the knot or span it is counted at
};

struct ShapeAudit
{
  /// Per span: bit c set if criterion c fails on the span or at one of its knots.
  std::vector<unsigned> SpanMask;
  /// Per span: how far its failing samples are beyond the tolerances (summed,
  /// scale-free), 0 where it passes: progress an automatic mode can measure
  /// before a violation disappears.
  std::vector<double> SpanDeficiency;
  /// Distinct failures per criterion (a knot or a span counts once).
  std::array<int, static_cast<int>(ShapeCriterion::Count)> Failures{};
  /// Every distinct failure, ordered by criterion, then knot or span.
  std::vector<ShapeFailure> Where;
  /// The largest distance of the curve from its segment of the reference
  /// polygon, over the longest of that segment and its neighbours, and the
  /// span where it is (-1: not measured); spans beyond
  /// MaximumPolygonDeviation count as violations (a curve through the points,
  /// or near its polygon, has no business away from them).
  double PolygonDeviation = 0.0;
  int DeviationSpan = -1;
  int StrayingSpans = 0;

  /// Failures of Definition 1 and straying spans.
  int violations() const;
  bool preserving() const { return this->violations() == 0; }
};

/**
 * Audits a curve, given one sample at a time (spans in any order, the samples
 * of a span in order along it), against the discrete shape of its data:
 * which criteria of Definition 1 fail on which span. Sign conditions fail only when the signed value, made scale-free
 * with the data's bounding-box diagonal, drops below -tolerances.Curve: a
 * vanishing value is not a sign change; likewise only samples whose
 * scale-free curvature exceeds tolerances.Curve have an osculating plane, and
 * a torsion, to check. Where the data's torsion changes sign at a knot, a
 * curve whose torsion is continuous (C3 and smoother) must pass through zero,
 * and (iv) would ask it to do so exactly at the knot: there the torsion may
 * change sign once anywhere on the two spans around the knot (the samples of
 * the wrong sign must run from the knot), as (ii.2) lets the curvature change
 * sign on a span whose ends turn opposite ways; likewise at an open line's
 * knot next to an end, whose end span has no discrete torsion to say whether
 * it reverses there. Within two spans of a knot where the data's torsion
 * reverses once (no other change among the five twisted segments on either
 * side), a torsion of the wrong sign counts only beyond half the largest step
 * of the discrete torsion between neighbouring segments there: the error of
 * both the data's torsion and a converging curve's near its zero on uneven
 * spacing. What a sample finds is kept with its span, so that the samples of
 * one span can be audited again (forget(), then add()) after the curve
 * changed there. The data and shape must outlive the auditor.
 */
class ShapeAuditor
{
public:
  ShapeAuditor(const CleanPolyline& data, const DiscreteShape& shape, const ShapeTolerances& tolerances);
  void add(const AuditSample& sample);
  /// Drops what the samples of span j found.
  void forget(int span);
  ShapeAudit result() const;

private:
  /// A failure found by the samples of one span: the spans it marks, how far beyond tolerance.
  struct Finding
  {
    ShapeFailure Failure;
    int Spans[2];
    double Deficiency;
  };
  void fail(const AuditSample& sample, ShapeCriterion criterion, int where, int spanA, int spanB,
    double deficiency);
  double signedCurvature(const FrenetFrame& frame, int point) const;
  /// Whether the data's torsion changes sign at knot i (both segments
  /// twisted), or may (an open line's knot next to an end, its inner span twisted).
  bool twistReversesAt(int i) const;
  /// TwistTolerance's values (after Scale and TwistReverses).
  std::vector<double> twistTolerances() const;
  /// A span next to such a knot: the torsion's failure beyond the one sign change allowed.
  double transitionDeficiency(int span) const;

  const CleanPolyline& Data;
  const DiscreteShape& Shape;
  ShapeTolerances Tolerances;
  double Scale = 1.0;
  /// Per point, the data's unit binormal; per knot, twistReversesAt: every
  /// sample reads them.
  std::vector<Vec3> UnitBinormal;
  std::vector<char> TwistReverses;
  /// Per span: how far its torsion may fall below zero (scale-free) before
  /// it counts as the wrong sign: tolerances.Curve, more near a reversal.
  std::vector<double> TwistTolerance;
  std::vector<std::vector<Finding>> Findings; ///< per span whose samples found them
  /// Per span next to a knot where the data's torsion changes sign: each
  /// inside sample's wrong-sign torsion beyond tolerance (0: right sign), in order.
  std::vector<std::vector<double>> TransitionTwist;
};

/// The audit of a whole sequence of samples.
ShapeAudit auditShape(const CleanPolyline& data, const DiscreteShape& shape,
  const std::vector<AuditSample>& samples, const ShapeTolerances& tolerances = {});
} // namespace shapesplines

#endif
