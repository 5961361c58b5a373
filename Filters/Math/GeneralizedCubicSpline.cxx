#include "GeneralizedCubicSpline.h"

#include "AutomaticShape.h"
#include "SparseSolve.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shapesplines
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
/// Below this tension the exponential and trigonometric kernels differ from
/// the cubic by less than rounding (their difference is O(p^2)).
constexpr double NegligibleTension = 1e-8;

/// sinh x - x and x - sin x by their series for |x| < 1, where the
/// subtraction would cancel: x^3/6 (1 +- x^2/20 + x^4/840 +- ...).
double sinhMinusX(double x, double sign)
{
  double term = x * x * x / 6.0;
  double sum = term;
  for (int j = 1; j < 12; ++j)
  {
    term *= sign * x * x / ((2.0 * j + 2.0) * (2.0 * j + 3.0));
    sum += term;
  }
  return sum;
}

/**
 * 2 e^-p f^(m)(x) for f(x) = sinh x - x and m = 0..4, x in [0, p]: the
 * hyperbolic kernel's numerators, scaled by 2 e^-p so that nothing
 * overflows for p up to the double range and nothing cancels for small x.
 */
Jet scaledHyperbolic(double x, double p)
{
  const double scale = 2.0 * std::exp(-p);
  const double up = std::exp(x - p);   // e^(x-p) <= 1
  const double down = std::exp(-x - p); // e^(-x-p)
  Jet f;
  const bool small = x < 1.0;
  const double sinhScaled = small ? scale * std::sinh(x) : up - down;
  f[0] = small ? scale * sinhMinusX(x, 1.0) : up - down - x * scale;
  f[1] = small ? scale * 2.0 * std::pow(std::sinh(0.5 * x), 2) : up + down - scale;
  f[2] = sinhScaled;
  f[3] = up + down;
  f[4] = sinhScaled;
  return f;
}

/// f^(m)(x) for f(x) = x - sin x, m = 0..4.
Jet trigonometric(double x)
{
  Jet f;
  f[0] = x < 1.0 ? sinhMinusX(x, -1.0) : x - std::sin(x);
  f[1] = 2.0 * std::pow(std::sin(0.5 * x), 2);
  f[2] = std::sin(x);
  f[3] = std::cos(x);
  f[4] = -std::sin(x);
  return f;
}

/// u^(m)(t) = (-p)^m f^(m)(p (1 - t)) / f(p) from the numerators f(x) and f(p).
Jet chainRule(const Jet& fx, double fp, double p)
{
  Jet u;
  double factor = 1.0;
  for (int m = 0; m < 5; ++m)
  {
    u[m] = factor * fx[m] / fp;
    factor *= -p;
  }
  return u;
}

/// f(p), the normalisation of the exponential (scaled by 2 e^-p) and trigonometric kernels.
double normalisation(SpaceKind kind, double p)
{
  return kind == SpaceKind::Exponential ? scaledHyperbolic(p, p)[0]
    : kind == SpaceKind::Trigonometric  ? trigonometric(p)[0]
                                        : 1.0;
}

/// u^(m)(t), m = 0..order (order <= 4; the rest 0), of one kind's kernel, whose
/// normalisation f(p) is given (it is computed once per kernel, not per point).
Jet kernel(SpaceKind kind, double p, double t, double fp, int order)
{
  const bool cubic =
    kind == SpaceKind::Polynomial || (kind != SpaceKind::VariableDegree && p < NegligibleTension);
  if (cubic || kind == SpaceKind::VariableDegree)
  {
    // (1 - t)^k and its derivatives, k >= 3: one power for s^(k-3), the rest
    // by products; the fourth derivative only when asked (it vanishes for k = 3).
    const double k = cubic ? 3.0 : p;
    const double s = 1.0 - t;
    const double base = k == 3.0 ? 1.0 : complementPower(t, k - 3.0);
    const double powers[4] = { base * s * s * s, base * s * s, base * s, base };
    Jet u{};
    double coefficient = 1.0;
    for (int m = 0; m < 4; ++m)
    {
      u[m] = coefficient * powers[m];
      coefficient *= -(k - m);
    }
    u[4] = order >= 4 && coefficient != 0.0 ? coefficient * complementPower(t, k - 4.0) : 0.0;
    return u;
  }
  const double x = p * (1.0 - t);
  return chainRule(kind == SpaceKind::Exponential ? scaledHyperbolic(x, p) : trigonometric(x), fp, p);
}

