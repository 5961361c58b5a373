#include "QQRSpline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

namespace shapesplines
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

void checkExponent(double a, const char* what)
{
  if (!(a >= 2.0) || !std::isfinite(a))
  {
    throw std::invalid_argument(std::string("qqr: shape parameter ") + what +
      " must be a finite number >= 2 (paper 003, Definition 1), got " + std::to_string(a));
  }
}

/**
 * d^m/dx^m of y^p, y = 1 - x, m = 0..order, from x and xc = 1 - x (both given:
 * whichever is the smaller is exact). y^(p-m) is exp((p-m) log1p(-x)) for
 * x < 1/2, so that the rounding of 1 - x near x = 0 does not cost p ulps,
 * and pow(xc, p-m) beyond. A falling factorial p (p-1)...(p-m+1) of zero
 * (integer p < m) gives an exact 0; at y = 0 a negative exponent p - m gives
 * +-inf (the derivative is unbounded there), a zero one the factorial.
 */
Jet complementPow(double x, double xc, double p, int order)
{
  const double logY = x < 0.5 ? std::log1p(-x) : 0.0;
  auto power = [&](double e) {
    if (x < 0.5)
    {
      return std::exp(e * logY);
    }
    if (xc > 0.0 && e >= 1.0 && e <= 16.0 && e == std::floor(e))
    {
      // Small integer exponents (alpha = beta = 4 by default) without pow:
      // xc <= 1/2 is exact, so each product costs an ulp of a value <= 2^-e.
      double product = xc;
      for (int k = 1; k < static_cast<int>(e); ++k)
      {
        product *= xc;
      }
      return product;
    }
    if (xc > 0.0)
    {
      return std::pow(xc, e);
    }
    return e > 0.0 ? 0.0 : Infinity;
  };
  // y^(p-m) for the derivatives: the lowest power by exp or pow, the others
  // multiplied up by y (a rounding each, a few ulps: y >= 1/2 here or exact),
  // so two exponentials instead of one per order; the value on its own.
  const double y = x < 0.5 ? 1.0 - x : xc;
  std::array<double, MaxDerivativeOrder + 1> powers{};
  powers[0] = power(p);
  if (order >= 1)
  {
    powers[order] = power(p - order);
    const bool multiplyUp = std::isfinite(powers[order]) && y > 0.0;
    for (int m = order - 1; m >= 1; --m)
    {
      powers[m] = multiplyUp ? powers[m + 1] * y : power(p - m);
    }
  }
  Jet out{};
  double factor = 1.0;
  for (int m = 0; m <= order; ++m)
  {
    if (factor == 0.0)
    {
      break; // this and every higher derivative vanish identically
    }
    // At y = 0 a negative exponent gives +-inf (powers[m] is inf), a zero one the factorial.
    const double value = p - m == 0.0 ? factor : factor * powers[m];
    out[m] = m % 2 == 0 ? value : -value; // d/dx = -d/dy
    factor *= p - m;
  }
  return out;
}

/// Derivatives in x of x (1 - x)^p (xc = 1 - x): x f^(m) + m f^(m-1), f = (1 - x)^p.
Jet xTimesComplementPow(double x, double xc, double p, int order)
{
  const Jet f = complementPow(x, xc, p, order);
  Jet out{};
  for (int m = 0; m <= order; ++m)
  {
    const double main = x * f[m];
    // At x = 1 both terms can be unbounded with opposite signs: the first,
    // of the more negative exponent, dominates.
    out[m] = m == 0 || std::isinf(main) ? main : main + m * f[m - 1];
  }
  return out;
}

/// log of (1 - x)^c (1 + c x) by its series for c x < 1/4 (no cancellation).
double tailLogSeries(double x, double c)
{
  // sum_k>=2 x^k / k ((-1)^(k+1) c^k - c); the k = 1 terms cancel exactly.
  double sum = 0.0;
  double xk = x;      // x^k
  double cxk = c * x; // (c x)^k
  for (int k = 2; k < 64; ++k)
  {
    xk *= x;
    cxk *= c * x;
    const double term = ((k % 2 == 1 ? cxk : -cxk) - c * xk) / k;
    sum += term;
    // (Not on the term itself: for c = 1 the odd terms vanish exactly.)
    if (cxk + c * xk <= 1e-18 * std::abs(sum))
    {
      break;
    }
  }
  return sum;
}

/// The pieces of one end of the basis at distance x from it (xc = 1 - x) with
/// exponent a: (1-x)^a, a x (1-x)^(a-1) and G(x; a), derivatives in x.
struct EndJets
{
  Jet Power, Linear, Tail;
};

/// tail false: Tail left 0 (what a curve's evaluation, which never needs A2, skips).
EndJets endJets(double x, double xc, double a, int order, bool tail = true)
{
  EndJets jets;
  jets.Power = complementPow(x, xc, a, order);
  jets.Linear = xTimesComplementPow(x, xc, a - 1.0, order);
  for (double& value : jets.Linear)
  {
    value *= a;
  }
  if (!tail)
  {
    return jets;
  }
  // G(x) = 1 - (1-x)^c (1 + c x), c = a - 1; G' = a (a - 1) x (1 - x)^(a-2).
  const double c = a - 1.0;
  jets.Tail = {};
  if (order >= 1)
  {
    const Jet integrand = xTimesComplementPow(x, xc, a - 2.0, order - 1);
    for (int m = 1; m <= order; ++m)
    {
      jets.Tail[m] = a * c * integrand[m - 1];
    }
  }
  if (c * x < 0.25)
  {
    jets.Tail[0] = -std::expm1(tailLogSeries(x, c));
  }
  else
  {
    // At most ~32 ulps lost here: G >= ~c (c + 1) x^2 / 2 >= 1/32 relative to 1.
    jets.Tail[0] = 1.0 - complementPow(x, xc, c, 0)[0] * (1.0 + c * x);
  }
  return jets;
}

