#include "QQRSpline.h"

#include "AutomaticShape.h"
#include "ExtendedIndex.h"
#include "SparseSolve.h"

#include <algorithm>
#include <cmath>
#include <optional>
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
      " must be a finite number >= 2 (Wang & Zhang, Definition 1), got " + std::to_string(a));
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
  this->H = knotSpacings(this->Knots, "qqr B-spline basis");
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
  scaleDerivatives(out, h, MaxDerivativeOrder);
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

QQRSpline QQRSpline::make(QQRConstruction construction, const std::vector<Vec3>& points,
  const std::vector<double>& knots, bool closed, double alpha, double beta, const Local& local,
  const QQRKnotShape& knotShape)
{
  const int spans = closed ? static_cast<int>(points.size()) : static_cast<int>(points.size()) - 1;
  return build(points, knots, closed, globalExponents(spans, alpha, beta), local, knotShape, construction);
}

QQRSpline QQRSpline::make(QQRConstruction construction, const std::vector<Vec3>& points,
  const std::vector<double>& knots, bool closed, const std::vector<double>& knotExponents,
  const Local& local, const QQRKnotShape& knotShape, GeometryMemo* memo)
{
  return build(points, knots, closed,
    knotExponentsToSpans(knotExponents, static_cast<int>(points.size()), closed), local, knotShape,
    construction, memo);
}

namespace
{
/**
 * Section 3.4's construction of one qqr curve: the knot intervals beyond the
 * ends (mirrored) or around (closed), the local shape parameters per knot
 * interval, and the five Bezier points of each span as a combination of the
 * control points P(k-1)..P(k+2) (bezier(), for points or, with unit
 * vectors, for their weights).
 */
class QQRGeometry
{
public:
  QQRGeometry(std::vector<double> dh, int points, bool closed, const QQRLocalShape& local,
    const QQRKnotShape& knotShape, bool localInterpolation)
    : Dh(std::move(dh))
    , Points(points)
    , Closed(closed)
    , Local(local)
    , KnotShape(knotShape)
    , LocalInterpolation(localInterpolation)
    , MemoX(this->Dh.size() + 3, std::numeric_limits<double>::quiet_NaN())
    , MemoY(MemoX)
    , MemoZ(MemoX)
  {
  }

  /// Span k's Bezier points from P(j), j = k-1..k+2 (P takes the paper's index minus one).
  template <class T, class Control>
  std::array<T, 5> bezier(int k, const Control& P) const
  {
    const auto [R, S, Tk] = this->pieces<T>(P);
    const int i = k + 2;
    const T middle = R(i - 1);
    return { Tk(i - 1), T(this->ups(i - 1) * S(i - 1) + this->mu(i - 1) * middle), middle,
      T(this->ups(i) * middle + this->mu(i) * S(i)), Tk(i) };
  }

  /// Span k's first (end false) or last Bezier point alone: where it starts or ends.
  template <class T, class Control>
  T bezierEnd(int k, bool end, const Control& P) const
  {
    const auto Tk = std::get<2>(this->pieces<T>(P));
    return Tk(end ? k + 2 : k + 1);
  }

  /// The local shape parameters in use, one per point.
  QQRKnotShape knotShape() const
  {
    QQRKnotShape used;
    for (int j = 0; j < this->Points; ++j)
    {
      used.X.push_back(this->X(j + 1));
      used.Y.push_back(this->Y(j + 1));
      used.Z.push_back(this->Z(j + 1));
    }
    return used;
  }

