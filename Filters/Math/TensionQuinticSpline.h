// ShapeSplines math core: C3 and C4 tensioned quintic parametric B-splines
// (Cravero, Manni, Sampoli, paper 000).
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

  struct Abscissae
  {
    std::vector<double> Xi;
    /// The parameters used: those given, or pulled towards 1 where (34) gave
    /// a non-increasing X (footnote 3).
    QuinticParameters Parameters;
    int Recoveries = 0; ///< rounds of pulling parameters towards 1
    bool Increasing = false; ///< X' > 0 on every span (false only without recovery)
  };

  /**
   * The knot system (34): abscissae xi such that X(t_i) = t_i at every knot
   * (open curves keep xi_{-2}, xi_{-1}, xi_{n+1}, xi_{n+2} at their Greville
   * values, so that gamma = lambda = 1 gives X(t) = t). Where the result is not strictly increasing
   * (footnote 3), the parameters of the knots around it are pulled halfway to
   * 1 and the system solved again (unless recover is false); after 64 rounds
   * all parameters are 1 (the Greville abscissae).
   */
  static Abscissae solveAbscissae(const std::vector<double>& t,
    const QuinticParameters& parameters, bool closed, bool recover = true);

  /**
   * Interpolates points (open: n + 1 >= 3 points; closed: n >= 3, knots with
   * the closing one) with knots x_i = knots[i] via (34). Open curves take
   * s' and s'' at each end from the polynomial through the six (or fewer)
   * end points.
   */
  static TensionQuinticSpline interpolate(const std::vector<Vec3>& points,
    const std::vector<double>& knots, const QuinticParameters& parameters, bool closed);

  Derivatives evaluateOnSpan(int span, double x, int order) const override;

  /// Derivatives of the parametric form C(t) = (X(t), Y(t)) on a span, t local in [0,1].
  std::pair<std::array<double, 5>, Derivatives> parametricDerivatives(
    int span, double tau, int order) const;

  const QuinticParameters& parameters() const { return this->Parameters; }
  const std::vector<double>& abscissae() const { return this->Xi; }
  const std::vector<Vec3>& controlPoints() const { return this->Points; }
  int knotRecoveries() const { return this->Recoveries; }

private:
  TensionQuinticSpline(std::vector<double> knots, bool closed);

  QuinticParameters Parameters;
  std::vector<double> Xi;
  std::vector<Vec3> Points;
  int Recoveries = 0;
  /// Per span: the Bezier ordinates of X and of C in the local parameter.
  std::vector<std::array<double, 6>> XBezier;
  std::vector<std::array<Vec3, 6>> CBezier;
};
} // namespace shapesplines

#endif