void checkTension(SpaceKind kind, double tension)
{
  if (!(tension >= 0.0) || (kind == SpaceKind::VariableDegree && tension < 3.0) ||
    (kind == SpaceKind::Trigonometric && tension >= Pi))
  {
    throw std::invalid_argument("generalized cubic: tension out of range for its kind");
  }
}
} // namespace

SpaceKernel::SpaceKernel(SpaceKind kind, double tension)
  : SpaceKernel(kind, tension, kind, tension)
{
}

SpaceKernel::SpaceKernel(
  SpaceKind leftKind, double leftTension, SpaceKind rightKind, double rightTension)
  : LeftKind(leftKind)
  , RightKind(rightKind)
  , LeftTension(leftTension)
  , RightTension(rightTension)
{
  checkTension(leftKind, leftTension);
  checkTension(rightKind, rightTension);
  this->LeftNormalisation = normalisation(leftKind, leftTension);
  this->RightNormalisation = normalisation(rightKind, rightTension);
  const Jet u0 = this->u(0.0);
  const Jet v1 = this->v(1.0);
  this->USlope = -u0[1];
  this->USecond = u0[2];
  this->VSlope = v1[1];
  this->VSecond = v1[2];
}

Jet SpaceKernel::u(double t, int order) const
{
  return kernel(this->LeftKind, this->LeftTension, t, this->LeftNormalisation, order);
}

Jet SpaceKernel::v(double t, int order) const
{
  Jet v = kernel(this->RightKind, this->RightTension, 1.0 - t, this->RightNormalisation, order);
  v[1] = -v[1];
  v[3] = -v[3];
  return v;
}

double SpaceKernel::tension() const
{
  auto own = [](SpaceKind kind, double p) { return kind == SpaceKind::Polynomial ? 0.0 : p; };
  return std::max(own(this->LeftKind, this->LeftTension), own(this->RightKind, this->RightTension));
}

double largestTension(SpaceKind kind, double requested)
{
  switch (kind)
  {
    case SpaceKind::Polynomial:
      return 0.0;
    case SpaceKind::Trigonometric:
      return std::min(requested, 0.99 * Pi);
    case SpaceKind::VariableDegree:
      return std::max(requested, 3.0);
    default:
      return requested;
  }
}

std::array<Jet, 4> generalizedBernstein(const SpaceKernel& kernel, double t)
{
  const Jet u = kernel.u(t);
  const Jet v = kernel.v(t);
  const double xi = 1.0 / kernel.uSlope();
  const double eta = 1.0 / kernel.vSlope();
  const double nu = 1.0 - xi - eta; // tau_2 - tau_1 > 0 by (7)
  // B1 + B2 = 1 - u - v and xi B1 + (1 - eta) B2 = t - v.
  std::array<Jet, 4> b;
  for (int m = 0; m < 5; ++m)
  {
    const double rest = (m == 0 ? 1.0 : 0.0) - u[m] - v[m];
    const double linear = (m == 0 ? t : (m == 1 ? 1.0 : 0.0)) - v[m];
    b[0][m] = u[m];
    b[1][m] = ((1.0 - eta) * rest - linear) / nu;
    b[2][m] = (linear - xi * rest) / nu;
    b[3][m] = v[m];
  }
  return b;
}