  /// Takes memo's x, y, z but at the paper indices marked in moved.
  void reuse(const QQRSpline::GeometryMemo& memo, const std::vector<char>& moved)
  {
    for (size_t i = 0; i < moved.size(); ++i)
    {
      if (!moved[i])
      {
        this->MemoX[i] = memo.X[i];
        this->MemoY[i] = memo.Y[i];
        this->MemoZ[i] = memo.Z[i];
      }
    }
  }
  /// Leaves the x, y, z computed so far in memo.
  void keep(QQRSpline::GeometryMemo& memo) const
  {
    memo.X = this->MemoX;
    memo.Y = this->MemoY;
    memo.Z = this->MemoZ;
  }
  size_t memoSize() const { return this->MemoX.size(); }

private:
  /// R(i) = R_{i-1,i}, S(i) = S_{i-1}, T(i) = T_{i-1} of section 3.4 (paper
  /// index i = k + 2 for span k), as combinations of the control points P.
  template <class T, class Control>
  auto pieces(const Control& P) const
  {
    auto R = [this, &P](int i) -> T { return (1.0 - this->Z(i)) * P(i - 1) + this->Z(i) * P(i); };
    auto S = [this, &P](int i) -> T {
      const double x = this->X(i), y = this->Y(i);
      return y * P(i - 2) + (1.0 - x - y) * P(i - 1) + x * P(i);
    };
    auto Tk = [this, R, S](int i) -> T {
      const double m = this->mu(i), u = this->ups(i);
      return u * u * R(i - 1) + 2.0 * u * m * S(i) + m * m * R(i);
    };
    return std::make_tuple(R, S, Tk);
  }

  /// x, y and z at the paper's index i, each made of several intervals and
  /// neighbouring spans' shapes: computed once per index (a span's Bezier
  /// points ask for them a dozen times; qqr builds spent a sixth of their
  /// time recomputing them).
  double X(int i) const { return this->memo(this->MemoX, i, &QQRGeometry::computeX); }
  double Y(int i) const { return this->memo(this->MemoY, i, &QQRGeometry::computeY); }
  double Z(int i) const { return this->memo(this->MemoZ, i, &QQRGeometry::computeZ); }
  double memo(std::vector<double>& values, int i, double (QQRGeometry::*compute)(int) const) const
  {
    if (i < 0 || i >= static_cast<int>(values.size()))
    {
      return (this->*compute)(i);
    }
    if (std::isnan(values[i]))
    {
      values[i] = (this->*compute)(i);
    }
    return values[i];
  }

