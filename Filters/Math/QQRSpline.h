// ShapeSplines math core: the quartic Bernstein-like (qqr) basis with two
// exponential shape parameters and the cubic B-spline-like curves built on it
// (Wang & Zhang, AIMS Mathematics 5(5), 2020).
#ifndef shapesplines_QQRSpline_h
#define shapesplines_QQRSpline_h

#include "FitPolyline.h"

#include <array>
#include <limits>
#include <vector>

namespace shapesplines
{
/**
 * The qqr basis of Definition 1, (2.1), at t in [0, 1]: A0 = (1-t)^alpha,
 * A1 = alpha t (1-t)^(alpha-1), A3 = beta (1-t) t^(beta-1), A4 = t^beta and
 * A2 = 1 - A0 - A1 - A3 - A4; entry [i][m] is the m-th derivative of A_i
 * (m = 0..order, order <= 4; the others are left 0). alpha, beta >= 2
 * (std::invalid_argument otherwise).
 *
 * A2 is evaluated without cancellation as G(t; alpha) - (A3 + A4) for
 * t <= 1/2 (G(1-t; beta) - (A0 + A1) beyond), where
 * G(t; a) = 1 - (1-t)^(a-1) (1 + (a-1) t) = a (a-1) int_0^t x (1-x)^(a-2) dx
 * is summed as a series where it is small; its derivatives come from the
 * integrand, and (1-t)^p is exp(p log1p(-t)) for t < 1/2 (t^p likewise), so
 * nothing cancels and no p ulps are lost to 1 - t for alpha, beta up to 200
 * and beyond (measured against long double: 6e-16 on values, 2e-14 on
 * derivatives relative to the largest of the five).
 *
 * Where t^(beta-m) or (1-t)^(alpha-m) has a negative exponent at an end
 * (beta < m at t = 0, alpha < m at t = 1), the m-th derivative there is
 * unbounded and returned as +-inf; a zero coefficient (integer exponent)
 * gives an exact 0.
 *
 * Decisions about the paper: the non-negativity of A2 (Theorem 1 (1), Lemma 1)
 * only holds for alpha, beta >= 3: Lemma 1's F(t; 2) = -2 t^2 (1 - t) < 0, and
 * for alpha = beta = 2 A2 = -2 t (1 - t). For alpha = beta = 3, A2 = 0 and the
 * basis is the cubic Bernstein basis (not linearly independent as five
 * functions). The second derivatives of Theorem 1 (5) need alpha, beta > 3.
 */
std::array<Jet, 5> qqrBasis(double t, double alpha, double beta, int order = 4);

/// G(t; a) above and its derivatives 0..order (a >= 2, t in [0, 1]).
Jet qqrTail(double t, double a, int order = 4);

/**
 * Local shape parameters x_i, y_i, z_i of the paper's choice just before its
 * Figure 5, per knot interval i of h (h_i = u_{i+1} - u_i), read with exactly
 * these indices (shifted by one, the basis at alpha = beta = 4 is no longer
 * the cubic B-spline on non-uniform knots; as read here it is, to 3e-16):
 *   x_i = h_i / (4 (h_i + h_{i+1} + h_{i+2})),
 *   y_i = h_{i+1} / (4 (h_{i-1} + h_i + h_{i+1})),
 *   z_i = (2 h_i + h_{i+1}) / (2 (h_i + h_{i+1} + h_{i+2})).
 * With alpha = beta = 4 they make the qqr B-splines the classical cubic
 * B-splines. Entries whose intervals fall outside h are NaN.
 */
struct QQRLocalParameters
{
  std::vector<double> X, Y, Z;
};
QQRLocalParameters cubicLocalParameters(const std::vector<double>& h);

/**
 * The cubic B-spline-like (qqr B-spline) basis of Definition 3, (3.1), on knots
 * u_0 < ... < u_m: B_i is B_{i,0}(t_i) on [u_i, u_{i+1}), B_{i,1}(t_{i+1}),
 * B_{i,2}(t_{i+2}), B_{i,3}(t_{i+3}) and 0 outside [u_i, u_{i+4}) (the paper's
 * text repeats B_{i,1}: a conversion typo), t_j = (u - u_j) / h_j.
 * Global alpha, beta; local x, y, z per knot interval (index as h).
 */
class QQRBSplineBasis
{
public:
  QQRBSplineBasis(std::vector<double> knots, double alpha, double beta, QQRLocalParameters local);

  /// Number of basis functions B_0..B_{m-4}.
  int size() const { return static_cast<int>(this->Knots.size()) - 4; }
  const std::vector<double>& knots() const { return this->Knots; }