/// c * v with 0 * inf = 0: a coefficient that is exactly zero removes the term.
double times(double c, double v)
{
  return c == 0.0 ? 0.0 : c * v;
}

std::array<Jet, 5> basis(double t, double alpha, double beta, int order, bool withA2)
{
  checkExponent(alpha, "alpha");
  checkExponent(beta, "beta");
  order = std::clamp(order, 0, 4);
  t = std::clamp(t, 0.0, 1.0);
  const double s = 1.0 - t;
  const EndJets left = endJets(t, s, alpha, order, withA2);
  const EndJets right = endJets(s, t, beta, order, withA2); // derivatives in s = 1 - t
  std::array<Jet, 5> a{};
  for (int m = 0; m <= order; ++m)
  {
    const double sign = m % 2 == 0 ? 1.0 : -1.0; // d/dt = -d/ds
    a[0][m] = left.Power[m];
    a[1][m] = left.Linear[m];
    a[3][m] = sign * right.Linear[m];
    a[4][m] = sign * right.Power[m];
    // A2 = G(t; alpha) + G(s; beta) - 1; its derivatives from the two tails.
    a[2][m] = left.Tail[m] + sign * right.Tail[m];
  }
  // The value from the half where the other side's complement is small:
  // G(t; alpha) - (A3 + A4) for t <= 1/2, G(s; beta) - (A0 + A1) beyond.
  a[2][0] = t <= 0.5 ? left.Tail[0] - (a[3][0] + a[4][0]) : right.Tail[0] - (a[0][0] + a[1][0]);
  return a;
}
} // namespace

Jet qqrTail(double t, double a, int order)
{
  checkExponent(a, "a");
  return endJets(t, 1.0 - t, a, std::clamp(order, 0, 4)).Tail;
}

std::array<Jet, 5> qqrBasis(double t, double alpha, double beta, int order)
{
  return basis(t, alpha, beta, order, true);
}

