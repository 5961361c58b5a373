// ShapeSplines math core: C2 generalized cubic splines (Costantini & Manni (generalized cubics)), piecewise
// in span{1, t, u(t), v(t)} with a kind and a tension per interval.
#ifndef shapesplines_GeneralizedCubicSpline_h
#define shapesplines_GeneralizedCubicSpline_h

#include "FitPolyline.h"

#include <array>
#include <vector>

namespace shapesplines
{
enum class SpaceKind : int
{
  Polynomial = 0,    ///< (1 - t)^3: the classical cubic, no tension
  Exponential = 1,   ///< hyperbolic, tension p >= 0 (p -> 0: cubic, p -> inf: polygon)
  Trigonometric = 2, ///< tension 0 <= p < pi
  VariableDegree = 3 ///< (1 - t)^k, degree k >= 3 (k = 3: cubic, k -> inf: polygon)
};

/**
 * The kernels of one interval's space span{1, t, u, v}, normalised as in the
 * paper's (4), (5): u(0) = 1, u(1) = u'(1) = u''(1) = 0 and v(1) = 1,
 * v(0) = v'(0) = v''(0) = 0. u comes from a left kind and tension, v from a
 * right one (v(t) = u_right(1 - t)); the symmetric space uses one kind.
 * Evaluated without overflow or cancellation for tensions up to 1e3 (degrees
 * up to any k) and as the tension goes to 0.
 */
class SpaceKernel
{
public:
  SpaceKernel() = default;
  /// tension: p for Exponential and Trigonometric, the degree k for VariableDegree.
  SpaceKernel(SpaceKind kind, double tension);
  SpaceKernel(SpaceKind leftKind, double leftTension, SpaceKind rightKind, double rightTension);

  /// Derivatives 0..order (order <= 4; the others are left 0) at t.
  Jet u(double t, int order = 4) const;
  Jet v(double t, int order = 4) const;
  /// -u'(0) and v'(1) (both > 1): xi = 1 / uSlope(), eta = 1 / vSlope() in the paper.
  double uSlope() const { return this->USlope; }
  double vSlope() const { return this->VSlope; }
  /// u''(0) and v''(1).
  double uSecond() const { return this->USecond; }
  double vSecond() const { return this->VSecond; }
  /// The larger of the two tensions (the degree for VariableDegree, 0 for Polynomial).
  double tension() const;

private:
  SpaceKind LeftKind = SpaceKind::Polynomial;
  SpaceKind RightKind = SpaceKind::Polynomial;
  double LeftTension = 0.0;
  double RightTension = 0.0;
  double LeftNormalisation = 1.0; ///< f(p) of each side, computed once
  double RightNormalisation = 1.0;
  double USlope = 3.0;
  double VSlope = 3.0;
  double USecond = 6.0;
  double VSecond = 6.0;
};

/// The largest tension each kind takes: Trigonometric stays below pi.
double largestTension(SpaceKind kind, double requested);

/**
 * The generalized Bernstein basis B0..B3 of the kernel's space (Theorem 1):
 * B0 = u, B3 = v, partition of unity and t = sum tau_i B_i with tau =
 * (0, xi, 1 - eta, 1); entry [i][m] is the m-th derivative of B_i at t.
 */
std::array<Jet, 4> generalizedBernstein(const SpaceKernel& kernel, double t);

/// The de Casteljau-like evaluation of Theorem 2, (9): sum b_i B_i(t) by three
/// rounds of combinations (convex when the tension grows as in (11)-(14)).
double deCasteljau(const SpaceKernel& kernel, const std::array<double, 4>& b, double t);

/**
 * Section 3's generalized de Boor construction: on extended knots x_0 < ...
 * < x_m (kernels per interval, m of them) and de Boor values P_0..P_m (one
 * per knot, at the abscissae sigma_k), the generalized Bezier coefficients
 * b_0..b_3 of every interval k = 2..m-3 (those whose gamma's are defined).
 * The value P_i = 1, others 0, gives the generalized cubic B-spline B^(i).
 */
std::vector<std::array<double, 4>> bezierFromDeBoor(const std::vector<double>& knots,
  const std::vector<SpaceKernel>& kernels, const std::vector<double>& deBoor);

/// End conditions of an open generalized cubic through its points.
enum class GeneralizedCubicEnds : int
{
  /// s'' = 0 at both ends (the paper's): an error of the size of the
  /// curvature at the ends, at any density.
  Natural = 0,
  /// s'' at each end is that of the cubic through the four end points: the
  /// curvature converges up to the ends (second order, as inside). As a
  /// span's tension grows its ends' second derivatives act ever more
  /// locally, so a tensioned end span still tends to its chord.
  Polynomial = 1
};

/**
 * A C2 curve that is, on each span, a combination of 1, t, u_k(t), v_k(t)
 * with the span's own kind and tension (t = (x - x_k) / h_k). Interpolation
 * solves for the second derivatives at the knots, a tridiagonal (cyclic for
 * closed curves) diagonally dominant system: the spline of Costantini &
 * Manni's generalized cubic B-splines (generalized cubics) that interpolates
 * the data, with natural or polynomial ends.
 */
class GeneralizedCubicSpline final : public Curve
{
public:
  /// kernels: one per span (points.size() - 1 open, points.size() closed).
  static GeneralizedCubicSpline interpolate(const std::vector<Vec3>& points,
    const std::vector<double>& knots, bool closed, const std::vector<SpaceKernel>& kernels,
    GeneralizedCubicEnds ends = GeneralizedCubicEnds::Natural);

  Derivatives evaluateOnSpan(int span, double t, int order) const override;
  /// "Tension" per span (the degree for VariableDegree).
  std::vector<SpanParameter> spanParameters() const override;
  const std::vector<SpaceKernel>& kernels() const { return this->Kernels; }

private:
  GeneralizedCubicSpline(std::vector<double> knots, bool closed);

  std::vector<SpaceKernel> Kernels;
  /// Per span: s = A + B t + C u(t) + D v(t).
  std::vector<std::array<Vec3, 4>> Coefficients;
};

struct GeneralizedCubicOptions
{
  SpaceKind Kind = SpaceKind::Exponential;
  /// Raise the tension only on spans where the shape audit fails, from
  /// Tension, until none fails or MaxTension is reached.
  bool Automatic = true;
  double Tension = 0.0;      ///< starting (automatic) or fixed tension
  double MaxTension = 1000.0;
  int MaxRounds = 64;
  GeneralizedCubicEnds Ends = GeneralizedCubicEnds::Polynomial; ///< of open lines
};

/// The tension after one more round of the automatic mode (0 stays 0 only for Polynomial).
double raisedTension(SpaceKind kind, double tension, double maxTension);

/**
 * Builder of generalized cubic splines through the data, fixed or automatic.
 * The context's PointValues, if any, are tensions per point: a span starts
 * from the larger of its two points' (instead of Tension).
 */
CurveBuilder generalizedCubicBuilder(const GeneralizedCubicOptions& options);
} // namespace shapesplines

#endif
