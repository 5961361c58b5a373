// ShapeSplines math core: the classical C2 cubic interpolating spline.
#ifndef shapesplines_CubicSpline_h
#define shapesplines_CubicSpline_h

#include "Curve.h"

#include <optional>
#include <utility>
#include <vector>

namespace shapesplines
{
enum class CubicEndCondition
{
  Natural,  ///< s'' = 0 at both ends
  NotAKnot, ///< s''' continuous at the second and last-but-one knots
  Clamped   ///< s' given at both ends (default: the derivative of the end parabolas)
};

/**
 * The C2 cubic spline through points I_i at knots t_i, stored per span in
 * power form. It is the baseline the shape-preserving families are compared
 * with and the reduction target of the generalized cubic family.
 */
class CubicSpline final : public Curve
{
public:
  /// Clamped end derivatives (start, end) with respect to t.
  using EndDerivatives = std::pair<Vec3, Vec3>;

  /**
   * Interpolates points (n >= 2; closed: n >= 3 distinct points, periodic ends).
   * knots has n entries (open) or n + 1 (closed, the last closing the seam span).
   * With fewer than four points a not-a-knot spline is the interpolating
   * parabola (three points) or the straight segment (two points).
   */
  static CubicSpline interpolate(const std::vector<Vec3>& points, const std::vector<double>& knots,
    bool closed, CubicEndCondition ends = CubicEndCondition::NotAKnot,
    const std::optional<EndDerivatives>& clamped = std::nullopt);

  /// Derivatives at the ends of the parabolas through the first and last three points.
  static EndDerivatives parabolaEndDerivatives(
    const std::vector<Vec3>& points, const std::vector<double>& knots);

  Derivatives evaluateOnSpan(int span, double t, int order) const override;

private:
  CubicSpline(std::vector<double> knots, bool closed);

  /// Per span: s(t) = C[0] + C[1] d + C[2] d^2 + C[3] d^3 with d = t - t_span.
  std::vector<std::array<Vec3, 4>> Coefficients;
};
} // namespace shapesplines

#endif