  int spans() const { return static_cast<int>(this->Dh.size()); }
  /// h_i of the paper: knot u_i is t_{i-2}.
  double H(int i) const
  {
    // Beyond the ends the intervals mirror the ones inside (decision).
    return this->Dh[extendedIndex(i - 2, this->spans(), this->Closed, Beyond::MirrorIntervals)];
  }
  double mu(int i) const { return this->H(i) / (this->H(i) + this->H(i + 1)); }
  double ups(int i) const { return this->H(i + 1) / (this->H(i) + this->H(i + 1)); }
  /// values[j], wrapped around a closed curve; fallback beyond an open
  /// line's ends and past the values given (none: all of them).
  template <class T>
  T entry(const std::vector<T>& values, int j, T fallback) const
  {
    if (this->Closed)
    {
      j = wrapIndex(j, this->Points); // a closed curve has as many spans as points
    }
    return j >= 0 && j < static_cast<int>(values.size()) ? values[j] : fallback;
  }
  /// The value per point at the paper's index i (point i - 1, QQRKnotShape), or NaN.
  double perPoint(const std::vector<double>& values, int i) const
  {
    return this->entry(values, i - 1, std::numeric_limits<double>::quiet_NaN());
  }
  /// Straightness of span k (0 beyond an open line's ends or where none is given).
  double straightness(int k) const { return this->entry(this->KnotShape.Straightness, k, 0.0); }
  /// How far span k, straightened, moves a parameter it shares with span
  /// neighbour: less where the points run straight through their common
  /// knot and the neighbour is straightened too (both spans then lie on one
  /// line already, and moving it would stop the curve at the knot).
  double pull(int k, int neighbour) const
  {
    const bool straight =
      this->entry(this->KnotShape.StraightThrough, std::max(k, neighbour), char(0)) != 0;
    return this->straightness(k) * (straight ? 1.0 - this->straightness(neighbour) : 1.0);
  }
  double computeZ(int i) const
  {
    // Span k = i - 1's middle point: the span after it wants it at its own
    // start (z = 1), the span before at its end (z = 0); both, halfway.
    const double after = this->pull(i, i - 1), before = this->pull(i - 2, i - 1);
    const double z = this->baseZ(i);
    return (1.0 - after) * (1.0 - before) * z + after * (1.0 - before) + 0.5 * after * before;
  }
  double baseZ(int i) const
  {
    const double z = this->perPoint(this->KnotShape.Z, i);
    if (!std::isnan(z))
    {
      return z;
    }
    return std::isnan(this->Local.Z)
      ? (2.0 * this->H(i) + this->H(i + 1)) / (2.0 * (this->H(i) + this->H(i + 1) + this->H(i + 2)))
      : this->Local.Z;
  }
  double computeX(int i) const
  {
    if (this->LocalInterpolation)
    {
      return -this->H(i) * this->Z(i) / (2.0 * this->H(i + 1)); // (3.18) with its missing 1/2
    }
    double x = this->perPoint(this->KnotShape.X, i);
    if (std::isnan(x))
    {
      x = std::isnan(this->Local.X)
        ? this->H(i) / (4.0 * (this->H(i) + this->H(i + 1) + this->H(i + 2)))
        : this->Local.X;
    }
    // S at the midpoint of R(i - 1) and R(i) has x = Z(i) / 2 ...
    const double flat = this->flattening(i);
    x = (1.0 - flat) * x + flat * 0.5 * this->Z(i);
    // ... and lies on span i - 2's chord when its x is 0.
    return (1.0 - this->pull(i - 2, i - 1)) * x;
  }
  double computeY(int i) const
  {
    if (this->LocalInterpolation)
    {
      return -this->H(i + 1) * (1.0 - this->Z(i - 1)) / (2.0 * this->H(i)); // (3.18)
    }
    double y = this->perPoint(this->KnotShape.Y, i);
    if (std::isnan(y))
    {
      y = std::isnan(this->Local.Y)
        ? this->H(i + 1) / (4.0 * (this->H(i - 1) + this->H(i) + this->H(i + 1)))
        : this->Local.Y;
    }
    // ... y = (1 - Z(i - 1)) / 2, and on span i - 1's chord when y is 0.
    const double flat = this->flattening(i);
    y = (1.0 - flat) * y + flat * 0.5 * (1.0 - this->Z(i - 1));
    return (1.0 - this->pull(i - 1, i - 2)) * y;
  }
  /// Flattening at the paper's index i (point i - 1; 0 where none is given).
  double flattening(int i) const { return this->entry(this->KnotShape.Flattening, i - 1, 0.0); }