  /// B_{i,piece}(t), piece 0..3, derivatives in t (0..order).
  Jet piece(int i, int piece, double t, int order = 4) const;
  /// B_i(u) and its derivatives in u. span: the knot interval u lies in (u may
  /// be at either end of it; -1: found from u, right-continuous).
  Jet value(int i, double u, int order = 4, int span = -1) const;

  /// mu_i, upsilon_i, rho_i of section 3.1.
  double mu(int i) const;
  double upsilon(int i) const;
  double rho(int i) const;

private:
  std::vector<double> Knots;
  std::vector<double> H;
  double Alpha, Beta;
  QQRLocalParameters Local;
};

/// A curve's local shape parameters x, y, z: NaN, the paper's choice
/// (cubicLocalParameters); a number, that value at every knot.
struct QQRLocalShape
{
  double X = std::numeric_limits<double>::quiet_NaN();
  double Y = std::numeric_limits<double>::quiet_NaN();
  double Z = std::numeric_limits<double>::quiet_NaN();
};

/**
 * A curve's local shape parameters per data point (decision: the vectors are
 * indexed by point, not by the paper's knot interval). With the indexing of
 * QQRSpline below (D_k at the paper's u_{k+2}), the paper's x_{k+1}, y_{k+1}
 * and z_{k+1} are the entries k:
 *  - Z[k] places the middle Bezier point of span k (from D_k to D_{k+1}) on
 *    its chord, (1 - Z[k]) D_k + Z[k] D_{k+1}; the last entry of an open line
 *    has no span and is not used.
 *  - X[k], Y[k] make S_k = D_k + Y[k] (D_{k-1} - D_k) + X[k] (D_{k+1} - D_k),
 *    the point near D_k from which the Bezier points next to the knot of D_k
 *    are made.
 * Each vector is empty (the QQRLocalShape value everywhere) or has one entry
 * per point; a NaN entry takes the QQRLocalShape value (or the paper's) at
 * that point. The local interpolation ignores X and Y ((3.18) gives them).
 *
 * What they do to a span k (the Bezier points of QQRSpline below): it lies on
 * its chord's line when S_k, S_{k+1}, the middle points of spans k - 1 and
 * k + 1 lie on it, i.e. Y[k] = 0, X[k+1] = 0, Z[k-1] = 1, Z[k+1] = 0 for the
 * control polygon; for the local interpolation, where (3.18) makes
 * Y[k] ~ -(1 - Z[k-1]) and X[k+1] ~ -Z[k+1], just Z[k-1] = 1 and Z[k+1] = 0
 * (Z[k] itself only slides the middle point along the chord). At the data
 * point D_k of an interpolation the tangent (3.20) is
 * ~ h_k (1 - Z[k-1]) (D_k - D_{k-1}) / h_{k-1} + h_{k-1} Z[k] (D_{k+1} - D_k) / h_k,
 * so Z[k-1] = 1 together with Z[k] = 0 stops the curve there (a corner).
 */
struct QQRKnotShape
{
  std::vector<double> X, Y, Z;
  /// Per span, how far (0..1) the local parameters around it are moved to
  /// put the span on its chord: Y[k] and X[k+1] scaled by 1 - s, Z[k-1]
  /// moved towards 1 and Z[k+1] towards 0 (at s = 1 the span is straight,
  /// the joins still C2). Empty: none.
  std::vector<double> Straightness;
  /// Per point, how far (0..1) S_k moves towards the midpoint of the middle
  /// points of its two spans, where the curve's second derivative at the
  /// knot vanishes (x = Z[k+1] / 2, y = (1 - Z[k-1]) / 2 before a span's
  /// Straightness scales them): at 1 the curve is flat at D_k. Empty: none.
  std::vector<double> Flattening;
  /// Per point, nonzero where the points run straight through it: two
  /// straightened spans meeting there share their line, and neither moves
  /// the other's parameters (which would stop the curve at the point).
  std::vector<char> StraightThrough;
};

/// How a qqr curve is made from the points.
enum class QQRConstruction : int
{
  /// The curve through the points: its control points solved (not-a-knot
  /// ends; natural at an end within three spans of a straightened one, see
  /// QQRKnotShape::Straightness). At alpha = beta = 4 with the paper's local
  /// parameters it is the classical cubic spline interpolant, and it
  /// converges as points are added.
  Interpolation = 0,
  /// Section 3.6's local interpolation: each point's tangent (3.20) and second
  /// derivative (3.21) from its neighbours only, no system solved. Its
  /// curvature at the points is about 3x the curve's at alpha = 4 however
  /// dense they are ((3.21) is (alpha^2 - alpha)/2 times the second
  /// difference over h^2 at z = 1/2): a design tool, not an estimate.
  LocalInterpolation = 1,
  /// The points are the control polygon (approximation, (3.7)).
  ControlPolygon = 2
};

/**
 * Cubic B-spline-like curves (Definition 4, (3.7)) in the Bezier form of
 * section 3.4, (3.8): on each span the qqr curve (2.5) with Bezier points
 * T_{i-2}, upsilon_{i-1} S_{i-2} + mu_{i-1} R_{i-2,i-1}, R_{i-2,i-1},
 * upsilon_i R_{i-2,i-1} + mu_i S_{i-1}, T_{i-1} (the paper's S_{i-1} has a_i
 * for x_i, and its last term A_3 for A_4: typos).
 *
 * Indexing (decision): the curve's knots are the data parameters t_0 < ... <
 * t_N, data point D_k sits at the paper's knot u_{k+2}; for the control
 * polygon and the local interpolation D_k is the control point P_k and the
 * open ends double the end points, P_{-1} = P_0 and P_{N+1} = P_N, as
 * section 3.6 does, so that there is one span per pair of neighbouring data
 * points; the interpolation solves for P_{-1}..P_{N+1}. The knot intervals
 * beyond the data that the formulas need mirror the ones inside (h_{-1} =
 * h_0, h_{-2} = h_1, ...); closed curves wrap around.
 *
 * Exponents: per span k a left exponent alpha_k and a right one beta_k. The
 * joins are C1 (and C2) when beta_{k-1} = alpha_k (paper's alpha = beta; the
 * derivation of Theorem 8 only pairs the two exponents that meet at a knot),
 * so a per-knot exponent kappa_j (alpha_k = kappa_k, beta_k = kappa_{k+1}) keeps
 * C2 with a different exponent at every knot (> 3, see qqrBasis). With
 * alpha != beta everywhere the curve is G1 only (continuous tangent direction,
 * speed ratio beta / alpha).
 */
class QQRSpline final : public Curve
{
public:
  using Local = QQRLocalShape;

