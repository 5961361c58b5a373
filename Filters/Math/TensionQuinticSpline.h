// ShapeSplines math core: C3 and C4 tensioned quintic parametric B-splines
// (Cravero, Manni, Sampoli, Cravero, Manni & Sampoli).
#ifndef shapesplines_TensionQuinticSpline_h
#define shapesplines_TensionQuinticSpline_h

#include "Curve.h"

#include <array>
#include <utility>
#include <vector>

namespace shapesplines
{
enum class QuinticContinuity
{
  C3, ///< section 3: gamma_i in (0,2) and lambda_i > 0 per knot
  C4  ///< section 4: gamma_i in (0,1] per knot
};

/// Shape parameters, one per knot (open: n + 1 for n spans; closed: n).
struct QuinticParameters
{
  QuinticContinuity Continuity = QuinticContinuity::C4;
  std::vector<double> Gamma;
  std::vector<double> Lambda; ///< C3 only; C4 ignores it

  static QuinticParameters uniform(
    QuinticContinuity continuity, int knots, double gamma = 1.0, double lambda = 1.0);
  /// Throws std::invalid_argument outside (9) (C3) or (0,1] (C4).
  void check(int knots) const;
};

/// Smallest gamma (and lambda) the automatic mode goes down to.
constexpr double QuinticTensionFloor = 1.0 / 256.0;

/**
 * A space curve s(x) = C(t(x)) built from the tensioned quintic B-splines:
 * C(t) = (X(t), sum_k P_k Y^(k)(t)) is piecewise quintic in t with Bezier
 * points from the geometric construction (10)-(18) (C3) or (22)-(32) (C4),
 * and X(t), common to all basis functions, maps the parametric knots t_i to the
 * knots x_i (19)/(33). The construction is linear in the de Boor points
 * D_k = (xi_k, P_k), so each Bezier point is a fixed convex combination of six
 * of them. The curve's parameter is x, in which it is C3 or C4; evaluation
 * inverts X on the span (monotone quintic) and converts the derivatives.
 *
 * Open curves with n spans have n + 5 de Boor points D_{-2}..D_{n+2} (stored
 * from index 0); parametric knots and parameters beyond the ends repeat the
 * end values. Closed curves have n, indices wrapping around (xi_{k+n} =
 * xi_k + t_n - t_0).
 */
class TensionQuinticSpline final : public Curve
{
public:
  /// The curve of given de Boor abscissae xi and points (t: n + 1 parametric knots).
  static TensionQuinticSpline fromControlPoints(const std::vector<double>& t,
    const std::vector<double>& xi, const std::vector<Vec3>& points,
    const QuinticParameters& parameters, bool closed);

  /// The Greville abscissae (21): with gamma = lambda = 1 they give X(t) = t.
  static std::vector<double> grevilleAbscissae(const std::vector<double>& t, bool closed);

  /// Per span, the weights of its six Bezier points (rows) on the de Boor
  /// points D_{i-2}..D_{i+3} (columns), from the geometric construction.
  using SpanWeights = Eigen::Matrix<double, 6, 6>;
  /// Derivatives 1-3 at an open line's start and end (polynomialEndDerivatives).
  using EndDerivatives = std::array<std::array<Vec3, 3>, 2>;

  /**
   * The weights of one open line's construction at the parameters last asked
   * for, kept between builds on the same knots: a build whose parameters
   * differ at a few knots (the automatic mode's searches) recomputes only the
   * spans those move (a span's weights read the parameters of the knots
   * within four of it). Closed lines are computed whole.
   */
  struct WeightsMemo
  {
    std::vector<double> Knots;
    QuinticParameters Parameters;
    std::vector<SpanWeights> Weights;
  };

  struct Abscissae
  {
    std::vector<double> Xi;
    /// The parameters used: those given, or pulled towards 1 where moving
    /// the knots did not give an increasing X.
    QuinticParameters Parameters;
    /// The construction's weights for Parameters (what the curve on these
    /// abscissae is built from).
    std::vector<SpanWeights> Weights;
    int Recoveries = 0;      ///< rounds of footnote-3 recovery
    bool KnotsMoved = false; ///< some knots are not where they were asked to be
    bool Increasing = false; ///< X' > 0 on every span (false only without recovery)
    DeferredCondition Condition; ///< of the last knot system solved
  };

