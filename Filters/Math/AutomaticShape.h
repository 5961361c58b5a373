// ShapeSplines math core: the automatic shape mode, written once for every
// family: raise a shape parameter (tension, degree, exponent) span by span
// where the curve breaks the shape of its reference, within bounds that keep
// the curve regular.
#ifndef shapesplines_AutomaticShape_h
#define shapesplines_AutomaticShape_h

#include "FitPolyline.h"

#include <functional>
#include <memory>
#include <vector>

namespace shapesplines
{
/**
 * What no automatic mode may make of a curve, however many violations are
 * left: a curvature beyond CurvatureFactor times the reference polygon's
 * largest discrete (Menger) curvature (StraightRunCurvatureFactor when the
 * reference has collinear points: a straight run joined to a turn needs a
 * sharp bend) or beyond CuspCurvature over the reference's bounding box
 * diagonal, a speed |s'| below SpeedFraction of a span's chord over its
 * parameter length (a curve that nearly stops makes a cusp), or a span
 * farther from its segment of the reference polygon than Deviation times
 * the longest of that segment and its neighbours (a curve through the
 * points, or near its polygon, has no business away from them); nor,
 * approximating, a curvature far from the fixed parameters' (CurvatureChange).
 */
struct ShapeBounds
{
  double CurvatureFactor = 1e3;
  double StraightRunCurvatureFactor = 1e4;
  double SpeedFraction = 1e-3;
  double Deviation = MaximumPolygonDeviation;
  /// Approximations (0: none): the curvature at every sample stays within
  /// this factor of the level-0 curve's, wherever that stands above what the
  /// reference's noise can bend (NoiseSignificance times the curvature of an
  /// arc whose sagitta over the span's segment is the larger
  /// ShapeLadder::ReferenceNoise of its vertices), and below this factor
  /// times that noise's curvature where the level-0 curve's is lower:
  /// keeping a noisy polygon's shape must neither flatten nor kink the curve.
  double CurvatureChange = 0.0;
};

/**
 * A family's automatic shape parameter as a level per span: level 0 is the
 * curve of the fixed parameters, each level up is one step tighter (a higher
 * tension or degree), TopLevel the family's cap. Families whose parameter
 * sits at the knots take, at each knot, the higher level of its two spans
 * (knotLevels).
 */
struct ShapeLadder
{
  int TopLevel = 0;
  /// The curve with level levels[j] on span j.
  std::function<std::unique_ptr<Curve>(const std::vector<int>& levels)> Build;
  /// How many spans on each side of a span its level visibly moves.
  int Reach = 2;
  /// Every span at one level (a global scheme): any failure raises them all.
  bool Uniform = false;
  /// A span whose torsion sign fails on it raises its neighbours with it
  /// (the solve spreads a third derivative over them; see
  /// searchShape). Off where neighbouring raises undo each
  /// other (qqr's flattening).
  bool RaiseTwistNeighbours = true;
  /// The criteria the ladder is meant to mend (criterionBit): the spans where
  /// the level-0 curve fails any other stay at level 0 and do not raise
  /// their neighbours.
  unsigned Mends = ~0u;
  /// Where the search leaves violations, search again raising only the
  /// failing spans (a twisting span's neighbours not with it) and keep the
  /// better curve. The variable degree interpolation's random 3D polylines
  /// lose their last violations that way; the quintic and qqr gained few or
  /// none for 1.3-2x the cost.
  bool RetrySpanBySpan = false;
  /// Where the search leaves violations, search again from the common level
  /// of every span with the fewest violations within the bounds (or from
  /// each window around what is left failing at its own best level), and
  /// keep the better curve: on very uneven knots (the aorta's) a span raised
  /// alone meets the bounds long before the level that mends it. For
  /// interpolations (it ignores CurvatureChange).
  bool RetryFromCommonLevel = false;
  /// Where the searches leave violations, try each span near one left
  /// failing alone at a few other levels and keep what lowers the violations
  /// within the bounds (see improveShape; a Uniform ladder is not refined).
  bool Refine = true;
  /// Refining tries a span back at level 0 too. qqr's searches straighten
  /// whole neighbourhoods and overshoot: 448 of the 2748 violations its
  /// refining mended on a set of users' data came from level 0. A tension or
  /// degree ladder's level 0 is the fixed curve's parameter, which failed
  /// there: none of the generalized cubic's and variable degree spline's
  /// and 15 of the quintic's 621 came from it, for a fifth of the trials.
  bool RefineBackToLevelZero = true;
  int MaxRounds = 64;
  ShapeBounds Bounds;
  /// Per vertex of the reference polygon, how far it moves with the noise
  /// (see discreteShape): empty for an interpolation's data.
  std::vector<double> ReferenceNoise;
};

/**
 * How many spans on each side of one the first search left failing a retry
 * (ShapeLadder::RetrySpanBySpan, RetryFromCommonLevel) searches again; the
 * other spans keep the first search's levels. A retry of the whole line cost
 * a 1e5-point noisy helix's variable degree spline 45 and 25 more rounds of
 * whole-line solves for nothing (9 violations left by the first search;
 * the retries in windows leave none, in two thirds of the time).
 */
constexpr int RetryReach = 32;

/// How many spans on each side of one left failing refining tries (see
/// improveShape), how many times over, and its cost: at most
/// RefineTrialsPerSpan builds a span of the line, and at most
/// RefinePointBuilds points built in all (each build solves the whole line:
/// a line of 1e4 points is hardly refined, one of 50 up to 98 builds).
constexpr int RefineReach = 2;
constexpr int RefinePasses = 2;
constexpr long RefineTrialsPerSpan = 2;
constexpr long RefinePointBuilds = 1L << 15;

/// The automatic mode's curve, its audit against the reference and the levels chosen.
struct AutomaticShape
{
  std::unique_ptr<Curve> Spline;
  ShapeAudit Audit;
  std::vector<int> Levels;
  int Rounds = 0;
};

/**
 * The automatic mode's first search: builds level 0 and audits it against
 * reference (the spans where it fails a criterion outside ShapeLadder::Mends
 * are left alone); then, round by round, raises each failing span (a span
 * already at the top, or frozen, raises its neighbours instead; a span whose
 * torsion changes sign on it raises its neighbours with it,
 * ShapeLadder::RaiseTwistNeighbours) by a step that doubles while it keeps
 * failing, rebuilds, and audits again only the spans within Reach of a
 * change. A raise that pushes a span beyond the bounds (and beyond where it
 * was) is undone, tried again as a single step, and then that span's level
 * frozen (the curve after the undo is checked again: a global solve moves
 * with every level); a span whose level three times in a row does
 * not bring it closer to passing (fewer failures, or a tenth less
 * ShapeAudit::SpanDeficiency) is frozen too. Stops when nothing fails, nothing
 * can rise, or eight rounds in a row meet no curve with fewer violations than
 * the best; a last audit of the whole curve catches the far effects of a global
 * solve (then it goes on), and so does one of the best curve met where the
 * rounds ended on another (then it goes on from the best, once). Returns the
 * best curve met: the fewest violations, among those within the bounds; the
 * fixed parameters' curve where the levels met are singular.
 * Progress is reported each round (it can abort), over the first half of
 * the line's fraction (refining, improveShape, reports the second).
 */
AutomaticShape searchShape(
  const FitContext& context, const CleanPolyline& reference, const ShapeLadder& ladder);

/**
 * What the ladder does where a first search (searchShape) left violations:
 * a second search, ShapeLadder::RetrySpanBySpan, or a third,
 * ShapeLadder::RetryFromCommonLevel, both only within RetryReach of the
 * spans left failing and kept if they leave fewer; then refining
 * (ShapeLadder::Refine): each span within RefineReach of one left failing
 * (the worst failing first, each followed by its neighbours nearest first:
 * an order the line's direction does not change; a span is passed over
 * once a trial kept has mended every span that near it, and when every
 * level of it was tried since the last trial kept) is tried alone at
 * levels 0 and 1 and at a quarter, half and all of the top, rebuilt and
 * audited around it (first the spans failing before, and only if those
 * lose failures, the rest), and the change kept where it lowers the
 * violations within the bounds; the refined curve, audited whole, is kept
 * if it has fewer. The searches raise a neighbourhood together, overshoot,
 * and freeze a span whose raise stalls: on 100 random 3D polylines of 60
 * points refining takes the generalized cubic from 17 violations left to
 * 5, the variable degree spline from 7 to 0, the quintic from 84 to 42 and
 * qqr from 94 to 32, mostly by lowering a span to level 0 or 1 (or
 * flattening one more of qqr's knots). Never returns more violations than
 * found has.
 */
AutomaticShape improveShape(AutomaticShape found, const FitContext& context,
  const CleanPolyline& reference, const ShapeLadder& ladder);

/// The automatic mode: searchShape, then improveShape.
AutomaticShape preserveShapeAutomatically(
  const FitContext& context, const CleanPolyline& reference, const ShapeLadder& ladder);

/// A found shape as a family's builder returns it: its curve and its audit.
BuiltCurve builtCurve(AutomaticShape found);

/**
 * What a family's builder returns: the ladder's level 0 as it is (automatic
 * false), or preserveShapeAutomatically()'s curve with its audit.
 */
BuiltCurve fixedOrAutomatic(bool automatic, const FitContext& context,
  const CleanPolyline& reference, const ShapeLadder& ladder);

/// Per knot (one per point; closed curves: one per distinct point), the higher level of its spans.
std::vector<int> knotLevels(const std::vector<int>& spanLevels, bool closed);

/// The shape parameter after a given number of steps: start raised level times
/// by raise() (which caps it), stopping early where it stops moving.
double raisedTimes(double start, int level, const std::function<double(double)>& raise);

/// The number of steps raise() takes from start until it stops moving (at most 64).
int stepsToCap(double start, const std::function<double(double)>& raise);
} // namespace shapesplines

#endif