  /**
   * The local shape parameters x, y, z (per paper index) of one open line's
   * last build, kept for the next build on the same knots whose shape differs
   * only in Straightness and Flattening (the automatic mode's searches): it
   * computes again only those a changed span or point moves (x, y and z at
   * paper index i read the straightness of spans i - 3..i and the flattening
   * of point i - 1).
   */
  struct GeometryMemo
  {
    std::vector<double> Knots;
    Local LocalShape;
    QQRKnotShape Shape;
    QQRConstruction Construction = QQRConstruction::Interpolation;
    std::vector<double> X, Y, Z;
    /// The interpolation's row per point: its knot's weights on P(k-1)..P(k+2)
    /// (they read x, y, z at two paper indices).
    std::vector<Eigen::Vector4d> Rows;
  };

  /**
   * The curve of the construction through (or on the control polygon of) the
   * points at the knots, with global alpha, beta (>= 2) and local shape
   * parameters local (NaN: the paper's choice before Figure 5), or per point
   * (knotShape; entries that are NaN or vectors that are empty fall back to
   * local). Any values keep the curve C2 (the joins of Theorem 8 hold for any
   * x, y, z per knot interval; checked in the tests). The local
   * interpolation takes x and y from (3.18) and ignores local.X, local.Y:
   * (3.18) as printed lacks a factor 1/2 in x_{i-1}; with it, Q(u_i) =
   * P_{i-2} and (3.20) hold (checked in the tests); without it, neither
   * does. So x_{i-1} = -h_{i-1} z_{i-1} / (2 h_i), y_{i-1} = -h_i (1 -
   * z_{i-2}) / (2 h_{i-1}).
   */
  static QQRSpline make(QQRConstruction construction, const std::vector<Vec3>& points,
    const std::vector<double>& knots, bool closed, double alpha, double beta,
    const Local& local = {}, const QQRKnotShape& knotShape = {});
  /// The same with one exponent per point (alpha = beta at that knot; points.size() values);
  /// memo: the last build's, given by a caller that builds many curves on the same points.
  static QQRSpline make(QQRConstruction construction, const std::vector<Vec3>& points,
    const std::vector<double>& knots, bool closed, const std::vector<double>& knotExponents,
    const Local& local = {}, const QQRKnotShape& knotShape = {}, GeometryMemo* memo = nullptr);

  Derivatives evaluateOnSpan(int span, double t, int order) const override;
  /// Per span "Alpha", the larger of its two exponents, "Straightness" and
  /// "Flattening", the larger of its knots' (QQRKnotShape; 0 unless the
  /// automatic mode moved them).
  std::vector<SpanParameter> spanParameters() const override;

