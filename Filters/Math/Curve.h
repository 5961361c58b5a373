// ShapeSplines math core: the one curve interface every spline family implements.
#ifndef shapesplines_Curve_h
#define shapesplines_Curve_h

#include "SparseSolve.h"

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace shapesplines
{
using Vec3 = Eigen::Vector3d;

/// Position and derivatives 0..MaxDerivativeOrder at one parameter value.
constexpr int MaxDerivativeOrder = 4;
using Derivatives = std::array<Vec3, MaxDerivativeOrder + 1>;
/// Values 0..4 of a scalar function (a basis function) and its derivatives at one point.
using Jet = std::array<double, MaxDerivativeOrder + 1>;

/// A family's shape parameter per span (degree, tension...), which the filters
/// write out generically: a point array Name and a cell array Max<Name> or Min<Name>.
struct SpanParameter
{
  std::string Name;
  std::vector<double> Values; ///< one per span
  bool CellSummaryIsMaximum = true;
};

/// (1 - v)^e for v in [0, 1]: through log1p(-v) where 1 - v would round
/// (v < 1/2), so that degrees and exponents in the hundreds do not multiply
/// that rounding.
inline double complementPower(double v, double e)
{
  return v < 0.5 ? std::exp(e * std::log1p(-v)) : std::pow(1.0 - v, e);
}

/// Derivatives in a span's local variable t = (x - x_j) / h made derivatives
/// in x: the m-th divided by h^m, m = 1..order.
template <class Values>
void scaleDerivatives(Values& values, double h, int order)
{
  double scale = 1.0;
  for (int m = 1; m <= order; ++m)
  {
    scale /= h;
    values[m] *= scale;
  }
}

/// The power-form coefficients a_k (p(u) = sum a_k u^k) of the Bezier curve
/// with points b on [0, 1]: a_k = C(n, k) sum_i (-1)^(k-i) C(k, i) b_i, the
/// k-th forward difference of the points times C(n, k).
template <typename T, size_t Points>
std::array<T, Points> bezierToPower(const std::array<T, Points>& b)
{
  constexpr int degree = static_cast<int>(Points) - 1;
  std::array<T, Points> a = b;
  // Forward differences in place: a[k] becomes the k-th difference of b at 0.
  for (int level = 1; level <= degree; ++level)
  {
    for (int j = degree; j >= level; --j)
    {
      a[j] = a[j] - a[j - 1];
    }
  }
  double binomial = 1.0; // C(degree, k)
  for (int k = 1; k <= degree; ++k)
  {
    binomial = binomial * (degree - k + 1) / k;
    a[k] = binomial * a[k];
  }
  return a;
}

namespace detail
{
/**
 * The Taylor shift of powerDerivatives on Width coordinates from the first
 * (Width 2: a pair in one SSE register), to a fixed order: every loop bound
 * known, so the coefficients stay in registers.
 */
template <int Order, int Width, typename T, size_t Points>
void taylorShift(const std::array<T, Points>& a, int first, double u, T* out)
{
  using Lane = std::conditional_t<Width == 1, double, Eigen::Array<double, Width, 1>>;
  constexpr int degree = static_cast<int>(Points) - 1;
  auto load = [&](const T& v) -> Lane {
    if constexpr (std::is_arithmetic_v<T>)
    {
      return v;
    }
    else if constexpr (Width == 1)
    {
      return v[first];
    }
    else
    {
      return v.template segment<Width>(first).array();
    }
  };
  std::array<Lane, Points> c;
  for (size_t k = 0; k < Points; ++k)
  {
    c[k] = load(a[k]);
  }
  double factorial = 1.0;
  for (int r = 0; r <= Order; ++r)
  {
    for (int k = degree - 1; k >= r; --k)
    {
      c[k] = c[k] + u * c[k + 1];
    }
    factorial *= r > 0 ? r : 1;
    if constexpr (std::is_arithmetic_v<T>)
    {
      out[r] = factorial * c[r];
    }
    else if constexpr (Width == 1)
    {
      out[r][first] = factorial * c[r];
    }
    else
    {
      out[r].template segment<Width>(first) = (factorial * c[r]).matrix();
    }
  }
}

template <int Width, typename T, size_t Points>
void taylorShift(const std::array<T, Points>& a, int top, int first, double u, T* out)
{
  constexpr int degree = static_cast<int>(Points) - 1;
  switch (top)
  {
    case 0:
      taylorShift<0, Width>(a, first, u, out);
      break;
    case 1:
      taylorShift<1, Width>(a, first, u, out);
      break;
    case 2:
      taylorShift<std::min(2, degree), Width>(a, first, u, out);
      break;
    case 3:
      taylorShift<std::min(3, degree), Width>(a, first, u, out);
      break;
    default:
      taylorShift<std::min(MaxDerivativeOrder, degree), Width>(a, first, u, out);
      break;
  }
}
} // namespace detail

/**
 * Derivatives 0..order of the polynomial sum a_k u^k (a from bezierToPower)
 * at u, by repeated Horner steps (a Taylor shift: after step r, a[r] holds
 * p^(r)(u) / r!). Fewer operations than a de Casteljau pass for the curves
 * that evaluate the same span many times. Orders above the degree, or above
 * MaxDerivativeOrder, are left zero. T is double or a fixed-size Eigen vector,
 * shifted two coordinates at a time (the same arithmetic as on whole vectors,
 * without their round trips through memory).
 */
template <typename T, size_t Points>
std::array<T, MaxDerivativeOrder + 1> powerDerivatives(
  const std::array<T, Points>& a, double u, int order, const T& zero)
{
  constexpr int degree = static_cast<int>(Points) - 1;
  std::array<T, MaxDerivativeOrder + 1> out;
  out.fill(zero);
  const int top = std::min({ order, degree, MaxDerivativeOrder });
  if constexpr (std::is_arithmetic_v<T>)
  {
    detail::taylorShift<1>(a, top, 0, u, out.data());
  }
  else
  {
    constexpr int coordinates = static_cast<int>(T::RowsAtCompileTime);
    for (int c = 0; c + 1 < coordinates; c += 2)
    {
      detail::taylorShift<2>(a, top, c, u, out.data());
    }
    if constexpr (coordinates % 2 == 1)
    {
      detail::taylorShift<1>(a, top, coordinates - 1, u, out.data());
    }
  }
  return out;
}

/**
 * A piecewise curve s(t) on knots t_0 < t_1 < ... < t_n (n spans). Families
 * implement evaluateOnSpan(); everything else (span search, sampling, frames,
 * curvature, torsion, shape audit) is written once against this interface.
 * A closed curve has s(t_0) = s(t_n) and its parameter wraps around.
 */
class Curve
{
public:
  virtual ~Curve() = default;

  const std::vector<double>& knots() const { return Knots; }
  int numberOfSpans() const { return static_cast<int>(Knots.size()) - 1; }
  bool isClosed() const { return Closed; }
  double firstParameter() const { return Knots.front(); }
  double lastParameter() const { return Knots.back(); }

  /// Span containing t (binary search; t outside the knots clamps to the end spans).
  int findSpan(double t) const;

  /// Derivatives 0..order (order <= MaxDerivativeOrder) at t; entries above order are
  /// zero. A closed curve's parameter wraps around (t_n is t_0, on the first span).
  Derivatives evaluate(double t, int order = MaxDerivativeOrder) const;

  /// Same, with the span already known (t may lie on either end of it).
  virtual Derivatives evaluateOnSpan(int span, double t, int order) const = 0;

  /// Arc length between parameters a <= b of one span: the 8-point
  /// Gauss-Legendre rule on the speed |s'(t)|. A family whose speed is
  /// smoother in a variable of its own integrates in that one instead.
  virtual double arcLengthOnSpan(int span, double a, double b) const;

  /// The shape parameters chosen per span; none for a family without any.
  virtual std::vector<SpanParameter> spanParameters() const { return {}; }

  /// Estimated condition number of the linear systems solved to build the
  /// curve (their largest; 1 when none was solved), estimated on the first
  /// call: above UntrustedCondition (SparseSolve.h) rounding can spoil the curve.
  virtual double conditionEstimate() const { return Condition.value(); }

protected:
  Curve(std::vector<double> knots, bool closed);

  std::vector<double> Knots;
  bool Closed = false;
  DeferredCondition Condition;
};
/**
 * The spans first..first + spans - 1 of another open curve, as a curve of
 * their own: an approximation fitted on knots beyond its data's ends (see
 * extendForApproximation) keeps only its data's stretch.
 */
class TrimmedCurve final : public Curve
{
public:
  TrimmedCurve(std::unique_ptr<Curve> whole, int first, int spans);

  Derivatives evaluateOnSpan(int span, double t, int order) const override;
  double arcLengthOnSpan(int span, double a, double b) const override;
  std::vector<SpanParameter> spanParameters() const override;
  double conditionEstimate() const override;
  /// The curve the spans come from.
  const Curve& whole() const { return *this->Whole; }

private:
  std::unique_ptr<Curve> Whole;
  int First;
};

/// The 8-point Gauss-Legendre rule (exact for polynomials of degree 15) for
/// the integral of f over [a, b].
template <class F>
double gaussLegendre(const F& f, double a, double b)
{
  constexpr std::array<double, 4> nodes = { 0.1834346424956498, 0.5255324099163290,
    0.7966664774136267, 0.9602898564975363 };
  constexpr std::array<double, 4> weights = { 0.3626837833783620, 0.3137066458778873,
    0.2223810344533745, 0.1012285362903763 };
  const double mid = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  double sum = 0.0;
  for (size_t k = 0; k < nodes.size(); ++k)
  {
    for (const double sign : { -1.0, 1.0 })
    {
      sum += weights[k] * f(mid + sign * half * nodes[k]);
    }
  }
  return half * sum;
}

/// The spacings h_i = knots[i + 1] - knots[i]; throws std::invalid_argument
/// "<family>: knots must increase strictly" unless each is positive and finite.
std::vector<double> knotSpacings(const std::vector<double>& knots, const std::string& family);

/// Derivatives 1, 2 and 3 (in the knot parameter; zero above the degree) at
/// one end of an open line of the polynomial through its `count` points
/// nearest that end (all of them if fewer): the end conditions that converge
/// at the order of a spline of degree count - 1.
std::array<Vec3, 3> polynomialEndDerivatives(
  const std::vector<Vec3>& points, const std::vector<double>& knots, bool start, int count);
} // namespace shapesplines

#endif