  std::vector<double> Dh;
  int Points;
  bool Closed;
  QQRLocalShape Local;
  const QQRKnotShape& KnotShape;
  bool LocalInterpolation;
  /// X, Y, Z per paper index 0 .. spans + 2 (NaN: not computed yet).
  mutable std::vector<double> MemoX, MemoY, MemoZ;
};

/// Weights of the r-th derivative (in u) of span k at its start (end false) or
/// end over its control points P(k-1)..P(k+2); non-finite where unbounded.
Eigen::Vector4d derivativeWeights(const QQRGeometry& geometry, const std::array<double, 2>& exponents,
  double h, int k, bool end, int r)
{
  const auto unit = [k](int j) { return Eigen::Vector4d(Eigen::Vector4d::Unit(j - (k - 1))); };
  if (r == 0)
  {
    // A0(0) = A4(1) = 1 and the others 0 (Theorem 1, exactly): a span starts
    // at its first Bezier point and ends at its last.
    return geometry.bezierEnd<Eigen::Vector4d>(k, end, unit);
  }
  const auto weights = geometry.bezier<Eigen::Vector4d>(k, unit);
  const auto basis = qqrBasis(end ? 1.0 : 0.0, exponents[0], exponents[1], r);
  Eigen::Vector4d out = Eigen::Vector4d::Zero();
  for (int m = 0; m < 5; ++m)
  {
    if (basis[m][r] != 0.0)
    {
      out += basis[m][r] * weights[m];
    }
  }
  return out / std::pow(h, r);
}

/**
 * The control points P(-1)..P(n) (open) or P(0)..P(n-1) (closed) of the qqr
 * curve through the n points at the knots. Open ends: not-a-knot (the third
 * derivative continuous at the second and the next-to-last knots, as
 * SciPy's CubicSpline) where notAKnot says so for that end, natural
 * (s'' = 0) there otherwise, where a line has only two spans or where an end
 * exponent leaves the third derivative unbounded; doubled control points
 * where it leaves the second unbounded too. rows: an earlier build's rows
 * of the points, each taken where moved (per paper index; nullptr: none
 * taken) marks neither index it reads; on return, this build's.
 */
std::vector<Vec3> interpolatingControlPoints(const std::vector<Vec3>& points,
  const std::vector<double>& dh, bool closed, const QQRGeometry& geometry,
  const std::vector<std::array<double, 2>>& exponents, std::array<bool, 2> notAKnot,
  DeferredCondition* condition, std::vector<Eigen::Vector4d>& rows, const std::vector<char>* moved)
{
  const int n = static_cast<int>(points.size());
  const int spans = static_cast<int>(dh.size());
  const int unknowns = closed ? n : n + 2;
  auto column = [&](int j) { return closed ? wrapIndex(j, n) : j + 1; };
  Triplets entries;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(unknowns, 3);
  auto addRow = [&](int row, int k, const Eigen::Vector4d& weights, double sign) {
    for (int c = 0; c < 4; ++c)
    {
      entries.emplace_back(row, column(k - 1 + c), sign * weights[c]);
    }
  };
  // The curve passes through every point: at its knot, the start of its span
  // (the end of the last span for an open line's last point).
  const bool earlier = moved && rows.size() == static_cast<size_t>(n);
  rows.resize(n);
  for (int i = 0; i < n; ++i)
  {
    const int k = std::min(i, spans - 1);
    const int index = k + 1 + (i > k); // the paper index of the knot's Tk
    if (!earlier || (*moved)[index - 1] || (*moved)[index])
    {
      rows[i] = derivativeWeights(geometry, exponents[k], dh[k], k, i > k, 0);
    }
    addRow(i, k, rows[i], 1.0);
    rhs.row(i) = points[i].transpose();
  }
  if (!closed)
  {
    auto finite = [](const Eigen::Vector4d& w) { return w.allFinite(); };
    // End conditions at the knot after the first span and before the last.
    const int ends[2][2] = { { 0, 1 }, { spans - 2, spans - 1 } };
    for (int e = 0; e < 2; ++e)
    {
      const int row = n + e;
      const auto [before, after] = ends[e];
      if (spans >= 3 && notAKnot[e])
      {
        const Eigen::Vector4d left = derivativeWeights(geometry, exponents[before], dh[before], before, true, 3);
        const Eigen::Vector4d right = derivativeWeights(geometry, exponents[after], dh[after], after, false, 3);
        if (finite(left) && finite(right))
        {
          addRow(row, before, left, 1.0);
          addRow(row, after, right, -1.0);
          continue;
        }
      }
      const int k = e == 0 ? 0 : spans - 1;
      const Eigen::Vector4d second = derivativeWeights(geometry, exponents[k], dh[k], k, e == 1, 2);
      if (finite(second))
      {
        addRow(row, k, second, 1.0);
        continue;
      }
      const int outer = e == 0 ? -1 : n;
      const int inner = e == 0 ? 0 : n - 1;
      entries.emplace_back(row, column(outer), 1.0);
      entries.emplace_back(row, column(inner), -1.0);
    }
  }
  const Eigen::MatrixX3d solution = solveSparse(unknowns, entries, rhs, condition);
  std::vector<Vec3> control(unknowns);
  for (int j = 0; j < unknowns; ++j)
  {
    control[j] = solution.row(j).transpose();
  }
  return control;
}

/// Equal values, NaN equal to NaN (a NaN entry asks for the default).
bool sameValues(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() &&
    std::equal(a.begin(), a.end(), b.begin(),
      [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); });
}