  /// The five Bezier points of a span (the qqr curve (2.5) on it).
  const std::array<Vec3, 5>& bezier(int span) const { return this->Bezier[span]; }
  /// The smallest speed |Q'| h on a span (65 samples) relative to the length
  /// of its Bezier polygon: ~1 for a regular span, ~alpha^2 2^-alpha for large
  /// exponents, where the span approaches a corner at its middle Bezier point.
  double speedRatio(int span) const;
  /// Left and right exponent of a span.
  const std::array<double, 2>& exponents(int span) const { return this->Exponents[span]; }
  /// The local shape parameters the curve was built with, one per point
  /// (QQRKnotShape; for an interpolation X and Y are the ones of (3.18)).
  const QQRKnotShape& knotShape() const { return this->KnotShape; }
  /// The flattening the curve was built with, one per point
  /// (QQRKnotShape::Flattening; empty: none).
  const std::vector<double>& flattening() const { return this->Flattening; }

private:
  QQRSpline(std::vector<double> knots, bool closed);
  static QQRSpline build(const std::vector<Vec3>& points, const std::vector<double>& knots,
    bool closed, std::vector<std::array<double, 2>> exponents, const Local& local,
    const QQRKnotShape& knotShape, QQRConstruction construction, GeometryMemo* memo = nullptr);

  std::vector<std::array<Vec3, 5>> Bezier;
  /// Per span, the power form of its quartic Bezier curve (bezierToPower):
  /// the span itself where alpha = beta = 4.
  std::vector<std::array<Vec3, 5>> QuarticPower;
  std::vector<std::array<double, 2>> Exponents;
  QQRKnotShape KnotShape;
  std::vector<double> Straightness;
  std::vector<double> Flattening;
};

struct QQROptions
{
  QQRConstruction Construction = QQRConstruction::Interpolation;
  /// Move the spans where the shape audit fails towards their chords
  /// (QQRKnotShape::Straightness), raising alpha = beta up to MaxAlpha where
  /// a straight run of the data ends in a turn; where violations remain,
  /// flatten the curve at the knots of the spans that fail only torsion
  /// signs (QQRKnotShape::Flattening) and straighten again from there; the
  /// curve with the fewest violations kept (qqrBuilder).
  bool Automatic = true;
  double Alpha = 4.0, Beta = 4.0, MaxAlpha = 200.0;
  /// NaN: the paper's choice before Figure 5 (cubicLocalParameters). The local
  /// interpolation takes x and y from (3.18) and ignores X and Y.
  double X = std::numeric_limits<double>::quiet_NaN();
  double Y = std::numeric_limits<double>::quiet_NaN();
  double Z = std::numeric_limits<double>::quiet_NaN();
  int MaxRounds = 64; ///< automatic: rounds at most
};

/// The automatic mode's levels: level l moves a span 1 - 2^(-l/2) of the
/// way to its chord (qqrStraightness), the top level to within 1e-6.
constexpr int QQRStraighteningLevels = 40;
double qqrStraightness(int level);
/// The exponent at a turn that ends a straight run, between two spans at
/// least at this level: kappa until straightness 3/4, then doubling every
/// four levels, capped at the larger of kappa and maxAlpha.
double qqrTurnExponent(double kappa, double maxAlpha, int level);

/**
 * Builder of qqr B-spline-like curves for fitPolyline: the construction of the
 * options (the data as control polygon: its shape reference is then the data
 * polygon), fixed exponents or automatic. The context's PointValues, if any,
 * are the local bias z per point; values outside [0, 1] or NaN take Z's.
 * Automatic: each span that breaks the shape is moved towards its chord,
 * level by level (searchShape); where violations remain, the curve is
 * flattened at the knots of the spans where the fixed curve breaks only
 * torsion signs, the straightening search is improved (improveShape) and
 * run again from the flattened curve, all within the automatic driver's
 * bounds, and the curve with the fewest violations kept. Moving a span
 * towards its chord keeps the sign of its torsion. An exponent alone cannot
 * keep the shape: it scales the curvature vector at its knot without
 * turning it, and a large exponent makes a span slow down at its middle
 * Bezier point (speed about alpha^2 2^-alpha of its polygon's). Two
 * neighbouring spans cannot both be straight where the data turn (C2 would
 * stop the curve there), so on densely curved data some violations stay,
 * reported.
 */
CurveBuilder qqrBuilder(const QQROptions& options);
} // namespace shapesplines

#endif