double deCasteljau(const SpaceKernel& kernel, const std::array<double, 4>& b, double t)
{
  // Theorem 2, (9), with u'(0) = -uSlope and v'(1) = vSlope; at t = 0 or 1,
  // u / (1 - t)^2 and v / t^2 take their limits (0: u and v vanish to third order).
  const double du = -kernel.uSlope();
  const double dv = kernel.vSlope();
  const double q = du * dv - du + dv;
  const double uOver = t < 1.0 ? kernel.u(t)[0] / ((1.0 - t) * (1.0 - t)) : 0.0;
  const double vOver = t > 0.0 ? kernel.v(t)[0] / (t * t) : 0.0;
  const double m11 = uOver;
  const double m12 = du * (1.0 - dv) * (uOver - 1.0) / q - t;
  const double m13 = -dv * (uOver - 1.0) / q + t;
  const double m22 = (1.0 - t) - 0.5 * (du + dv) / q;
  const double m23 = t + 0.5 * (du + dv) / q;
  const double m32 = du * (vOver - 1.0) / q + (1.0 - t);
  const double m33 = -dv * (1.0 + du) * (vOver - 1.0) / q - (1.0 - t);
  const double m34 = vOver;
  const double c0 = m11 * b[0] + m12 * b[1] + m13 * b[2];
  const double c1 = m22 * b[1] + m23 * b[2];
  const double c2 = m32 * b[1] + m33 * b[2] + m34 * b[3];
  const double d0 = (1.0 - t) * c0 + t * c1;
  const double d1 = (1.0 - t) * c1 + t * c2;
  return (1.0 - t) * d0 + t * d1;
}

std::vector<std::array<double, 4>> bezierFromDeBoor(const std::vector<double>& knots,
  const std::vector<SpaceKernel>& kernels, const std::vector<double>& deBoor)
{
  const int m = static_cast<int>(knots.size()) - 1; // intervals
  if (m < 5 || static_cast<int>(kernels.size()) != m || static_cast<int>(deBoor.size()) != m + 1)
  {
    throw std::invalid_argument("generalized de Boor: need 5 intervals or more, a kernel per "
                                "interval and a de Boor value per knot");
  }
  std::vector<double> h(m), xi(m), eta(m), nu(m);
  for (int k = 0; k < m; ++k)
  {
    h[k] = knots[k + 1] - knots[k];
    xi[k] = 1.0 / kernels[k].uSlope();
    eta[k] = 1.0 / kernels[k].vSlope();
    nu[k] = 1.0 - xi[k] - eta[k];
  }
  // gamma_k, gamma_k^+ and gamma_k^- at the interior knots 1..m-1.
  std::vector<double> plus(m + 1, 0.0), minus(m + 1, 0.0);
  for (int k = 1; k < m; ++k)
  {
    const double vSecond = kernels[k - 1].vSecond();
    const double uSecond = kernels[k].uSecond();
    const double gamma = (h[k - 1] * eta[k - 1] + h[k] * xi[k]) /
      (vSecond * h[k] * eta[k - 1] + uSecond * h[k - 1] * xi[k]);
    plus[k] = h[k - 1] / h[k] * xi[k] / nu[k] * uSecond * gamma;
    minus[k] = h[k] / h[k - 1] * eta[k - 1] / nu[k - 1] * vSecond * gamma;
  }
  // b_{2,k-1} and b_{1,k} around knot k, then b_{3,k-1} = b_{0,k} between them.
  auto second = [&](int k) { // b_{2,k-1}, needs gamma at k-1 and k
    const double w = 1.0 + plus[k - 1] + minus[k];
    return deBoor[k] * (1.0 + plus[k - 1]) / w + deBoor[k - 1] * minus[k] / w;
  };
  auto first = [&](int k) { // b_{1,k}, needs gamma at k and k+1
    const double w = 1.0 + minus[k + 1] + plus[k];
    return deBoor[k] * (1.0 + minus[k + 1]) / w + deBoor[k + 1] * plus[k] / w;
  };
  auto junction = [&](int k) { // b_{3,k-1} = b_{0,k}
    const double w = xi[k] * h[k] + eta[k - 1] * h[k - 1];
    return second(k) * h[k] * xi[k] / w + first(k) * h[k - 1] * eta[k - 1] / w;
  };
  std::vector<std::array<double, 4>> bezier(m, { 0.0, 0.0, 0.0, 0.0 });
  for (int k = 2; k <= m - 3; ++k)
  {
    bezier[k] = { junction(k), first(k), second(k + 1), junction(k + 1) };
  }
  return bezier;
}

