#include "QQRSpline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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
  Jet out{};
  double factor = 1.0;
  const double logY = x < 0.5 ? std::log1p(-x) : 0.0;
  for (int m = 0; m <= order; ++m)
  {
    if (factor == 0.0)
    {
      break; // this and every higher derivative vanish identically
    }
    const double e = p - m;
    double value = 0.0;
    if (e == 0.0)
    {
      value = factor;
    }
    else if (x < 0.5)
    {
      value = factor * std::exp(e * logY);
    }
    else if (xc > 0.0)
    {
      value = factor * std::pow(xc, e);
    }
    else
    {
      value = e > 0.0 ? 0.0 : std::copysign(Infinity, factor);
    }
    out[m] = m % 2 == 0 ? value : -value; // d/dx = -d/dy
    factor *= e;
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

EndJets endJets(double x, double xc, double a, int order)
{
  EndJets jets;
  jets.Power = complementPow(x, xc, a, order);
  jets.Linear = xTimesComplementPow(x, xc, a - 1.0, order);
  for (double& value : jets.Linear)
  {
    value *= a;
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
} // namespace

Jet qqrTail(double t, double a, int order)
{
  checkExponent(a, "a");
  return endJets(t, 1.0 - t, a, std::clamp(order, 0, 4)).Tail;
}

std::array<Jet, 5> qqrBasis(double t, double alpha, double beta, int order)
{
  checkExponent(alpha, "alpha");
  checkExponent(beta, "beta");
  order = std::clamp(order, 0, 4);
  t = std::clamp(t, 0.0, 1.0);
  const double s = 1.0 - t;
  const EndJets left = endJets(t, s, alpha, order);
  const EndJets right = endJets(s, t, beta, order); // derivatives in s = 1 - t
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
  bool closed, double alpha, double beta, const Local& local)
{
  const int spans = closed ? static_cast<int>(points.size()) : static_cast<int>(points.size()) - 1;
  return build(points, knots, closed, globalExponents(spans, alpha, beta), local, {}, false);
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
  bool closed, double alpha, double beta, const Local& local)
{
  const int spans = closed ? static_cast<int>(points.size()) : static_cast<int>(points.size()) - 1;
  return build(points, knots, closed, globalExponents(spans, alpha, beta), local, {}, true);
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
  const auto a = qqrBasis(t, alpha, beta, order);
  const auto& e = this->Bezier[span];
  // (2.10): Q = E2 + sum_{j != 2} A_j (E_j - E2); A2 is not needed and its
  // derivatives (sums of the others) never enter.
  Derivatives out;
  out.fill(Vec3::Zero());
  double scale = 1.0; // h^-m: derivatives with respect to the curve parameter
  for (int m = 0; m <= order; ++m)
  {
    for (const int j : { 0, 1, 3, 4 })
    {
      const Vec3 d = e[j] - e[2];
      for (int c = 0; c < 3; ++c)
      {
        out[m][c] += times(d[c], a[j][m]);
      }
    }
    out[m] *= scale;
    scale /= h;
  }
  out[0] += e[2];
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
/// One round of the automatic mode on a local parameter: half the way to its
/// target, the target itself once within 1/1024 of it.
double halfwayTo(double value, double target)
{
  const double next = 0.5 * (value + target);
  return std::abs(next - target) < 1.0 / 1024.0 ? target : next;
}
} // namespace

CurveBuilder qqrBuilder(const QQROptions& options)
{
  checkExponent(options.Alpha, "Alpha");
  checkExponent(options.Beta, "Beta");
  if (options.Automatic)
  {
    checkExponent(options.MaxAlpha, "MaxAlpha");
  }
  return [options](const FitContext& context) {
    const CleanPolyline& data = context.Data;
    const bool closed = data.Closed;
    const int n = static_cast<int>(data.Points.size());
    const int spans = data.numberOfSpans();
    const QQRSpline::Local local{ options.X, options.Y, options.Z };
    BuiltCurve built;
    if (!options.Interpolate)
    {
      built.ShapeReference = data; // the control polygon is the shape of reference
    }
    if (!options.Automatic)
    {
      built.Spline = std::make_unique<QQRSpline>(options.Interpolate
          ? QQRSpline::interpolate(data.Points, context.Knots, closed, options.Alpha, options.Beta, local)
          : QQRSpline::approximate(data.Points, context.Knots, closed, options.Alpha, options.Beta, local));
      return built;
    }
    // Automatic: alpha = beta at every knot (C2), from the larger of Alpha and
    // Beta, and the local shape parameters per point (QQRKnotShape), from the
    // options' (or the paper's) values.
    std::vector<double> kappa(n, std::max(options.Alpha, options.Beta));
    QQRKnotShape shape;
    auto make = [&]() {
      return std::make_unique<QQRSpline>(options.Interpolate
          ? QQRSpline::interpolate(data.Points, context.Knots, closed, kappa, local, shape)
          : QQRSpline::approximate(data.Points, context.Knots, closed, kappa, local, shape));
    };
    shape = make()->knotShape();
    if (options.Interpolate)
    {
      shape.X.clear(); // (3.18) makes them from Z
      shape.Y.clear();
    }

    // Decision (measured, see the tests): a large exponent does not tighten the
    // curve towards the data polygon. Each span tends to its Bezier polygon
    // E0..E4 with a corner at E2, approached with a speed ~ alpha^2 2^-alpha
    // (1e-18 of the chord speed at alpha = 68); for the local interpolation
    // (x, y < 0) that corner even turns the wrong way on convex data. Where
    // the speed is that small the audit counts any curvature as flat (its
    // rounding threshold grows as 1 / speed^2) and passes a curve with
    // curvature 1e50.
    //
    // What does pull a span k towards its chord are the local parameters
    // (QQRKnotShape): its Bezier points lie on the chord's line when
    // Z[k-1] = 1 and Z[k+1] = 0 (the middle Bezier points of the spans on
    // either side move onto D_k and D_{k+1}), and for the control polygon also
    // Y[k] = 0 and X[k+1] = 0 (S_k, S_{k+1} on the line; the x_i = z_i = 0
    // next to a straight run suggested for Akima's data is X[k+1] = Z[k+1] = 0,
    // the right end of that condition; the left end needs Y[k] = 0,
    // Z[k-1] = 1). In the interpolation the tangent at D_k then follows the
    // chord of span k alone, and its second derivative (3.21) too. So each
    // round, per failing span, those parameters go half the way to their
    // targets (halfwayTo). A parameter pulled both ways (Z[k] by failing spans
    // k - 1 and k + 1) stays. Only when none of a failing span's parameters
    // can move any more are the exponents at its two knots raised.
    //
    // Both can make a curve irregular: Z[k-1] -> 1 with Z[k] -> 0 stops the
    // interpolation at D_k, large exponents stop a span mid-way. A change that
    // makes a span slower than RegularSpeed of its Bezier polygon is undone and
    // the parameters of that span are frozen, and the curve returned is the
    // regular one with the fewest violations seen (ties: fewer failing spans,
    // then the earliest).
    constexpr double RegularSpeed = 1e-3;
    const QQRSpline* last = nullptr;
    auto build = [&]() -> std::unique_ptr<Curve> {
      auto curve = make();
      last = curve.get();
      return curve;
    };
    auto irregularSpans = [&](const QQRSpline& curve) {
      std::vector<int> slow;
      for (int k = 0; k < spans; ++k)
      {
        if (curve.speedRatio(k) < RegularSpeed)
        {
          slow.push_back(k);
        }
      }
      return slow;
    };
    // The parameters: 0 kappa, 1 X, 2 Y, 3 Z, one per point each.
    std::array<std::vector<double>*, 4> values{ &kappa, &shape.X, &shape.Y, &shape.Z };
    std::array<std::vector<double>, 4> previous;
    std::array<std::vector<char>, 4> frozen;
    for (int v = 0; v < 4; ++v)
    {
      previous[v] = *values[v];
      frozen[v].assign(values[v]->size(), 0);
    }
    // Point j + offset of span k, or -1 where the open line has none (or it
    // does not matter: D_{-1} = D_0 removes Y[0], D_n = D_{n-1} X[n-1]).
    auto point = [&](int k, int offset) {
      const int j = k + offset;
      return closed ? (j + n) % n : (j < 0 || j >= n ? -1 : j);
    };
    auto spanIndex = [&](int k, int offset) { // Z: one per span
      const int j = k + offset;
      return closed ? (j + n) % n : (j < 0 || j >= spans ? -1 : j);
    };
    // Every parameter span k depends on: (kind, index).
    auto parametersOf = [&](int k) {
      std::vector<std::pair<int, int>> list;
      for (const int j : { point(k, 0), point(k, 1) })
      {
        list.emplace_back(0, j);
        if (!options.Interpolate)
        {
          list.emplace_back(1, j);
          list.emplace_back(2, j);
        }
      }
      for (const int offset : { -1, 0, 1 })
      {
        list.emplace_back(3, spanIndex(k, offset));
      }
      return list;
    };
    std::vector<double> best = kappa;
    QQRKnotShape bestShape = shape;
    std::pair<int, int> bestScore{ std::numeric_limits<int>::max(), 0 };
    auto tighten = [&](const std::vector<char>& failing) {
      // The curve just built: undo the last change where it made a span irregular.
      bool reverted = false;
      for (const int k : irregularSpans(*last))
      {
        for (const auto& [v, j] : parametersOf(k))
        {
          if (j < 0)
          {
            continue;
          }
          if ((*values[v])[j] != previous[v][j])
          {
            (*values[v])[j] = previous[v][j];
            reverted = true;
          }
          frozen[v][j] = 1;
        }
      }
      if (reverted)
      {
        return true; // rebuild the reverted curve before changing more
      }
      const int failingSpans = static_cast<int>(std::count(failing.begin(), failing.end(), 1));
      const std::pair<int, int> score{ context.audit(*last, data).violations(), failingSpans };
      if (score < bestScore)
      {
        bestScore = score;
        best = kappa;
        bestShape = shape;
      }
      for (int v = 0; v < 4; ++v)
      {
        previous[v] = *values[v];
      }
      // Pulls: bit 0 towards 0, bit 1 towards 1, per local parameter.
      std::array<std::vector<unsigned>, 4> pull;
      for (int v = 1; v < 4; ++v)
      {
        pull[v].assign(values[v]->size(), 0u);
      }
      auto wish = [&](int v, int j, double target) {
        if (j >= 0 && !pull[v].empty())
        {
          pull[v][j] |= target == 0.0 ? 1u : 2u;
        }
      };
      for (int k = 0; k < spans; ++k)
      {
        if (failing[k])
        {
          wish(3, spanIndex(k, -1), 1.0);
          wish(3, spanIndex(k, 1), 0.0);
          if (!options.Interpolate)
          {
            wish(2, closed || k > 0 ? point(k, 0) : -1, 0.0);
            wish(1, closed || k + 1 < n - 1 ? point(k, 1) : -1, 0.0);
          }
        }
      }
      bool changed = false;
      std::vector<char> spanMoved(spans, 0);
      for (int v = 1; v < 4; ++v)
      {
        for (size_t j = 0; j < pull[v].size(); ++j)
        {
          const unsigned p = pull[v][j];
          const double target = p == 1u ? 0.0 : 1.0;
          double& value = (*values[v])[j];
          if ((p == 1u || p == 2u) && !frozen[v][j] && value != target)
          {
            value = halfwayTo(value, target);
            changed = true;
          }
        }
      }
      for (int k = 0; k < spans; ++k)
      {
        for (const auto& [v, j] : parametersOf(k))
        {
          if (v > 0 && j >= 0 && (*values[v])[j] != previous[v][j])
          {
            spanMoved[k] = 1;
          }
        }
      }
      // The exponents, where a failing span's local parameters are exhausted.
      // A span depends on the exponents at its two knots only: raise both.
      for (int k = 0; k < spans; ++k)
      {
        if (!failing[k] || spanMoved[k])
        {
          continue;
        }
        for (const int j : { point(k, 0), point(k, 1) })
        {
          if (!frozen[0][j] && kappa[j] < options.MaxAlpha && kappa[j] == previous[0][j])
          {
            kappa[j] = raisedQQRExponent(kappa[j], options.MaxAlpha);
            changed = true;
          }
        }
      }
      return changed;
    };
    ShapeAudit audit;
    built.Spline = preserveShape(context, data, build, tighten, options.MaxRounds, &audit);
    // The last curve competes with the best one seen (tighten only saw those before it).
    const int lastFailing = static_cast<int>(
      std::count_if(audit.SpanMask.begin(), audit.SpanMask.end(), [](unsigned m) { return m != 0; }));
    const bool lastRegular = irregularSpans(*last).empty();
    const std::pair<int, int> lastScore{ audit.violations(), lastFailing };
    if (!(lastRegular && lastScore < bestScore) &&
      (kappa != best || shape.X != bestShape.X || shape.Y != bestShape.Y || shape.Z != bestShape.Z))
    {
      kappa = best;
      shape = bestShape;
      built.Spline = build();
      audit = context.audit(*built.Spline, data);
    }
    built.Audit = audit;
    return built;
  };
}
} // namespace shapesplines