/**
 * The paper indices 0..size - 1 whose x, y, z an open line's shape moves
 * from before to now (see QQRSpline::GeometryMemo), or nothing when the two
 * differ in more than Straightness and Flattening.
 */
std::optional<std::vector<char>> movedIndices(
  const QQRKnotShape& before, const QQRKnotShape& now, size_t size)
{
  if (!sameValues(before.X, now.X) || !sameValues(before.Y, now.Y) ||
    !sameValues(before.Z, now.Z) || before.StraightThrough != now.StraightThrough)
  {
    return std::nullopt;
  }
  std::vector<char> moved(size, 0);
  auto mark = [&](size_t from, size_t to) {
    std::fill(moved.begin() + std::min(from, size), moved.begin() + std::min(to + 1, size), 1);
  };
  // Beyond a vector's end (or all of an empty one) the value is 0.
  auto at = [](const std::vector<double>& v, size_t j) { return j < v.size() ? v[j] : 0.0; };
  for (size_t k = 0; k < std::max(before.Straightness.size(), now.Straightness.size()); ++k)
  {
    if (at(before.Straightness, k) != at(now.Straightness, k))
    {
      mark(k, k + 3);
    }
  }
  for (size_t j = 0; j < std::max(before.Flattening.size(), now.Flattening.size()); ++j)
  {
    if (at(before.Flattening, j) != at(now.Flattening, j))
    {
      mark(j + 1, j + 1);
    }
  }
  return moved;
}
} // namespace