QQRLocalParameters cubicLocalParameters(const std::vector<double>& h)
{
  const int m = static_cast<int>(h.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  QQRLocalParameters local{ std::vector<double>(m, nan), std::vector<double>(m, nan),
    std::vector<double>(m, nan) };
  for (int i = 0; i < m; ++i)
  {
    if (i + 2 < m)
    {
      const double sum = h[i] + h[i + 1] + h[i + 2];
      local.X[i] = h[i] / (4.0 * sum);
      local.Z[i] = (2.0 * h[i] + h[i + 1]) / (2.0 * sum);
    }
    if (i >= 1 && i + 1 < m)
    {
      local.Y[i] = h[i + 1] / (4.0 * (h[i - 1] + h[i] + h[i + 1]));
    }
  }
  return local;
}

QQRBSplineBasis::QQRBSplineBasis(
  std::vector<double> knots, double alpha, double beta, QQRLocalParameters local)
  : Knots(std::move(knots))
  , Alpha(alpha)
  , Beta(beta)
  , Local(std::move(local))
{
  checkExponent(alpha, "alpha");
  checkExponent(beta, "beta");
  const int m = static_cast<int>(this->Knots.size()) - 1;
  if (m < 4)
  {
    throw std::invalid_argument("qqr B-spline basis: needs at least 5 knots (one basis function)");
  }
  if (static_cast<int>(this->Local.X.size()) != m || static_cast<int>(this->Local.Y.size()) != m ||
    static_cast<int>(this->Local.Z.size()) != m)
  {
    throw std::invalid_argument(
      "qqr B-spline basis: x, y and z need one value per knot interval (" + std::to_string(m) + ")");
  }
  this->H.resize(m);
  for (int i = 0; i < m; ++i)
  {
    this->H[i] = this->Knots[i + 1] - this->Knots[i];
    if (!(this->H[i] > 0.0))
    {
      throw std::invalid_argument("qqr B-spline basis: knots must increase strictly");
    }
  }
}

double QQRBSplineBasis::mu(int i) const
{
  return this->H[i] / (this->H[i] + this->H[i + 1]);
}

double QQRBSplineBasis::upsilon(int i) const
{
  return this->H[i + 1] / (this->H[i] + this->H[i + 1]);
}

double QQRBSplineBasis::rho(int i) const
{
  const auto& [x, y, z] = this->Local;
  const double mu1 = this->mu(i + 1), up1 = this->upsilon(i + 1);
  return mu1 * mu1 * (1.0 - z[i + 1]) + up1 * up1 * z[i] + 2.0 * mu1 * up1 * (1.0 - x[i + 1] - y[i + 1]);
}

Jet QQRBSplineBasis::piece(int i, int piece, double t, int order) const
{
  if (i < 0 || i >= this->size() || piece < 0 || piece > 3)
  {
    throw std::out_of_range("qqr B-spline basis: no such function or piece");
  }
  const auto& [x, y, z] = this->Local;
  // Coefficients of A_0..A_4 in B_{i,piece}, section 3.1.
  std::array<double, 5> c{};
  const double mu0 = this->mu(i), up0 = this->upsilon(i);
  switch (piece)
  {
    case 0:
      c = { 0.0, 0.0, 0.0, mu0 * x[i], mu0 * (mu0 * z[i] + 2.0 * up0 * x[i]) };
      break;
    case 1:
    {
      const double mu1 = this->mu(i + 1), up1 = this->upsilon(i + 1);
      c = { mu0 * (mu0 * z[i] + 2.0 * up0 * x[i]), mu0 * z[i] + up0 * x[i], z[i],
        mu1 * (1.0 - x[i + 1] - y[i + 1]) + up1 * z[i], this->rho(i) };
      break;
    }
    case 2:
    {
      const double mu1 = this->mu(i + 1), up1 = this->upsilon(i + 1);
      const double mu2 = this->mu(i + 2), up2 = this->upsilon(i + 2);
      c = { this->rho(i), mu1 * (1.0 - z[i + 1]) + up1 * (1.0 - x[i + 1] - y[i + 1]),
        1.0 - z[i + 1], mu2 * y[i + 2] + up2 * (1.0 - z[i + 1]),
        up2 * (2.0 * mu2 * y[i + 2] + up2 * (1.0 - z[i + 1])) };
      break;
    }
    default:
    {
      const double mu2 = this->mu(i + 2), up2 = this->upsilon(i + 2);
      c = { up2 * (2.0 * mu2 * y[i + 2] + up2 * (1.0 - z[i + 1])), up2 * y[i + 2], 0.0, 0.0, 0.0 };
    }
  }
  const auto a = qqrBasis(t, this->Alpha, this->Beta, order);
  Jet out{};
  for (int m = 0; m <= std::clamp(order, 0, 4); ++m)
  {
    for (int j = 0; j < 5; ++j)
    {
      out[m] += times(c[j], a[j][m]);
    }
  }
  return out;
}

Jet QQRBSplineBasis::value(int i, double u, int order, int span) const
{
  const int m = static_cast<int>(this->H.size());
  if (span < 0)
  {
    const auto it = std::upper_bound(this->Knots.begin(), this->Knots.end(), u);
    span = std::clamp(static_cast<int>(it - this->Knots.begin()) - 1, 0, m - 1);
  }
  if (span < i || span > i + 3)
  {
    return Jet{};
  }
  const double h = this->H[span];
  Jet out = this->piece(i, span - i, (u - this->Knots[span]) / h, order);
  double scale = 1.0;
  for (double& value : out)
  {
    value *= scale;
    scale /= h;
  }
  return out;
}

QQRSpline::QQRSpline(std::vector<double> knots, bool closed)
  : Curve(std::move(knots), closed)
{
}

namespace
{
std::vector<std::array<double, 2>> globalExponents(int spans, double alpha, double beta)
{
  checkExponent(alpha, "alpha");
  checkExponent(beta, "beta");
  return std::vector<std::array<double, 2>>(spans, { alpha, beta });
}

std::vector<std::array<double, 2>> knotExponentsToSpans(
  const std::vector<double>& kappa, int points, bool closed)
{
  if (static_cast<int>(kappa.size()) != points)
  {
    throw std::invalid_argument("qqr: one exponent per point expected, got " +
      std::to_string(kappa.size()) + " for " + std::to_string(points) + " points");
  }
  for (const double k : kappa)
  {
    checkExponent(k, "alpha = beta at a knot");
  }
  const int spans = closed ? points : points - 1;
  std::vector<std::array<double, 2>> exponents(std::max(spans, 0));
  for (int k = 0; k < spans; ++k)
  {
    exponents[k] = { kappa[k], kappa[(k + 1) % points] };
  }
  return exponents;
}
} // namespace

QQRSpline QQRSpline::approximate(const std::vector<Vec3>& points, const std::vector<double>& knots,
  bool closed, double alpha, double beta, const Local& local, const QQRKnotShape& knotShape)
{
  const int spans = closed ? static_cast<int>(points.size()) : static_cast<int>(points.size()) - 1;
  return build(points, knots, closed, globalExponents(spans, alpha, beta), local, knotShape, false);
}

QQRSpline QQRSpline::approximate(const std::vector<Vec3>& points, const std::vector<double>& knots,
  bool closed, const std::vector<double>& knotExponents, const Local& local)
{
  return approximate(points, knots, closed, knotExponents, local, QQRKnotShape{});
}

QQRSpline QQRSpline::approximate(const std::vector<Vec3>& points, const std::vector<double>& knots,
  bool closed, const std::vector<double>& knotExponents, const Local& local,
  const QQRKnotShape& knotShape)
{
  return build(points, knots, closed,
    knotExponentsToSpans(knotExponents, static_cast<int>(points.size()), closed), local, knotShape,
    false);
}

QQRSpline QQRSpline::interpolate(const std::vector<Vec3>& points, const std::vector<double>& knots,
  bool closed, double alpha, double beta, const Local& local, const QQRKnotShape& knotShape)
{
  const int spans = closed ? static_cast<int>(points.size()) : static_cast<int>(points.size()) - 1;
  return build(points, knots, closed, globalExponents(spans, alpha, beta), local, knotShape, true);
}

QQRSpline QQRSpline::interpolate(const std::vector<Vec3>& points, const std::vector<double>& knots,
  bool closed, const std::vector<double>& knotExponents, const Local& local)
{
  return interpolate(points, knots, closed, knotExponents, local, QQRKnotShape{});
}

QQRSpline QQRSpline::interpolate(const std::vector<Vec3>& points, const std::vector<double>& knots,
  bool closed, const std::vector<double>& knotExponents, const Local& local,
  const QQRKnotShape& knotShape)
{
  return build(points, knots, closed,
    knotExponentsToSpans(knotExponents, static_cast<int>(points.size()), closed), local, knotShape,
    true);
}

QQRSpline QQRSpline::build(const std::vector<Vec3>& points, const std::vector<double>& knots,
  bool closed, std::vector<std::array<double, 2>> exponents, const Local& local,
  const QQRKnotShape& knotShape, bool interpolate)
{
  const int n = static_cast<int>(points.size());
  const int spans = closed ? n : n - 1;
  if (n < 2 || (closed && n < 3) || static_cast<int>(knots.size()) != spans + 1 ||
    static_cast<int>(exponents.size()) != spans)
  {
    throw std::invalid_argument("qqr: at least 2 points (3 closed) and one knot per point (plus "
                                "the closing knot of a closed curve) expected");
  }
  std::vector<double> dh(spans);
  for (int k = 0; k < spans; ++k)
  {
    dh[k] = knots[k + 1] - knots[k];
    if (!(dh[k] > 0.0) || !std::isfinite(dh[k]))
    {
      throw std::invalid_argument("qqr: knots must increase strictly");
    }
  }
  for (const double value : { local.X, local.Y, local.Z })
  {
    if (std::isinf(value))
    {
      throw std::invalid_argument("qqr: local shape parameters must be finite (or NaN: the paper's)");
    }
  }
  for (const auto* values : { &knotShape.X, &knotShape.Y, &knotShape.Z })
  {
    if (!values->empty() && static_cast<int>(values->size()) != n)
    {
      throw std::invalid_argument("qqr: local shape parameters per point need one value per point (" +
        std::to_string(n) + "), got " + std::to_string(values->size()));
    }
    if (std::any_of(values->begin(), values->end(), [](double v) { return std::isinf(v); }))
    {
      throw std::invalid_argument("qqr: local shape parameters must be finite (or NaN: the paper's)");
    }
  }
  // The paper's indices: knot u_i is t_{i-2}, h_i = dh_{i-2}, P_j = D_j.
  auto wrap = [](int j, int period) { return ((j % period) + period) % period; };
  auto H = [&](int i) {
    int j = i - 2;
    if (closed)
    {
      return dh[wrap(j, spans)];
    }
    // Beyond the ends the intervals mirror the ones inside (decision).
    if (j < 0)
    {
      j = -1 - j;
    }
    if (j >= spans)
    {
      j = 2 * spans - 1 - j;
    }
    return dh[std::clamp(j, 0, spans - 1)];
  };
  auto P = [&](int j) -> const Vec3& {
    return closed ? points[wrap(j, n)] : points[std::clamp(j, 0, n - 1)]; // doubled ends
  };
  auto mu = [&](int i) { return H(i) / (H(i) + H(i + 1)); };
  auto ups = [&](int i) { return H(i + 1) / (H(i) + H(i + 1)); };
  // The value per point at the paper's index i (point i - 1, QQRKnotShape), or NaN.
  auto perPoint = [&](const std::vector<double>& values, int i) {
    int j = i - 1;
    if (closed)
    {
      j = wrap(j, n);
    }
    return values.empty() || j < 0 || j >= n ? std::numeric_limits<double>::quiet_NaN() : values[j];
  };
  auto Z = [&](int i) {
    const double z = perPoint(knotShape.Z, i);
    if (!std::isnan(z))
    {
      return z;
    }
    return std::isnan(local.Z) ? (2.0 * H(i) + H(i + 1)) / (2.0 * (H(i) + H(i + 1) + H(i + 2)))
                               : local.Z;
  };
  auto X = [&](int i) {
    if (interpolate)
    {
      return -H(i) * Z(i) / (2.0 * H(i + 1)); // (3.18) with its missing 1/2
    }
    const double x = perPoint(knotShape.X, i);
    if (!std::isnan(x))
    {
      return x;
    }
    return std::isnan(local.X) ? H(i) / (4.0 * (H(i) + H(i + 1) + H(i + 2))) : local.X;
  };
  auto Y = [&](int i) {
    if (interpolate)
    {
      return -H(i + 1) * (1.0 - Z(i - 1)) / (2.0 * H(i)); // (3.18)
    }
    const double y = perPoint(knotShape.Y, i);
    if (!std::isnan(y))
    {
      return y;
    }
    return std::isnan(local.Y) ? H(i + 1) / (4.0 * (H(i - 1) + H(i) + H(i + 1))) : local.Y;
  };
  // R(i) = R_{i-1,i}, S(i) = S_{i-1}, T(i) = T_{i-1} of section 3.4.
  auto R = [&](int i) -> Vec3 { return (1.0 - Z(i)) * P(i - 1) + Z(i) * P(i); };
  auto S = [&](int i) -> Vec3 {
    const double x = X(i), y = Y(i);
    return y * P(i - 2) + (1.0 - x - y) * P(i - 1) + x * P(i);
  };
  auto T = [&](int i) -> Vec3 {
    const double m = mu(i), u = ups(i);
    return u * u * R(i - 1) + 2.0 * u * m * S(i) + m * m * R(i);
  };

  QQRSpline spline(knots, closed);
  spline.Exponents = std::move(exponents);
  for (auto* values : { &spline.KnotShape.X, &spline.KnotShape.Y, &spline.KnotShape.Z })
  {
    values->resize(n);
  }
  for (int j = 0; j < n; ++j)
  {
    spline.KnotShape.X[j] = X(j + 1);
    spline.KnotShape.Y[j] = Y(j + 1);
    spline.KnotShape.Z[j] = Z(j + 1);
  }
  spline.Bezier.resize(spans);
  for (int k = 0; k < spans; ++k)
  {
    const int i = k + 2;
    const Vec3 middle = R(i - 1);
    spline.Bezier[k] = { T(i - 1), ups(i - 1) * S(i - 1) + mu(i - 1) * middle, middle,
      ups(i) * middle + mu(i) * S(i), T(i) };
  }
  return spline;
}

Derivatives QQRSpline::evaluateOnSpan(int span, double x, int order) const
{
  order = std::clamp(order, 0, MaxDerivativeOrder);
  const double h = this->Knots[span + 1] - this->Knots[span];
  const double t = std::clamp((x - this->Knots[span]) / h, 0.0, 1.0);
  const auto& [alpha, beta] = this->Exponents[span];
  const auto& e = this->Bezier[span];
  Derivatives out; // derivatives in t
  if (alpha == 4.0 && beta == 4.0)
  {
    // The qqr basis at alpha = beta = 4 is the quartic Bernstein basis
    // (A2 = 6 t^2 (1-t)^2): a quartic Bezier span, no powers to take.
    out = bezierDerivatives(e, t, order, Vec3(Vec3::Zero()));
  }
  else
  {
    // (2.10): Q = E2 + sum_{j != 2} A_j (E_j - E2); A2 is not needed and its
    // derivatives (sums of the others) never enter.
    const auto a = basis(t, alpha, beta, order, false);
    constexpr std::array<int, 4> outer = { 0, 1, 3, 4 };
    std::array<Vec3, 4> offsets;
    for (int i = 0; i < 4; ++i)
    {
      offsets[i] = e[outer[i]] - e[2];
    }
    out.fill(Vec3::Zero());
    for (int m = 0; m <= order; ++m)
    {
      for (int i = 0; i < 4; ++i)
      {
        for (int c = 0; c < 3; ++c)
        {
          out[m][c] += times(offsets[i][c], a[outer[i]][m]);
        }
      }
    }
    out[0] += e[2];
  }
  double scale = 1.0; // h^-m: derivatives with respect to the curve parameter
  for (int m = 1; m <= order; ++m)
  {
    scale /= h;
    out[m] *= scale;
  }
  return out;
}

std::vector<SpanParameter> QQRSpline::spanParameters() const
{
  std::vector<double> alpha(this->Exponents.size());
  std::transform(this->Exponents.begin(), this->Exponents.end(), alpha.begin(),
    [](const std::array<double, 2>& ab) { return std::max(ab[0], ab[1]); });
  return { { "Alpha", alpha, true } };
}

double raisedQQRExponent(double alpha, double maxAlpha)
{
  return std::min(maxAlpha, std::max(alpha + 1.0, 1.5 * alpha));
}

double QQRSpline::speedRatio(int span) const
{
  const auto& e = this->Bezier[span];
  double polygon = 0.0;
  for (int j = 0; j < 4; ++j)
  {
    polygon += (e[j + 1] - e[j]).norm();
  }
  if (!(polygon > 0.0))
  {
    return 0.0;
  }
  const double h = this->Knots[span + 1] - this->Knots[span];
  double slowest = std::numeric_limits<double>::infinity();
  constexpr int Samples = 64;
  for (int s = 0; s <= Samples; ++s)
  {
    const double x = this->Knots[span] + h * s / Samples;
    slowest = std::min(slowest, this->evaluateOnSpan(span, x, 1)[1].norm() * h / polygon);
  }
  return slowest;
}

namespace
{
/// One step of the automatic mode on a local parameter: half the way to its
/// target, the target itself once within 1/1024 of it.
double halfwayTo(double value, double target)
{
  const double next = 0.5 * (value + target);
  return std::abs(next - target) < 1.0 / 1024.0 ? target : next;
}

/// An exponent lowered by one step of the automatic mode: half the way to 3
/// (where the basis turns cubic), not below minAlpha.
double loweredQQRExponent(double alpha, double minAlpha)
{
  return std::max(minAlpha, 3.0 + 0.5 * (alpha - 3.0));
}

/// The curve of the options' mode with exponents and local parameters per point.
std::unique_ptr<QQRSpline> qqrCurve(const QQROptions& options, const CleanPolyline& data,
  const std::vector<double>& knots, const std::vector<double>& exponents,
  const QQRKnotShape& knotShape)
{
  const QQRSpline::Local local{ options.X, options.Y, options.Z };
  return std::make_unique<QQRSpline>(options.Interpolate
      ? QQRSpline::interpolate(data.Points, knots, data.Closed, exponents, local, knotShape)
      : QQRSpline::approximate(data.Points, knots, data.Closed, exponents, local, knotShape));
}

/// One qqr fit (qqrBuilder's curve) in the orientation the context gives.
BuiltCurve qqrFit(const QQROptions& options, const FitContext& context)
{
  const CleanPolyline& data = context.Data;
  const bool closed = data.Closed;
  const int n = static_cast<int>(data.Points.size());
  const int spans = data.numberOfSpans();
  const QQRSpline::Local local{ options.X, options.Y, options.Z };
  // The user's z per point, where given in [0, 1] (NaN elsewhere: Z's value).
  QQRKnotShape given;
  for (const double z : context.PointValues)
  {
    given.Z.push_back(z >= 0.0 && z <= 1.0 ? z : std::numeric_limits<double>::quiet_NaN());
  }
  BuiltCurve built;
  if (!options.Interpolate)
  {
    built.ShapeReference = data; // the control polygon is the shape of reference
  }
  if (!options.Automatic)
  {
    built.Spline = std::make_unique<QQRSpline>(options.Interpolate
        ? QQRSpline::interpolate(
            data.Points, context.Knots, closed, options.Alpha, options.Beta, local, given)
        : QQRSpline::approximate(
            data.Points, context.Knots, closed, options.Alpha, options.Beta, local, given));
    return built;
  }
  // Automatic: alpha = beta at every knot (C2), from the larger of Alpha and
  // Beta, and the local shape parameters per point (QQRKnotShape), from the
  // options' (or the paper's) values.
  //
  // Decisions (measured, see the tests):
  //
  // 1. A large exponent does not tighten the curve towards the data polygon.
  // Each span tends to its Bezier polygon E0..E4 with a corner at E2,
  // approached with a speed ~ alpha^2 2^-alpha (1e-18 of the chord speed at
  // alpha = 68); for the local interpolation (x, y < 0) that corner even
  // turns the wrong way on convex data, where alpha = 4 already touches zero
  // curvature mid-span and alpha < 4 keeps it positive. So the exponent at a
  // knot may also be lowered (loweredQQRExponent, down to MinAlpha > 3,
  // which keeps C2), not only raised.
  //
  // 2. What pulls a span k towards its chord are the local parameters
  // (QQRKnotShape): its Bezier points lie on the chord's line when
  // Z[k-1] = 1 and Z[k+1] = 0 (the middle Bezier points of the spans on
  // either side move onto D_k and D_{k+1}), and for the control polygon also
  // Y[k] = 0 and X[k+1] = 0 (S_k, S_{k+1} on the line). The suggested
  // x_i = z_i = 0 next to Akima's straight run is X[k+1] = Z[k+1] = 0, the
  // right end of that condition (checked: it makes the control-polygon
  // curve's last span of the run straight); the left end of a run needs
  // Y[k] = 0, Z[k-1] = 1. In the interpolation the tangent (3.20) at D_k
  // then follows the chord of span k alone, and its second derivative (3.21)
  // too (Z[k] alone only slides the middle point along the chord).
  //
  // 3. Those targets conflict: Z[k] is pulled to 0 by a failing span k - 1
  // and to 1 by a failing span k + 1, and Z[k-1] = 1 with Z[k] = 0 stops the
  // interpolation at D_k (its tangent (3.20) vanishes). On Akima's data the
  // curve found without violations has the middle point of the span after
  // the run on the run's end (Z[5] = 0, span 4's rule) but Z[6] = 1, against
  // span 5's rule (Z[6] -> 0). So the rule alone does not get there; each
  // round is a sweep over the failing spans (collinearity first) that tries,
  // per span, every step of its parameters: the chord-following ones
  // (Z[k-1] and Z[k+1] half way to 1 and 0, for the control polygon Y[k] and
  // X[k+1] half way to 0), the whole way at once, the opposite ones, Z[k]
  // either way, and the exponents at its two knots raised or lowered. The
  // step that lowers the score most is taken; if none lowers it, a
  // chord-following step that keeps it is taken (several are needed before
  // a straight span is exactly straight), never against an earlier such step
  // of that parameter, so the search ends. A step that makes a span nearby
  // slower than RegularSpeed of its Bezier polygon is refused: it would
  // approach a corner, where the audit counts any curvature as rounding (its
  // threshold grows as 1 / speed^2) and passes curvatures of 1e50.
  //
  // 4. The score: (violations, failing spans), in a second search also the
  // deficiency of the failing spans (how far their tangents and signed
  // curvatures are beyond the tolerances), which lets a step count that
  // brings a span closer to passing. The two end in different local minima
  // (measured, interpolation: Akima 0 and 1, RPN 15A 1 and 2, titanium 1 and
  // 0): the second runs when the first leaves violations, and the better
  // curve is kept (ties: the first).
  //
  // 5. Cost: each step tried is a rebuild and an audit of the whole curve,
  // about 16 per failing span and sweep. A search stops after
  // EvaluationBudget span audits (2500 steps tried on a 10-point line, 500
  // on a 50-point one; measured needs: Akima's control polygon 654 steps,
  // titanium's interpolation 224), after MaxRounds sweeps, or when a sweep
  // changes nothing. (Two steps at once on a stuck span were tried too: on
  // these data sets they found nothing the single steps had not, at ten
  // times the cost.)
  constexpr double RegularSpeed = 0.02;
  constexpr double EvaluationBudget = 2.5e4;
  std::vector<double> kappa(n, std::max(options.Alpha, options.Beta));
  QQRKnotShape shape = given;
  auto make = [&](const std::vector<double>& exponents, const QQRKnotShape& knotShape) {
    return qqrCurve(options, data, context.Knots, exponents, knotShape);
  };
  shape = make(kappa, shape)->knotShape();
  if (options.Interpolate)
  {
    shape.X.clear(); // (3.18) makes them from Z
    shape.Y.clear();
  }
  auto build = [&]() -> std::unique_ptr<Curve> { return make(kappa, shape); };

  // Point k + offset, or -1 where the open line has none.
  auto point = [&](int k, int offset) {
    const int j = k + offset;
    return closed ? (j + n) % n : (j < 0 || j >= n ? -1 : j);
  };
  auto span = [&](int k, int offset) {
    const int j = k + offset;
    return closed ? (j + spans) % spans : (j < 0 || j >= spans ? -1 : j);
  };
  // A step: parameter kind (0 kappa, 1 X, 2 Y, 3 Z), index, new value, and
  // for a chord-following step its direction (+-1; 0 for the others).
  struct Step
  {
    int Kind, Index;
    double Value;
    int Chord;
  };
  std::array<std::vector<double>*, 4> values{ &kappa, &shape.X, &shape.Y, &shape.Z };
  std::array<std::vector<int>, 4> direction; // of the chord-following steps so far
  for (int v = 0; v < 4; ++v)
  {
    direction[v].assign(values[v]->size(), 0);
  }
  auto stepsOf = [&](int k) {
    std::vector<Step> steps;
    auto add = [&](int kind, int index, double target, bool chord) {
      if (index < 0)
      {
        return;
      }
      const double now = (*values[kind])[index];
      const double next = kind == 0 ? target : halfwayTo(now, target);
      if (next != now)
      {
        steps.push_back({ kind, index, next, chord ? (target > now ? 1 : -1) : 0 });
      }
      if (kind != 0 && next != target)
      {
        steps.push_back({ kind, index, target, 0 }); // the whole way at once
      }
    };
    add(3, span(k, -1), 1.0, true);
    add(3, span(k, 1), 0.0, true);
    if (!options.Interpolate)
    {
      // D_{-1} = D_0 and D_n = D_{n-1}: Y[0] and X[n-1] of an open line do nothing.
      add(2, closed || k > 0 ? point(k, 0) : -1, 0.0, true);
      add(1, closed || k + 1 < n - 1 ? point(k, 1) : -1, 0.0, true);
      add(1, closed || k < n - 1 ? point(k, 0) : -1, 0.0, false);
      add(2, point(k, 1), 0.0, false);
    }
    add(3, span(k, -1), 0.0, false);
    add(3, span(k, 1), 1.0, false);
    add(3, span(k, 0), 0.0, false);
    add(3, span(k, 0), 1.0, false);
    for (const int j : { point(k, 0), point(k, 1) })
    {
      add(0, j, raisedQQRExponent(kappa[j], options.MaxAlpha), false);
      add(0, j, loweredQQRExponent(kappa[j], options.MinAlpha), false);
    }
    return steps;
  };
  // The score: violations, failing spans, and, in the guided search (4.
  // above), how far the failing spans are from passing (deficiency).
  using Score = std::tuple<int, int, double>;
  const Score worst{ std::numeric_limits<int>::max(), std::numeric_limits<int>::max(),
    std::numeric_limits<double>::infinity() };
  const DiscreteShape reference = discreteShape(data, context.Options.Tolerances);
  const double diagonal = boundingBoxDiagonal(data.Points);
  const double scale = diagonal > 0.0 ? diagonal : 1.0;
  const double tolerance = context.Options.Tolerances.Curve;
  const unsigned collinearBit = 1u << static_cast<int>(ShapeCriterion::Collinearity);
  const unsigned convexBits = (1u << static_cast<int>(ShapeCriterion::ConvexityAtKnot)) |
    (1u << static_cast<int>(ShapeCriterion::ConvexityOnSpan));
  // Sum over the spans failing collinearity or convexity (criteria (i),
  // (ii) of the audit) of the tangent's sine beyond the tolerance, and of the
  // scale-free signed curvature below -tolerance, on 17 samples per span. A
  // guide only: the counts come from the audit.
  bool guided = false;
  auto deficiency = [&](const QQRSpline& curve, const ShapeAudit& audit) {
    double sum = 0.0;
    if (!guided)
    {
      return sum;
    }
    for (int k = 0; k < spans; ++k)
    {
      const unsigned mask = audit.SpanMask[k];
      if ((mask & (collinearBit | convexBits)) == 0)
      {
        continue;
      }
      const int next = (k + 1) % n;
      const double u0 = curve.knots()[k], h = curve.knots()[k + 1] - u0;
      const bool convexSpan = reference.Convex[k] && reference.Convex[next] &&
        reference.Binormal[k].dot(reference.Binormal[next]) > 0.0;
      for (int sample = 0; sample <= 16; ++sample)
      {
        const Derivatives d = curve.evaluateOnSpan(k, u0 + h * sample / 16.0, 2);
        const double speed = d[1].norm();
        if (!(speed > 0.0))
        {
          continue;
        }
        const Vec3 bend = d[1].cross(d[2]) / (speed * speed * speed) * scale;
        for (const int i : { k, next })
        {
          if ((mask & collinearBit) && reference.Collinear[i])
          {
            sum += std::max(0.0, (d[1] / speed).cross(data.segment(i).normalized()).norm() - tolerance);
          }
          const bool atKnot = (sample == 0 && i == k) || (sample == 16 && i == next);
          if ((mask & convexBits) && reference.Convex[i] && (convexSpan || atKnot))
          {
            sum += std::max(0.0, -bend.dot(reference.Binormal[i].normalized()) - tolerance);
          }
        }
      }
    }
    return sum;
  };
  auto failingSpans = [](const ShapeAudit& audit) {
    return static_cast<int>(std::count_if(
      audit.SpanMask.begin(), audit.SpanMask.end(), [](unsigned m) { return m != 0; }));
  };
  auto scoreOf = [&](const QQRSpline& curve, const ShapeAudit& audit) {
    return Score{ audit.violations(), failingSpans(audit), deficiency(curve, audit) };
  };
  double evaluations = 0.0; // span audits
  // The score after a step (and that curve's audit), worst if a span within
  // two of the step's index turns irregular.
  auto tryStep = [&](const Step& step, ShapeAudit& audit) {
    double& value = (*values[step.Kind])[step.Index];
    const double before = value;
    value = step.Value;
    const auto curve = make(kappa, shape);
    value = before;
    evaluations += spans;
    for (int offset = -2; offset <= 2; ++offset)
    {
      const int k = span(step.Index, offset);
      if (k >= 0 && curve->speedRatio(k) < RegularSpeed)
      {
        return worst;
      }
    }
    audit = context.audit(*curve, data);
    return scoreOf(*curve, audit);
  };
  auto tighten = [&](const std::vector<char>&) {
    const std::unique_ptr<QQRSpline> current = make(kappa, shape);
    ShapeAudit audit = context.audit(*current, data);
    Score score = scoreOf(*current, audit);
    std::vector<int> order;
    for (int k = 0; k < spans; ++k)
    {
      if (audit.SpanMask[k] != 0)
      {
        order.push_back(k);
      }
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return (audit.SpanMask[a] & collinearBit) > (audit.SpanMask[b] & collinearBit);
    });
    bool changed = false;
    for (const int k : order)
    {
      if (audit.SpanMask[k] == 0 || evaluations > EvaluationBudget)
      {
        continue; // fixed by an earlier step of this sweep, or out of budget
      }
      Score bestScore = worst, bestChordScore = worst;
      Step best{}, bestChord{};
      ShapeAudit bestAudit, bestChordAudit;
      for (const Step& step : stepsOf(k))
      {
        ShapeAudit candidate;
        const Score s = tryStep(step, candidate);
        if (s < bestScore)
        {
          bestScore = s;
          best = step;
          bestAudit = candidate;
        }
        if (step.Chord != 0 && direction[step.Kind][step.Index] != -step.Chord && s <= score &&
          s < bestChordScore)
        {
          bestChordScore = s;
          bestChord = step;
          bestChordAudit = candidate;
        }
      }
      const bool improves = bestScore < score;
      if (!improves && bestChordScore == worst)
      {
        continue;
      }
      const Step& step = improves ? best : bestChord;
      (*values[step.Kind])[step.Index] = step.Value;
      if (step.Chord != 0)
      {
        direction[step.Kind][step.Index] = step.Chord;
      }
      score = improves ? bestScore : bestChordScore;
      audit = improves ? bestAudit : bestChordAudit;
      changed = true;
    }
    return changed && evaluations <= EvaluationBudget;
  };
  const std::vector<double> startKappa = kappa;
  const QQRKnotShape startShape = shape;
  auto search = [&](bool guide) {
    guided = guide;
    kappa = startKappa;
    shape = startShape;
    evaluations = 0.0;
    for (int v = 0; v < 4; ++v)
    {
      direction[v].assign(values[v]->size(), 0);
    }
    ShapeAudit audit;
    std::unique_ptr<Curve> curve =
      preserveShape(context, data, build, tighten, options.MaxRounds, &audit);
    return std::make_pair(std::move(curve), std::move(audit));
  };
  auto result = search(false);
  if (!result.second.preserving())
  {
    // The guided search (4. above); the better curve is kept.
    auto second = search(true);
    const auto first = std::make_pair(result.second.violations(), failingSpans(result.second));
    if (std::make_pair(second.second.violations(), failingSpans(second.second)) < first)
    {
      result = std::move(second);
    }
  }
  built.Spline = std::move(result.first);
  built.Audit = std::move(result.second);
  return built;
}

/// The line's shape as numbers that rotation, translation, scaling and
/// mirroring keep: its segment lengths (relative to the longest; a closed
/// line's closing one last), then the cosines of its turning angles.
std::vector<double> intrinsicKey(const std::vector<Vec3>& points, bool closed)
{
  const int n = static_cast<int>(points.size());
  const int segments = closed ? n : n - 1;
  std::vector<Vec3> d(segments);
  double longest = 0.0;
  for (int i = 0; i < segments; ++i)
  {
    d[i] = points[(i + 1) % n] - points[i];
    longest = std::max(longest, d[i].norm());
  }
  std::vector<double> key;
  for (const Vec3& segment : d)
  {
    key.push_back(segment.norm() / longest);
  }
  for (int i = closed ? 0 : 1; i < segments; ++i)
  {
    const Vec3& before = d[(i + segments - 1) % segments];
    key.push_back(before.dot(d[i]) / (before.norm() * d[i].norm()));
  }
  return key;
}

/// Whether the line read backwards comes first, comparing intrinsicKey's
/// numbers in order (a difference below 1e-9 counts as none, so that
/// rounding does not decide): the automatic search then runs on the reversed
/// line, and a line and its reverse, moved, scaled or mirrored, get the same
/// curve. A line that reads the same both ways is taken as given.
bool reversedComesFirst(const std::vector<Vec3>& points, bool closed)
{
  std::vector<Vec3> reversed(points.rbegin(), points.rend());
  const std::vector<double> forward = intrinsicKey(points, closed);
  const std::vector<double> backward = intrinsicKey(reversed, closed);
  for (size_t i = 0; i < forward.size(); ++i)
  {
    if (std::abs(forward[i] - backward[i]) > 1e-9)
    {
      return backward[i] < forward[i];
    }
  }
  return false;
}

/**
 * The automatic search visits the failing spans in order and keeps the first
 * best step, so it can end differently on a reversed line: it runs on the
 * orientation that comes first (reversedComesFirst), and the exponents and
 * local parameters it chose are mapped back onto the line as given. Reversal
 * maps point i to n-1-i, the middle point of span k to that of span n-2-k
 * with z -> 1 - z, and swaps x and y (S_k's neighbours trade places).
 */
BuiltCurve qqrFitEitherWay(const QQROptions& options, const FitContext& context)
{
  const CleanPolyline& data = context.Data;
  const int n = static_cast<int>(data.Points.size());
  if (!options.Automatic || !reversedComesFirst(data.Points, data.Closed))
  {
    return qqrFit(options, context);
  }
  auto mirror = [n](int i) { return n - 1 - i; };
  // The middle point of span k is that of span n - 2 - k reversed (mod n when closed).
  auto mirrorSpan = [n, &data](int k) {
    const int j = n - 2 - k;
    return data.Closed ? (j + n) % n : j;
  };
  CleanPolyline reversed = data;
  std::reverse(reversed.Points.begin(), reversed.Points.end());
  std::reverse(reversed.SourceIndex.begin(), reversed.SourceIndex.end());
  // Knots as the forward fit of the reversed line computes them, bit for bit.
  const std::vector<double> knots = computeKnots(reversed, context.Options.Knots);
  std::vector<double> values(context.PointValues.size());
  for (int k = 0; k < static_cast<int>(values.size()); ++k)
  {
    const int j = mirrorSpan(k);
    values[k] = j >= 0 ? 1.0 - context.PointValues[j] : std::numeric_limits<double>::quiet_NaN();
  }
  const BuiltCurve found =
    qqrFit(options, FitContext{ reversed, knots, context.Options, context.CoordinateNoise, values });
  const auto& chosen = dynamic_cast<const QQRSpline&>(*found.Spline);
  const QQRKnotShape& shape = chosen.knotShape();
  const int spans = chosen.numberOfSpans();
  std::vector<double> kappa(n);
  QQRKnotShape mapped;
  mapped.Z.assign(n, std::numeric_limits<double>::quiet_NaN());
  for (int k = 0; k < n; ++k)
  {
    kappa[mirror(k)] = k < spans ? chosen.exponents(k)[0] : chosen.exponents(spans - 1)[1];
    const int j = mirrorSpan(k);
    if (j >= 0 && k < static_cast<int>(shape.Z.size()))
    {
      mapped.Z[j] = 1.0 - shape.Z[k];
    }
  }
  if (!options.Interpolate)
  {
    mapped.X.resize(n);
    mapped.Y.resize(n);
    for (int k = 0; k < n; ++k)
    {
      mapped.X[mirror(k)] = shape.Y[k];
      mapped.Y[mirror(k)] = shape.X[k];
    }
  }
  BuiltCurve built;
  built.Spline = qqrCurve(options, data, context.Knots, kappa, mapped);
  if (!options.Interpolate)
  {
    built.ShapeReference = data; // the control polygon is the shape of reference
  }
  built.Audit = context.audit(*built.Spline, data);
  return built;
}
} // namespace

CurveBuilder qqrBuilder(const QQROptions& options)
{
  checkExponent(options.Alpha, "Alpha");
  checkExponent(options.Beta, "Beta");
  if (options.Automatic)
  {
    checkExponent(options.MaxAlpha, "MaxAlpha");
    if (!(options.MinAlpha > 3.0) || !std::isfinite(options.MinAlpha))
    {
      throw std::invalid_argument("qqr: MinAlpha must be a finite number > 3 (C2 joins, Theorem 1 "
                                  "(5)), got " + std::to_string(options.MinAlpha));
    }
  }
  return [options](const FitContext& context) { return qqrFitEitherWay(options, context); };
}
} // namespace shapesplines