  /**
   * The knot system (34): abscissae xi such that X(t_i) = t_i at every knot
   * (open curves keep xi_{-2}, xi_{-1}, xi_{n+1}, xi_{n+2} at their Greville
   * values, so that gamma = lambda = 1 gives X(t) = t). Where X is not
   * strictly increasing (footnote 3) and recover is true, the requested knots
   * near the bad spans move halfway towards those of the Greville abscissae
   * (which are increasing for any parameters), up to 12 times, the last time
   * all the way; if that fails too the parameters there are pulled halfway to
   * 1; after 64 rounds all parameters are 1 and X(t) = t. Throws
   * std::domain_error if recover is true and even that has no solution (knots
   * so uneven that the knot system is singular).
   */
  static Abscissae solveAbscissae(const std::vector<double>& t,
    const QuinticParameters& parameters, bool closed, bool recover = true,
    WeightsMemo* memo = nullptr);

  /**
   * Interpolates points (open: n + 1 >= 3 points; closed: n >= 3, knots with
   * the closing one) with knots x_i = knots[i] via (34). Open curves take
   * s' and s'' at each end from the polynomial through the six (or fewer)
   * end points, blended by w = min(1, gamma, lambda) of the end knot towards
   * the limit polygon's: s' = w p' + (1 - w) chord slope, s'' = w p''.
   * ends: those polynomials' derivatives (dataEnds), and memo, the weights
   * of the last build, given by a caller that builds many curves on the same
   * points and knots.
   */
  static TensionQuinticSpline interpolate(const std::vector<Vec3>& points,
    const std::vector<double>& knots, const QuinticParameters& parameters, bool closed,
    const EndDerivatives* ends = nullptr, WeightsMemo* memo = nullptr);
  /// The derivatives at an open line's start and end of the polynomials
  /// interpolate() takes its end conditions from (polynomialEndDerivatives).
  static EndDerivatives dataEnds(const std::vector<Vec3>& points, const std::vector<double>& knots);

  /**
   * The spline with knots x_i = knots[i] (via (34)) closest in least squares
   * to points at parameters u: sum_j |s(u_j) - points_j|^2 minimal (the
   * normal equations are banded, cyclic when closed). Needs enough points on
   * every span. Closed: knots end with the closing one, parameters have one
   * entry per distinct knot, and u may hold the closing parameter after the
   * points'. memo: as interpolate's.
   */
  static TensionQuinticSpline approximate(const std::vector<Vec3>& points,
    const std::vector<double>& u, const std::vector<double>& knots,
    const QuinticParameters& parameters, bool closed = false, WeightsMemo* memo = nullptr);

  Derivatives evaluateOnSpan(int span, double x, int order) const override;
  /// In the span's own variable u: the length of C(u) (a quintic), whose
  /// speed stays smooth where a small gamma makes s'(x) = C'(u) / X'(u) vary
  /// fast; and no inversion of X per node.
  double arcLengthOnSpan(int span, double a, double b) const override;

  /// "Gamma" per span (the smaller of its two knots', cell summary MinGamma),
  /// and for C3 "Lambda" likewise.
  std::vector<SpanParameter> spanParameters() const override;

  /// Derivatives of the parametric form C(t) = (X(t), Y(t)) on a span, t local in [0,1].
  std::pair<std::array<double, 5>, Derivatives> parametricDerivatives(
    int span, double tau, int order) const;

  const QuinticParameters& parameters() const { return this->Parameters; }
  const std::vector<double>& abscissae() const { return this->Xi; }
  const std::vector<Vec3>& controlPoints() const { return this->Points; }
  int knotRecoveries() const { return this->Recoveries; }

private:
  TensionQuinticSpline(std::vector<double> knots, bool closed);
  /// fromControlPoints with the construction's weights already computed.
  /// The spline of the de Boor points solved for on abscissae (one per row
  /// of solution), its condition the larger of the two systems'.
  static TensionQuinticSpline fromSolution(const std::vector<double>& t, Abscissae abscissae,
    const Eigen::MatrixX3d& solution, DeferredCondition condition, bool closed);
  static TensionQuinticSpline fromWeights(const std::vector<double>& t,
    const std::vector<double>& xi, const std::vector<Vec3>& points,
    const QuinticParameters& parameters, bool closed, const std::vector<SpanWeights>& weights);
  /// The local parameter on span where X = x (clamped to [0,1]).
  double localParameter(int span, double x) const;

  QuinticParameters Parameters;
  std::vector<double> Xi;
  std::vector<Vec3> Points;
  int Recoveries = 0;
  /// Per span: the Bezier ordinates of X in the local parameter (X's range
  /// and Newton's first guess), and X and C in powers of it (bezierToPower:
  /// faster to evaluate than de Casteljau, and each sample evaluates X several times).
  std::vector<std::array<double, 6>> XBezier;
  std::vector<std::array<double, 6>> XPower;
  /// (X, C) in one vector: one Horner pass for both (vectorised as 4 doubles).
  std::vector<std::array<Eigen::Vector4d, 6>> XCPower;
};
} // namespace shapesplines

#endif