QQRSpline QQRSpline::build(const std::vector<Vec3>& points, const std::vector<double>& knots,
  bool closed, std::vector<std::array<double, 2>> exponents, const Local& local,
  const QQRKnotShape& knotShape, QQRConstruction construction, GeometryMemo* memo)
{
  const int n = static_cast<int>(points.size());
  const int spans = closed ? n : n - 1;
  if (n < 2 || (closed && n < 3) || static_cast<int>(knots.size()) != spans + 1 ||
    static_cast<int>(exponents.size()) != spans)
  {
    throw std::invalid_argument("qqr: at least 2 points (3 closed) and one knot per point (plus "
                                "the closing knot of a closed curve) expected");
  }
  const std::vector<double> dh = knotSpacings(knots, "qqr");
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
  // Straightness per span and flattening per point: fractions in [0, 1].
  const auto checkFractions = [](const std::vector<double>& values, int count,
                                const std::string& name, const char* per) {
    if (!values.empty() && static_cast<int>(values.size()) != count)
    {
      throw std::invalid_argument("qqr: " + name + " needs one value per " + per + " (" +
        std::to_string(count) + "), got " + std::to_string(values.size()));
    }
    const auto outside = [](double f) { return !(f >= 0.0 && f <= 1.0); };
    if (std::any_of(values.begin(), values.end(), outside))
    {
      throw std::invalid_argument("qqr: " + name + " must lie in [0, 1]");
    }
  };
  const std::vector<double>& straightness = knotShape.Straightness;
  checkFractions(straightness, spans, "straightness", "span");
  checkFractions(knotShape.Flattening, n, "flattening", "point");
  if (!knotShape.StraightThrough.empty() && static_cast<int>(knotShape.StraightThrough.size()) != n)
  {
    throw std::invalid_argument("qqr: StraightThrough needs one flag per point (" +
      std::to_string(n) + "), got " + std::to_string(knotShape.StraightThrough.size()));
  }
  QQRGeometry geometry(
    dh, n, closed, local, knotShape, construction == QQRConstruction::LocalInterpolation);
  const bool remember = memo && !closed;
  const auto sameLocal = [&](const Local& other) {
    return sameValues({ other.X, other.Y, other.Z }, { local.X, local.Y, local.Z });
  };
  std::optional<std::vector<char>> moved;
  std::vector<Eigen::Vector4d> rows;
  if (remember && memo->Knots == knots && memo->Construction == construction &&
    sameLocal(memo->LocalShape) && memo->X.size() == geometry.memoSize())
  {
    moved = movedIndices(memo->Shape, knotShape, geometry.memoSize());
    if (moved)
    {
      geometry.reuse(*memo, *moved);
      // Taken, not copied: a build that throws leaves the memo without rows,
      // and the next one computes them all (interpolatingControlPoints).
      rows = std::move(memo->Rows);
    }
  }
  QQRSpline spline(knots, closed);
  // Control point P(j): the data's (open ends doubled, P(-1) = P(0), as
  // section 3.6 does), or those solved for the global interpolation (open:
  // P(-1)..P(n), each end free for its end condition).
  std::vector<Vec3> control;
  if (construction == QQRConstruction::Interpolation)
  {
    // Not-a-knot ties an end's third derivative to the spans next to it: with
    // one of them straightened it made the curve bend hard there (noisy
    // helices: 166 times the data's curvature for 6.7 with natural ends, and
    // 40% more violations left), and could make the system singular.
    auto straightened = [&](int first, int last) {
      const auto begin = straightness.begin();
      const int size = static_cast<int>(straightness.size());
      return std::any_of(begin + std::clamp(first, 0, size), begin + std::clamp(last + 1, 0, size),
        [](double s) { return s > 0.0; });
    };
    constexpr int EndReach = 3;
    const std::array<bool, 2> notAKnot{ !straightened(0, EndReach - 1),
      !straightened(spans - EndReach, spans - 1) };
    control = interpolatingControlPoints(points, dh, closed, geometry, exponents, notAKnot,
      &spline.Condition, rows, moved ? &*moved : nullptr);
  }
  auto P = [&](int j) -> const Vec3& {
    if (!control.empty())
    {
      return closed ? control[wrapIndex(j, n)] : control[j + 1];
    }
    return points[extendedIndex(j, n, closed)];
  };
  spline.Exponents = std::move(exponents);
  spline.KnotShape = geometry.knotShape();
  spline.Straightness = knotShape.Straightness;
  spline.Flattening = knotShape.Flattening;
  // Appended, not resized and overwritten: zeroing them was 2.6% of a qqr build.
  spline.Bezier.reserve(spans);
  spline.QuarticPower.reserve(spans);
  for (int k = 0; k < spans; ++k)
  {
    spline.Bezier.push_back(geometry.bezier<Vec3>(k, P));
    spline.QuarticPower.push_back(bezierToPower(spline.Bezier.back()));
  }
  if (remember)
  {
    geometry.keep(*memo);
    memo->Rows = std::move(rows);
    memo->Knots = knots;
    memo->LocalShape = local;
    memo->Shape = knotShape;
    memo->Construction = construction;
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
    out = powerDerivatives(this->QuarticPower[span], t, order, Vec3(Vec3::Zero()));
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
  scaleDerivatives(out, h, order);
  return out;
}

std::vector<SpanParameter> QQRSpline::spanParameters() const
{
  std::vector<double> alpha(this->Exponents.size());
  std::transform(this->Exponents.begin(), this->Exponents.end(), alpha.begin(),
    [](const std::array<double, 2>& ab) { return std::max(ab[0], ab[1]); });
  std::vector<double> straightness = this->Straightness;
  straightness.resize(this->Exponents.size(), 0.0);
  std::vector<double> flattening(this->Exponents.size(), 0.0);
  const int points = static_cast<int>(this->Flattening.size());
  for (int k = 0; k < static_cast<int>(flattening.size()) && points > 0; ++k)
  {
    flattening[k] = std::max(this->Flattening[k], this->Flattening[(k + 1) % points]);
  }
  return { { "Alpha", alpha, true }, { "Straightness", straightness, true },
    { "Flattening", flattening, true } };
}

double qqrStraightness(int level)
{
  return 1.0 - std::exp2(-0.5 * level);
}

double qqrTurnExponent(double kappa, double maxAlpha, int level)
{
  constexpr int FirstLevel = 4; // straightness 3/4
  const double raised = kappa * std::exp2(0.25 * std::max(0, level - FirstLevel));
  return std::min(std::max(kappa, maxAlpha), raised);
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
    const QQRSpline::Local local{ options.X, options.Y, options.Z };
    // The user's z per point, where given in [0, 1] (NaN elsewhere: Z's value).
    QQRKnotShape given;
    for (const double z : context.PointValues)
    {
      given.Z.push_back(z >= 0.0 && z <= 1.0 ? z : std::numeric_limits<double>::quiet_NaN());
    }
    BuiltCurve built;
    if (!options.Automatic)
    {
      built.Spline = std::make_unique<QQRSpline>(QQRSpline::make(options.Construction,
        data.Points, context.Knots, data.Closed, options.Alpha, options.Beta, local, given));
    }
    else
    {
      // Each failing span is moved towards its chord (QQRKnotShape::
      // Straightness): an exponent alone only scales the curvature at its
      // knot and leaves straight runs and convexity as the cubic's (see the
      // README). The exponent (alpha = beta, C2) stays the larger of Alpha
      // and Beta but where a straight run ends in a turn between two spans
      // moved well towards their chords: there it narrows the turn.
      const double kappa = std::max(options.Alpha, options.Beta);
      const int n = static_cast<int>(data.Points.size());
      QQRKnotShape shape = given;
      shape.StraightThrough =
        discreteShape(data, context.Options.Tolerances, {}, context.CoordinateNoise).Collinear;
      const std::vector<char>& through = shape.StraightThrough;
      std::vector<char> runEnd(n, 0);
      for (int i = 0; i < n; ++i)
      {
        const int before = extendedIndex(i - 1, n, data.Closed, Beyond::Clamp);
        const int after = extendedIndex(i + 1, n, data.Closed, Beyond::Clamp);
        runEnd[i] = !through[i] && (through[before] || through[after]);
      }
      ShapeLadder ladder;
      ladder.TopLevel = QQRStraighteningLevels;
      ladder.MaxRounds = options.MaxRounds;
      ladder.Reach = 3; // a span's local parameters move its neighbours and the global solve
      ladder.RetrySpanBySpan = true;
      QQRSpline::GeometryMemo straighteningMemo; // a search's builds move a few spans at a time
      ladder.Build = [&](const std::vector<int>& levels) -> std::unique_ptr<Curve> {
        shape.Straightness.resize(levels.size());
        std::transform(levels.begin(), levels.end(), shape.Straightness.begin(), qqrStraightness);
        const int spans = static_cast<int>(levels.size());
        std::vector<double> exponents(n, kappa);
        for (int i = 0; i < n; ++i)
        {
          const int before = data.Closed ? wrapIndex(i - 1, spans) : i - 1;
          const int after = data.Closed ? wrapIndex(i, spans) : i;
          if (runEnd[i] && before >= 0 && after < spans)
          {
            const int level = std::min(levels[before], levels[after]);
            exponents[i] = qqrTurnExponent(kappa, options.MaxAlpha, level);
          }
        }
        return std::make_unique<QQRSpline>(QQRSpline::make(options.Construction, data.Points,
          context.Knots, data.Closed, exponents, local, shape, &straighteningMemo));
      };
      // Flattening the curve at a failing span's knots keeps torsion signs
      // that moving the span towards its chord cannot (that keeps the sign
      // until the span is straight, and its neighbours then fail): searched
      // where straightening leaves violations (see below), on the spans where
      // the fixed curve fails nothing else (the others, and their
      // neighbours, left as they are: a long noisy line fails a little of
      // everything, and a helix of 2e4 points with one convexity failure
      // kept 1473 violations, not 545); the curve with the fewest kept (400
      // helices of 50 points, 0.1% noise, before the audit let the torsion
      // waver where it touches zero: straightening alone left 133 of 4993
      // violations, with flattening 11). One level: a knot is flattened or
      // not (flattened halfway, the knots of a span took more rounds and left
      // more). Neighbouring knots flattened make the interpolation singular
      // (its control points free to alternate), so a twisting span does not
      // raise its neighbours with it.
      ShapeLadder flattening;
      flattening.TopLevel = 1;
      // A flattened knot moves the curve far along a run of flattened knots
      // (their interpolation rows ~(1, 2, 1) / 4 do not damp a change), which
      // the audits of each round's neighbourhood miss: on a long line the
      // search does not converge, and spent its rounds for nothing while
      // its curve was discarded. Short lines end within 16 rounds (400 noisy
      // helices: the same 11 violations left); a helix of 1e4 points spent
      // 5.8x the fixed mode's time, 3.7x capped.
      constexpr int FlatteningRounds = 16;
      flattening.MaxRounds = std::min(options.MaxRounds, FlatteningRounds);
      flattening.Reach = ladder.Reach;
      flattening.RaiseTwistNeighbours = false;
      flattening.Mends = criterionBit(ShapeCriterion::TorsionSignAtKnot) |
        criterionBit(ShapeCriterion::TorsionSignOnSpan);
      QQRKnotShape flat = given;
      QQRSpline::GeometryMemo flatteningMemo;
      flattening.Build = [&](const std::vector<int>& levels) -> std::unique_ptr<Curve> {
        const std::vector<int> perKnot = knotLevels(levels, data.Closed);
        flat.Flattening.assign(perKnot.begin(), perKnot.end());
        return std::make_unique<QQRSpline>(QQRSpline::make(options.Construction, data.Points,
          context.Knots, data.Closed, std::vector<double>(n, kappa), local, flat, &flatteningMemo));
      };
      // Straightening runs first, its search alone (searchShape, neither
      // retried span by span nor refined: most of its cost where violations are
      // left, and on a long line they always are): where it removes every
      // violation its curve is kept, since a flattened knot has curvature 0
      // (400 helices of 50 points, 0.1% noise: curvature error over the middle
      // spans 2.7% straightened, 7.2% with flattening first, the fixed curve's
      // 1.4%; torsion 0 on half the samples). Where it leaves violations,
      // flattening is searched (the local interpolation takes x and y from
      // (3.18): nothing to flatten with), then the straightening search
      // improved (improveShape), and straightening again from the flattened
      // curve (its knots kept flat under the spans it straightens: the two
      // agree at a straightened span's knots); the curve with the fewest
      // violations is kept, a tie the straightened one. No start wins
      // everywhere: the users'-data generator over 12 seeds (Math core), 237
      // violations left from the unflattened curve alone, 322 from the
      // flattened one alone, 197 from both. Each of the four reports a
      // quarter of the line's progress.
      const ProgressPart first(context, 0.0, 0.25), flatteningPart(context, 0.25, 0.5),
        improving(context, 0.5, 0.75), fromFlattened(context, 0.75, 1.0);
      AutomaticShape kept = searchShape(first.context(), data, ladder);
      std::vector<double> flattenedKnots;
      if (kept.Audit.violations() > 0 &&
        options.Construction != QQRConstruction::LocalInterpolation)
      {
        AutomaticShape flattened =
          preserveShapeAutomatically(flatteningPart.context(), data, flattening);
        if (const auto* curve = dynamic_cast<const QQRSpline*>(flattened.Spline.get()))
        {
          flattenedKnots = curve->flattening();
        }
        if (flattened.Audit.violations() > 0)
        {
          kept = improveShape(std::move(kept), improving.context(), data, ladder);
        }
        if (flattened.Audit.violations() < kept.Audit.violations())
        {
          kept = std::move(flattened);
        }
      }
      built = builtCurve(std::move(kept));
      const bool flattenedAny = std::any_of(
        flattenedKnots.begin(), flattenedKnots.end(), [](double f) { return f > 0.0; });
      if (flattenedAny && built.Audit->violations() > 0)
      {
        shape.Flattening = std::move(flattenedKnots);
        BuiltCurve straightened = fixedOrAutomatic(true, fromFlattened.context(), data, ladder);
        if (straightened.Audit->violations() < built.Audit->violations())
        {
          built = std::move(straightened);
        }
      }
    }
    if (options.Construction == QQRConstruction::ControlPolygon)
    {
      built.ShapeReference = data; // the control polygon is the shape of reference
    }
    return built;
  };
}
} // namespace shapesplines
