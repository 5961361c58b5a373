// ShapeSplines math core: what the approximating families share: the
// classical quintic least squares on uniform knots, the knot count by
// cross-validation, the parameters corrected towards the curve, the
// least-squares polygon of reference.
#ifndef shapesplines_Approximation_h
#define shapesplines_Approximation_h

#include "Curve.h"
#include "FitPolyline.h" // CrossValidatedKnots
#include "Sampler.h"   // FitAborted

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace shapesplines
{
/// count >= 2 knots spread uniformly over the data parameters u, ending
/// exactly at u's ends: the knots of the least-squares approximations.
std::vector<double> uniformKnots(const std::vector<double>& u, int count);

/**
 * The classical quintic spline (C4; tension 1 in both approximating
 * families' spaces) on the given knots (open: clamped, spans + 5 B-splines;
 * closed: periodic, the last knot closing), closest in least squares to
 * points at parameters u (within the knots): banded normal equations, O(N).
 */
class QuinticFit
{
public:
  static constexpr int Degree = 5;

  /// The fit, or nothing when a span holds no point or the normal equations
  /// are singular (a span decided by its neighbours' points alone).
  static std::optional<QuinticFit> solve(const std::vector<Vec3>& points,
    const std::vector<double>& u, const std::vector<double>& knots, bool closed);

  /// Position and its first two derivatives at u.
  std::array<Vec3, 3> evaluate(double u) const;
  /// The parameter of the fit's point nearest p, by Newton steps from u,
  /// kept within the knots.
  double nearest(const Vec3& p, double u) const;
  /// Sum of the squared distances from the points to the fit at u.
  double residual(const std::vector<Vec3>& points, const std::vector<double>& u) const;

private:
  QuinticFit(const std::vector<double>& knots, bool closed);
  int unknown(int j) const;
  int locate(double u) const;
  /// The six B-splines nonzero on a span (coefficients span..span + 5) and
  /// their first two derivatives at u.
  std::array<std::array<double, Degree + 1>, 3> basis(int span, double u) const;

  int Spans;
  bool Closed;
  double First, Last;
  std::vector<double> T; ///< the full knot vector, Degree more at each end
  Eigen::MatrixX3d Coefficients;
};

/**
 * The data an approximation with knotCount knots is fitted to. Open lines:
 * the points with the two next to each end mirrored through it (p_-k =
 * 2 p_0 - p_k, parameters likewise), and knotCount uniform knots over the
 * points' parameters with one more at each end, where the mirrored points
 * end (Extra = 1 span beyond each end). A least squares has no condition at its ends: its end
 * spans follow the last few points wherever their noise goes, into a hook
 * (on the shipped aorta centerline, curvature 16 where the vessel's is
 * below 1); the mirrored points make the ends continue the curve instead
 * (an odd continuation, whose second derivative at the end is about zero).
 * The fit's stretch between the data's ends is kept (TrimmedCurve). Closed
 * lines have no ends: the points, and knotCount distinct uniform knots.
 */
struct ExtendedData
{
  std::vector<Vec3> Points;
  std::vector<double> Parameters;
  std::vector<double> Knots;
  int Extra = 0;
};

ExtendedData extendForApproximation(const std::vector<Vec3>& points,
  const std::vector<double>& u, int knotCount, bool closed);

/// Per span of an approximation on extended knots (ExtendedData), the level
/// of the data's span it continues: levels beyond an end take the end's.
std::vector<int> extendedLevels(const std::vector<int>& levels, int extra);

/// What an approximation of noisy points rests on (planApproximation).
struct ApproximationPlan
{
  /// Per point: its parameter, the given one or corrected towards the curve
  /// (each point where it projects on the fit, an open line's ends too; the
  /// points' order kept).
  std::vector<double> Parameters;
  int Knots = 0; ///< the knot count (distinct knots of a closed line)
  /// The points' root-mean-square distance from the classical quintic
  /// least squares on those knots and parameters: the noise of the points,
  /// as far as the fit can tell.
  double NoiseLevel = 0.0;
  /// The count's knots leave a span with no points, or too few to decide it
  /// (uneven spacing), so that the classical least squares is singular: the
  /// parameters are the given ones and NoiseLevel 0 (not estimated). Only a
  /// requested count, or every count cross-validation tried, can be one.
  bool StarvedSpan = false;
};

/**
 * Parameters and knot count for approximating noisy, unevenly spaced points.
 * Chord lengths between noisy points carry the noise (where the noise is as
 * large as the spacing, they are mostly noise), and a least squares on them
 * fits the parameters' jitter with ever more knots. So, for each knot count,
 * the parameters start from u and are corrected towards the fit (each point
 * projected onto the classical quintic least squares, three rounds: the
 * classical parameter correction, Hoschek 1988), and the count is judged by
 * generalized cross-validation of the points' distances from that fit. Of
 * the counts within half a standard error of the best score (the score's
 * relative error is about sqrt(2 / N)), the fewest is taken: curvature and
 * torsion are second and third derivatives, which the last few knots a
 * position-based score accepts only make noisier (after Breiman's
 * one-standard-error rule; a whole standard error let bias into coarse
 * helices, none let noise into the torsion of randomly sampled trefoils).
 * Counts whose fit is singular (a span without points) are not candidates,
 * nor counts leaving a span with a single point (free to bulge into a gap),
 * or, smoothing (the best count takes three points or more a knot), with
 * fewer than three.
 * Lines that are smoothed (three points or more a knot) are planned a
 * second time from parameters warped by the first plan's curvature, so
 * that uniform knots gather where the curve bends; the plan with the lower
 * score is taken, or, where both score within half a standard error of the
 * better one's best count, the one with fewer knots. requestedKnots: a
 * count to use (clamped to [lowest, highest]) instead of choosing one;
 * correctParameters false keeps u. Progress is
 * reported after every count fitted (a million points take tens of seconds
 * in all); FitAborted when it asks to stop.
 */
ApproximationPlan planApproximation(const std::vector<Vec3>& points, const std::vector<double>& u,
  int highest, bool closed, int requestedKnots, bool correctParameters,
  const ProgressCallback& progress = {});

/**
 * Whether points at parameters u look noisy to a least squares: the
 * classical quintic on a third as many knots as points predicts them
 * better (generalized cross-validation) than on half as many, so
 * cross-validation keeps far fewer knots than points. Clean points, even
 * coarse ones, fit better and better as knots are added. False for fewer
 * than 20 points.
 */
bool looksNoisy(const std::vector<Vec3>& points, const std::vector<double>& u, bool closed);

/// The fewest knots an approximation takes: 2, or 3 distinct ones when closed.
inline int lowestKnotCount(bool closed)
{
  return closed ? 3 : 2;
}

/// Whether a request for knots (a count, or CrossValidatedKnots) approximates
/// a line that can take `highest` knots at most; otherwise it is interpolated.
inline bool approximates(int requested, bool closed, int highest)
{
  return (requested >= 2 || requested == CrossValidatedKnots) && highest >= lowestKnotCount(closed);
}

/**
 * Of built (knots knots) and the fits with up to two knots more or fewer
 * (within [lowest, highest]), the one whose automatic shape mode left the
 * fewest violations, the nearest count first on ties. The violations an
 * approximation keeps come and go with the count (the shipped aorta's
 * lines keep 0 to 4 over 26-39 knots, where the reference polygon's
 * vertices near an end turn within their noise), while cross-validation's
 * score is bumpy there: on the aorta the counts taken score 3% lower (line
 * 0, 36 for 34 knots) and the same (line 1, 32 for 30) on uniform knots,
 * neighbouring counts up to 20% apart.
 */
template <class Fit>
BuiltCurve fewestViolations(BuiltCurve built, int knots, int lowest, int highest, const Fit& fit,
  const ApproximationPlan& plan)
{
  for (const int other : { knots + 1, knots - 1, knots + 2, knots - 2 })
  {
    if (other < lowest || other > highest)
    {
      continue;
    }
    try
    {
      BuiltCurve candidate = fit(plan, other);
      if (candidate.Audit && candidate.Audit->violations() < built.Audit->violations())
      {
        built = std::move(candidate);
      }
    }
    catch (const FitAborted&)
    {
      throw; // the user stopped the work
    }
    catch (const std::exception&)
    {
      // a singular fit (a span without points): not a candidate
    }
    if (built.Audit->preserving())
    {
      break;
    }
  }
  return built;
}

/**
 * An approximating family's fit(plan, knots), with what the plan found
 * (BuiltCurve::DataParameters, NoiseLevel, StarvedSpan): planApproximation's
 * plan (the parameters corrected when correctParameters) and count, the requested one
 * clamped to [lowestKnotCount(closed), highest] or for CrossValidatedKnots
 * the chosen one, and then 10% fewer while fit throws (a singular system: a
 * gap in the data leaves a span without points where the family's knots
 * differ from the plan's), down to the lowest, where the failure is
 * rethrown. A user's count fails as asked. Nothing when the line cannot be
 * approximated (approximates() false): the family interpolates.
 */
template <class Fit>
std::optional<BuiltCurve> approximateWithPlan(const std::vector<Vec3>& points,
  const std::vector<double>& u, int requested, bool closed, int highest, bool correctParameters,
  const ProgressCallback& progress, const Fit& fit)
{
  if (!approximates(requested, closed, highest))
  {
    return std::nullopt;
  }
  const ApproximationPlan plan =
    planApproximation(points, u, highest, closed, requested, correctParameters, progress);
  const int lowest = lowestKnotCount(closed);
  for (int knots = plan.Knots;; knots = std::max(lowest, std::min(knots - 1, knots * 9 / 10)))
  {
    try
    {
      BuiltCurve built = fit(plan, knots);
      if (requested == CrossValidatedKnots && built.Audit && !built.Audit->preserving())
      {
        built = fewestViolations(std::move(built), knots, lowest, highest, fit, plan);
      }
      built.DataParameters = plan.Parameters;
      built.NoiseLevel = plan.NoiseLevel;
      built.StarvedSpan = plan.StarvedSpan;
      return built;
    }
    catch (const FitAborted&)
    {
      throw; // the user stopped the work: no retry
    }
    catch (const std::exception&)
    {
      if (requested != CrossValidatedKnots || knots <= lowest)
      {
        throw;
      }
    }
  }
}

/**
 * L*: the piecewise linear curve with vertices at knots closest in least
 * squares to points at parameters u (knots[0] <= u <= knots.back()); closed,
 * one vertex per distinct knot (the last knot closes the polygon).
 */
std::vector<Vec3> leastSquaresPolygon(const std::vector<Vec3>& points,
  const std::vector<double>& u, const std::vector<double>& knots, bool closed = false);

/**
 * How far each vertex of leastSquaresPolygon(points, u, knots, closed) moves
 * with the noise of the points (whose positions it does not read), per unit
 * of it: sqrt((H^-1)_ii), H the normal matrix of the hat functions at u
 * (points off the curve independently, each by the unit). On points spread
 * evenly, N of them on K knots, that is sqrt(sqrt(3) K / N) inside (the Gram
 * matrix of hat functions, [1/6 2/3 1/6] per point per span, has an inverse
 * whose diagonal tends to sqrt(3)), more at an open polygon's ends and where
 * the points are sparse. Throws std::runtime_error when a vertex rests on no
 * point.
 */
std::vector<double> leastSquaresPolygonNoise(const std::vector<Vec3>& points,
  const std::vector<double>& u, const std::vector<double>& knots, bool closed = false);

/// An approximation's reference polygon (L*, psi) and how far its vertices
/// move with the noise of the points.
struct ReferencePolygon
{
  /// leastSquaresPolygon of the extended data: one vertex per knot, beyond an open line's ends too.
  std::vector<Vec3> Whole;
  /// Its vertices on the data's knots: the polygon whose shape the curve keeps.
  CleanPolyline Polygon;
  /// Per vertex of Polygon: pointNoise times leastSquaresPolygonNoise (the
  /// mirrored points counted as independent ones).
  std::vector<double> VertexNoise;
};

/// The reference polygon of an approximation of data whose points are off
/// the curve by about pointNoise (the plan's NoiseLevel).
ReferencePolygon referencePolygon(const ExtendedData& data, bool closed, double pointNoise);
} // namespace shapesplines

#endif