GeneralizedCubicSpline::GeneralizedCubicSpline(std::vector<double> knots, bool closed)
  : Curve(std::move(knots), closed)
{
}

GeneralizedCubicSpline GeneralizedCubicSpline::interpolate(const std::vector<Vec3>& points,
  const std::vector<double>& knots, bool closed, const std::vector<SpaceKernel>& kernels,
  GeneralizedCubicEnds ends)
{
  const int n = static_cast<int>(points.size());
  const int spans = closed ? n : n - 1;
  if (n < 2 || (closed && n < 3) || static_cast<int>(knots.size()) != spans + 1 ||
    static_cast<int>(kernels.size()) != spans)
  {
    throw std::invalid_argument("generalized cubic: too few points, or knots or kernels of the wrong size");
  }
  const std::vector<double> h = knotSpacings(knots, "generalized cubic");
  auto y = [&](int i) -> const Vec3& { return points[i % n]; };
  auto slope = [&](int k) -> Vec3 { return (y(k + 1) - y(k)) / h[k]; };
  // Span k with second derivatives M_k, M_k+1 (in x) at its ends:
  // C = h^2 M_k / u''(0), D = h^2 M_k+1 / v''(1). C1 at knot j:
  //   L_j-1 M_j-1 + (F_j-1 + G_j) M_j + R_j M_j+1 = slope_j - slope_j-1
  // with L = h / u''(0), R = h / v''(1), F = R (v'(1) - 1), G = L (-u'(0) - 1)
  // (the cubic's h/6 and h/3); diagonally dominant since -u'(0), v'(1) > 2.
  std::vector<double> left(spans), right(spans), f(spans), g(spans);
  for (int k = 0; k < spans; ++k)
  {
    left[k] = h[k] / kernels[k].uSecond();
    right[k] = h[k] / kernels[k].vSecond();
    f[k] = right[k] * (kernels[k].vSlope() - 1.0);
    g[k] = left[k] * (kernels[k].uSlope() - 1.0);
  }
  Triplets entries;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(n, 3);
  const int first = closed ? 0 : 1;
  const int last = closed ? n - 1 : n - 2;
  for (int j = first; j <= last; ++j)
  {
    const int before = (j - 1 + spans) % spans;
    entries.emplace_back(j, (j - 1 + n) % n, left[before]);
    entries.emplace_back(j, j, f[before] + g[j % spans]);
    entries.emplace_back(j, (j + 1) % n, right[j % spans]);
    rhs.row(j) = (slope(j % spans) - slope(before)).transpose();
  }
  if (!closed)
  {
    // M at the ends, zero (natural) or the end cubic's, scaled like the
    // other rows so that pivoting keeps them.
    entries.emplace_back(0, 0, g[0]);
    entries.emplace_back(n - 1, n - 1, f[spans - 1]);
    if (ends == GeneralizedCubicEnds::Polynomial)
    {
      rhs.row(0) = g[0] * polynomialEndDerivatives(points, knots, true, 4)[1].transpose();
      rhs.row(n - 1) =
        f[spans - 1] * polynomialEndDerivatives(points, knots, false, 4)[1].transpose();
    }
  }
  GeneralizedCubicSpline spline(knots, closed);
  const Eigen::MatrixX3d moments = n == 2 && !closed
    ? Eigen::MatrixX3d(Eigen::MatrixX3d::Zero(n, 3))
    : solveSparse(n, entries, rhs, &spline.Condition);
  spline.Kernels = kernels;
  spline.Coefficients.resize(spans);
  for (int k = 0; k < spans; ++k)
  {
    const Vec3 c = h[k] * left[k] * moments.row(k).transpose();
    const Vec3 d = h[k] * right[k] * moments.row((k + 1) % n).transpose();
    spline.Coefficients[k] = { y(k) - c, y(k + 1) - y(k) + c - d, c, d };
  }
  return spline;
}

Derivatives GeneralizedCubicSpline::evaluateOnSpan(int span, double x, int order) const
{
  const double h = this->Knots[span + 1] - this->Knots[span];
  const double t = std::clamp((x - this->Knots[span]) / h, 0.0, 1.0);
  const auto& [a, b, c, d] = this->Coefficients[span];
  const Jet u = this->Kernels[span].u(t, order);
  const Jet v = this->Kernels[span].v(t, order);
  Derivatives out;
  out.fill(Vec3::Zero());
  for (int m = 0; m <= order; ++m)
  {
    out[m] = u[m] * c + v[m] * d;
  }
  scaleDerivatives(out, h, order);
  out[0] += a + t * b;
  if (order >= 1)
  {
    out[1] += b / h;
  }
  return out;
}

std::vector<SpanParameter> GeneralizedCubicSpline::spanParameters() const
{
  std::vector<double> tension(this->Kernels.size());
  std::transform(this->Kernels.begin(), this->Kernels.end(), tension.begin(),
    [](const SpaceKernel& kernel) { return kernel.tension(); });
  return { { "Tension", tension, true } };
}

double raisedTension(SpaceKind kind, double tension, double maxTension)
{
  double next = tension;
  switch (kind)
  {
    case SpaceKind::Polynomial:
      return 0.0;
    case SpaceKind::Exponential:
      // Doubling: x4 a step overshot what a span needed (200 random 3D
      // polylines kept 32 violations, now 17; noisy helices' largest
      // curvature 320x the data's, now 68x, at 0.94x the time).
      next = std::max(2.0, 2.0 * tension);
      break;
    case SpaceKind::Trigonometric:
      next = std::max(1.0, tension + 0.5 * (Pi - tension));
      break;
    case SpaceKind::VariableDegree:
      next = std::ceil(1.5 * tension);
      break;
  }
  return largestTension(kind, std::min(next, maxTension));
}

CurveBuilder generalizedCubicBuilder(const GeneralizedCubicOptions& options)
{
  return [options](const FitContext& context) {
    const int spans = static_cast<int>(context.Knots.size()) - 1;
    // Per span: the larger tension of its two points when the user gave them
    // (a value out of range counts as Tension), else Tension.
    const auto& given = context.PointValues;
    auto pointTension = [&](size_t i) {
      const double value = given[i % given.size()];
      return std::isfinite(value) && value >= 0.0 ? value : options.Tension;
    };
    std::vector<double> tension(spans, options.Tension);
    for (int k = 0; k < spans && !given.empty(); ++k)
    {
      tension[k] = std::max(pointTension(k), pointTension(k + 1));
    }
    for (double& p : tension)
    {
      p = largestTension(options.Kind, std::min(p, options.MaxTension));
    }
    auto raise = [&](double p) { return raisedTension(options.Kind, p, options.MaxTension); };
    ShapeLadder ladder;
    ladder.TopLevel = stepsToCap(*std::min_element(tension.begin(), tension.end()), raise);
    ladder.MaxRounds = options.MaxRounds;
    ladder.RetryFromCommonLevel = true;
    ladder.RefineBackToLevelZero = false;
    ladder.Build = [&](const std::vector<int>& levels) {
      std::vector<SpaceKernel> kernels;
      kernels.reserve(spans);
      for (int k = 0; k < spans; ++k)
      {
        kernels.emplace_back(options.Kind, raisedTimes(tension[k], levels[k], raise));
      }
      return std::make_unique<GeneralizedCubicSpline>(GeneralizedCubicSpline::interpolate(
        context.Data.Points, context.Knots, context.Data.Closed, kernels, options.Ends));
    };
    // The polynomial kind has no tension to raise.
    return fixedOrAutomatic(options.Automatic && options.Kind != SpaceKind::Polynomial, context,
      context.Data, ladder);
  };
}
} // namespace shapesplines
