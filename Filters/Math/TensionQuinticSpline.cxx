#include "TensionQuinticSpline.h"

#include "ExtendedIndex.h"
#include "FitPolyline.h" // lowestKnotCount
#include "SparseSolve.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace shapesplines
{
namespace
{
/// Weights on the de Boor points D_{i-3}..D_{i+3} of a point built at knot i.
using Local = Eigen::Matrix<double, 7, 1>;
using SpanWeights = TensionQuinticSpline::SpanWeights;

/// This line cannot be a tensioned quintic: a documented refusal, not a failure.
[[noreturn]] void refuseKnots()
{
  throw std::domain_error("tension quintic spline: its abscissae X(t) are not increasing on "
                          "these knots (Cravero, Manni & Sampoli, footnote 3; extremely uneven "
                          "spacing); use the generalized cubic, another parameterization, or "
                          "resample the line");
}

Local unit(int offset)
{
  Local v = Local::Zero();
  v[offset + 3] = 1.0;
  return v;
}

/// Weights seen from knot i+1 re-expressed from knot i.
Local fromNext(const Local& v)
{
  Local out = Local::Zero();
  out.tail<6>() = v.head<6>();
  return out;
}

/// Weights seen from knot i-1 re-expressed from knot i.
Local fromPrevious(const Local& v)
{
  Local out = Local::Zero();
  out.head<6>() = v.tail<6>();
  return out;
}

Local blend(double wa, const Local& a, double wb, const Local& b)
{
  return (wa * a + wb * b) / (wa + wb);
}

/// delta_i = epsilon_i of (6).
double deltaOf(double g)
{
  return g * (g + 1.0) / (2.0 * (2.0 - g));
}

/// rho_i = tau_i of (22).
double rhoOf(double g)
{
  return g * (g * g + 2.0 * g + 4.0) / (7.0 * g * g - 40.0 * g + 40.0);
}

/// sigma_i of (22).
double sigmaOf(double g)
{
  const double g2 = g * g;
  return (g + 1.0) * (g2 + 2.0 * g + 4.0) * g2 /
    (11.0 * g2 * g2 + 23.0 * g2 * g - 108.0 * g2 + 56.0 * g + 32.0);
}

/// Knot spacings and shape parameters at any index: open curves repeat the
/// end values beyond the ends, closed ones wrap around.
struct Lookup
{
  std::vector<double> H;
  const QuinticParameters& P;
  bool Closed;

  int spans() const { return static_cast<int>(this->H.size()); }
  int knot(int i) const
  {
    return extendedIndex(i, this->Closed ? this->spans() : this->spans() + 1, this->Closed);
  }
  double h(int i) const
  {
    return this->H[extendedIndex(i, this->spans(), this->Closed)];
  }
  double g(int i) const { return this->P.Gamma[this->knot(i)]; }
  double l(int i) const { return this->P.Lambda[this->knot(i)]; }
  double d(int i) const { return deltaOf(this->g(i)); }
  double rho(int i) const { return rhoOf(this->g(i)); }
  double sigma(int i) const { return sigmaOf(this->g(i)); }
};

/// The auxiliary parameters (23)-(32) of the C4 construction, all from the
/// formulas at one index i; (30) and (31) give psibar_{i-1} and omegabar_{i-1}.
struct Auxiliary
{
  double Theta, ThetaBar, Psi, Omega, PsiBarPrevious, OmegaBarPrevious;
};

Auxiliary auxiliary(const Lookup& k, int i)
{
  const double hm2 = k.h(i - 2), hm1 = k.h(i - 1), h0 = k.h(i), hp1 = k.h(i + 1);
  const double g = k.g(i), d = k.d(i), rho = k.rho(i), sigma = k.sigma(i);
  const double dm = k.d(i - 1), dp = k.d(i + 1), gm = k.g(i - 1), gp = k.g(i + 1);
  const double rhom = k.rho(i - 1), rhop = k.rho(i + 1);
  Auxiliary a;
  a.Theta = rhom * d * hm1 * (dm * hm2 + hm1 + d * h0) /
    ((dm * hm2 + hm1) * (hm1 + g * h0) - rhom * d * hm2 * h0);
  // (24) with the '+' the paper lost in (h_i + delta_{i+1} h_{i+1}).
  a.ThetaBar = d * rhop * h0 * (d * hm1 + h0 + dp * hp1) /
    ((g * hm1 + h0) * (h0 + dp * hp1) - rhop * d * hm1 * hp1);
  const double lambdaBar = rho * dp * h0 * (rho * hm1 + h0 + gp * hp1) /
    ((d * hm1 + h0) * (h0 + gp * hp1) - rho * dp * hm1 * hp1);
  const double phi = dm * rho * hm1 * (gm * hm2 + hm1 + rho * h0) /
    ((gm * hm2 + hm1) * (hm1 + d * h0) - rho * dm * hm2 * h0);
  const double dd = d * hm1 + d * h0;
  const double lambda = sigma * a.Theta * hm1 * (phi * hm2 + rho * hm1 + sigma * h0) /
    ((phi * hm2 + rho * hm1) * dd - sigma * a.Theta * hm2 * h0);
  const double rightDenominator = dd * (lambdaBar * hp1 + rho * h0) - sigma * a.ThetaBar * hm1 * hp1;
  const double phiBar =
    sigma * a.ThetaBar * h0 * (sigma * hm1 + rho * h0 + lambdaBar * hp1) / rightDenominator;
  a.Psi = sigma * h0 * (dd + a.ThetaBar * hp1) / rightDenominator;
  a.PsiBarPrevious = sigma * hm1 * (a.Theta * hm2 + dd) /
    ((phi * hm2 + rho * hm1) * dd - sigma * a.Theta * hm2 * h0);
  const double omegaDenominator =
    (phi * hm2 + rho * hm1 + sigma * h0) * (sigma * hm1 + rho * h0 + lambdaBar * hp1) -
    lambda * phiBar * hm2 * hp1;
  a.OmegaBarPrevious = phiBar * (lambda * hm2 + sigma * hm1 + rho * h0 + lambdaBar * hp1) *
    (hm1 + a.PsiBarPrevious * h0) / omegaDenominator;
  a.Omega = lambda * (phi * hm2 + rho * hm1 + sigma * h0 + phiBar * hp1) * (a.Psi * hm1 + h0) /
    omegaDenominator;
  return a;
}

/// E_i^-, E_i^+ and S_i, (10)-(14) or their C4 versions, seen from knot i.
struct KnotBlend
{
  Local EMinus, EPlus, S;
};

/// around: the auxiliary parameters at knots i - 1, i, i + 1 (C4 only).
KnotBlend knotBlend(const Lookup& k, int i, const Auxiliary* around)
{
  const double hm3 = k.h(i - 3), hm2 = k.h(i - 2), hm1 = k.h(i - 1), h0 = k.h(i),
               hp1 = k.h(i + 1), hp2 = k.h(i + 2);
  const Local dm = unit(-1), d0 = unit(0), dp = unit(1);
  KnotBlend b;
  if (k.P.Continuity == QuinticContinuity::C3)
  {
    const Local fMinus = blend(k.l(i - 1) * (hm2 + hm3) + hm1, d0, k.l(i) * (h0 + hp1), dm);
    const Local fPlus = blend(k.l(i + 1) * (hp1 + hp2) + h0, d0, k.l(i) * (hm2 + hm1), dp);
    b.EMinus = blend(hm2, fPlus, hm1 + h0 + hp1, fMinus);
    b.EPlus = blend(hm2 + hm1 + h0, fPlus, hp1, fMinus);
  }
  else
  {
    const Auxiliary &previous = around[0], &here = around[1], &next = around[2];
    const Local fMinus = blend(previous.Psi * hm2 + previous.Omega * hm3 + hm1, d0,
      here.PsiBarPrevious * h0 + here.OmegaBarPrevious * hp1, dm);
    const Local fPlus = blend(next.PsiBarPrevious * hp1 + next.OmegaBarPrevious * hp2 + h0, d0,
      here.Omega * hm2 + here.Psi * hm1, dp);
    const double dd = k.d(i) * (hm1 + h0);
    b.EMinus = blend(here.Theta * hm2, fPlus, dd + here.ThetaBar * hp1, fMinus);
    b.EPlus = blend(here.Theta * hm2 + dd, fPlus, here.ThetaBar * hp1, fMinus);
  }
  b.S = blend(hm1, b.EPlus, h0, b.EMinus);
  return b;
}

/// The Bezier points around knot i, (15)-(18), seen from knot i.
struct KnotPoints
{
  Local B3Previous, B4Previous, B0, B1, B2;
};

/// around: the blends of knots i - 1, i, i + 1.
KnotPoints knotPoints(const Lookup& k, int i, const KnotBlend* around)
{
  const KnotBlend &previous = around[0], &here = around[1], &next = around[2];
  const double hm2 = k.h(i - 2), hm1 = k.h(i - 1), h0 = k.h(i), hp1 = k.h(i + 1);
  const double g = k.g(i), d = k.d(i);
  KnotPoints p;
  p.B3Previous = blend(d * h0, fromPrevious(previous.EPlus), k.d(i - 1) * hm2 + hm1, here.EMinus);
  p.B2 = blend(k.d(i + 1) * hp1 + h0, here.EPlus, d * hm1, fromNext(next.EMinus));
  p.B4Previous = blend(g * h0, p.B3Previous, hm1, here.S);
  p.B1 = blend(g * hm1, p.B2, h0, here.S);
  p.B0 = blend(h0, p.B4Previous, hm1, p.B1);
  return p;
}

/// The weights of spans first..last - 1 (of their six Bezier points on
/// D_{i-2}..D_{i+3}) into weights[first..last - 1].
void spanWeightsOf(const Lookup& k, int first, int last, std::vector<SpanWeights>& weights)
{
  // Each auxiliary serves three knots' blends and each blend three knots'
  // points: computed once per knot, from two knots before the first span.
  std::vector<Auxiliary> auxiliaries;
  if (k.P.Continuity == QuinticContinuity::C4)
  {
    for (int i = first - 2; i <= last + 2; ++i)
    {
      auxiliaries.push_back(auxiliary(k, i));
    }
  }
  std::vector<KnotBlend> blends;
  for (int i = first - 1; i <= last + 1; ++i)
  {
    blends.push_back(
      knotBlend(k, i, auxiliaries.empty() ? nullptr : &auxiliaries[i - 1 - (first - 2)]));
  }
  std::vector<KnotPoints> points;
  for (int i = first; i <= last; ++i)
  {
    points.push_back(knotPoints(k, i, &blends[i - 1 - (first - 1)]));
  }
  for (int i = first; i < last; ++i)
  {
    const KnotPoints& a = points[i - first];
    const KnotPoints& b = points[i + 1 - first];
    const Local rows[6] = { a.B0, a.B1, a.B2, fromNext(b.B3Previous), fromNext(b.B4Previous),
      fromNext(b.B0) };
    for (int j = 0; j < 6; ++j)
    {
      weights[i].row(j) = rows[j].tail<6>().transpose();
    }
  }
}

/// Per span, the weights of its six Bezier points on D_{i-2}..D_{i+3}.
std::vector<SpanWeights> spanWeights(const Lookup& k)
{
  std::vector<SpanWeights> weights(k.spans());
  spanWeightsOf(k, 0, k.spans(), weights);
  return weights;
}

/// The knots on each side of one whose parameters a span's weights read
/// (auxiliaries one knot away, blends two, Bezier points three, a span its two ends').
constexpr int WeightsReach = 4;

/// spanWeights(k), recomputed in memo only around the knots whose parameters
/// changed since memo's last build on the same knots t (an open line's).
std::vector<SpanWeights> memoizedSpanWeights(
  const Lookup& k, const std::vector<double>& t, TensionQuinticSpline::WeightsMemo* memo)
{
  const int n = k.spans();
  const QuinticParameters& p = k.P;
  if (!memo || k.Closed || memo->Knots != t || memo->Weights.size() != static_cast<size_t>(n) ||
    memo->Parameters.Continuity != p.Continuity ||
    memo->Parameters.Gamma.size() != p.Gamma.size() ||
    memo->Parameters.Lambda.size() != p.Lambda.size())
  {
    std::vector<SpanWeights> weights = spanWeights(k);
    if (memo && !k.Closed)
    {
      *memo = { t, p, weights };
    }
    return weights;
  }
  std::vector<char> stale(n, 0);
  const bool c3 = p.Continuity == QuinticContinuity::C3;
  for (size_t m = 0; m < p.Gamma.size(); ++m)
  {
    if (p.Gamma[m] != memo->Parameters.Gamma[m] || (c3 && p.Lambda[m] != memo->Parameters.Lambda[m]))
    {
      const int knot = static_cast<int>(m);
      std::fill(stale.begin() + std::max(0, knot - WeightsReach),
        stale.begin() + std::min(n, knot + WeightsReach), 1);
    }
  }
  for (int first = 0; first < n;)
  {
    if (!stale[first])
    {
      ++first;
      continue;
    }
    int last = first;
    while (last < n && stale[last])
    {
      ++last;
    }
    spanWeightsOf(k, first, last, memo->Weights);
    first = last;
  }
  memo->Parameters = p;
  return memo->Weights;
}

Lookup lookup(const std::vector<double>& t, const QuinticParameters& parameters, bool closed)
{
  return Lookup{ knotSpacings(t, "tension quintic spline"), parameters, closed };
}

/// Where the de Boor point of index m (from -2 for open curves) is stored.
int storage(int m, int spans, bool closed)
{
  return closed ? wrapIndex(m, spans) : m + 2;
}

/// Abscissa xi_m: closed curves add a period per turn.
double abscissa(const std::vector<double>& xi, int m, int spans, bool closed, double period)
{
  return closed ? xi[wrapIndex(m, spans)] + floorDiv(m, spans) * period : xi[m + 2];
}

/// The rows of X or C at the ends of an open curve: first and second local
/// derivatives of span 0 at its start, of the last span at its end.
std::array<Eigen::Matrix<double, 1, 6>, 2> endRows(const SpanWeights& w, bool start)
{
  if (start)
  {
    return { 5.0 * (w.row(1) - w.row(0)), 20.0 * (w.row(2) - 2.0 * w.row(1) + w.row(0)) };
  }
  return { 5.0 * (w.row(5) - w.row(4)), 20.0 * (w.row(5) - 2.0 * w.row(4) + w.row(3)) };
}

/// Strictly increasing Bezier abscissae on every span (hence X' > 0): the
/// spans where that fails.
std::vector<int> nonIncreasingSpans(const std::vector<SpanWeights>& weights,
  const std::vector<double>& xi, bool closed, double period)
{
  const int n = static_cast<int>(weights.size());
  std::vector<int> bad;
  for (int i = 0; i < n; ++i)
  {
    Eigen::Matrix<double, 6, 1> d;
    for (int m = 0; m < 6; ++m)
    {
      d[m] = abscissa(xi, i - 2 + m, n, closed, period);
    }
    const Eigen::Matrix<double, 6, 1> x = weights[i] * d;
    bool increasing = std::isfinite(x[0]);
    for (int j = 0; j < 5; ++j)
    {
      increasing = increasing && std::isfinite(x[j + 1]) && x[j + 1] > x[j];
    }
    if (!increasing)
    {
      bad.push_back(i);
    }
  }
  return bad;
}

/// The weights of knot i (0..n) on D_{base}..D_{base+5}: b_{i,0}.
std::pair<Eigen::Matrix<double, 1, 6>, int> knotRow(const std::vector<SpanWeights>& weights, int i)
{
  const int n = static_cast<int>(weights.size());
  return i < n ? std::make_pair(Eigen::Matrix<double, 1, 6>(weights[i].row(0)), i - 2)
               : std::make_pair(Eigen::Matrix<double, 1, 6>(weights[n - 1].row(5)), n - 3);
}

/// Adds a row of weights on D_{base}..D_{base+5}; closed curves wrap (entries add up).
void addRow(Triplets& a, int row, const Eigen::Matrix<double, 1, 6>& w, int base, int spans,
  bool closed)
{
  for (int m = 0; m < 6; ++m)
  {
    if (w[m] != 0.0)
    {
      a.emplace_back(row, storage(base + m, spans, closed), w[m]);
    }
  }
}
} // namespace

QuinticParameters QuinticParameters::uniform(
  QuinticContinuity continuity, int knots, double gamma, double lambda)
{
  QuinticParameters p;
  p.Continuity = continuity;
  p.Gamma.assign(knots, gamma);
  p.Lambda.assign(knots, lambda);
  return p;
}

void QuinticParameters::check(int knots) const
{
  const bool c3 = this->Continuity == QuinticContinuity::C3;
  if (static_cast<int>(this->Gamma.size()) != knots ||
    (c3 && static_cast<int>(this->Lambda.size()) != knots))
  {
    throw std::invalid_argument("tension quintic spline: one shape parameter per knot");
  }
  for (int i = 0; i < knots; ++i)
  {
    const double g = this->Gamma[i];
    const bool ok = c3 ? (g > 0.0 && g < 2.0 && this->Lambda[i] > 0.0 && std::isfinite(this->Lambda[i]))
                       : (g > 0.0 && g <= 1.0);
    if (!ok)
    {
      throw std::invalid_argument("tension quintic spline: shape parameter out of range at knot " +
        std::to_string(i));
    }
  }
}

TensionQuinticSpline::TensionQuinticSpline(std::vector<double> knots, bool closed)
  : Curve(std::move(knots), closed)
{
}

std::vector<double> TensionQuinticSpline::grevilleAbscissae(const std::vector<double>& t, bool closed)
{
  const int n = static_cast<int>(t.size()) - 1;
  // Parametric knot j: beyond the ends of open curves the end spacings repeat.
  auto knot = [&](int j) {
    if (closed)
    {
      return periodicKnot(t, j);
    }
    if (j < 0)
    {
      return t[0] + j * (t[1] - t[0]);
    }
    return j > n ? t[n] + (j - n) * (t[n] - t[n - 1]) : t[j];
  };
  std::vector<double> xi;
  for (int m = closed ? 0 : -2; m <= (closed ? n - 1 : n + 2); ++m)
  {
    xi.push_back((knot(m - 2) + knot(m - 1) + knot(m) + knot(m + 1) + knot(m + 2)) / 5.0);
  }
  return xi;
}

TensionQuinticSpline TensionQuinticSpline::fromControlPoints(const std::vector<double>& t,
  const std::vector<double>& xi, const std::vector<Vec3>& points,
  const QuinticParameters& parameters, bool closed)
{
  const int n = static_cast<int>(t.size()) - 1;
  const size_t deBoor = closed ? n : n + 5;
  if (n < 1 || (closed && n < 3) || xi.size() != deBoor || points.size() != deBoor)
  {
    throw std::invalid_argument("tension quintic spline: wrong number of knots or de Boor points");
  }
  parameters.check(closed ? n : n + 1);
  return fromWeights(t, xi, points, parameters, closed, spanWeights(lookup(t, parameters, closed)));
}

TensionQuinticSpline TensionQuinticSpline::fromWeights(const std::vector<double>& t,
  const std::vector<double>& xi, const std::vector<Vec3>& points,
  const QuinticParameters& parameters, bool closed, const std::vector<SpanWeights>& weights)
{
  const int n = static_cast<int>(t.size()) - 1;
  const double period = t.back() - t.front();
  if (!nonIncreasingSpans(weights, xi, closed, period).empty())
  {
    // The abscissae stayed non-increasing after every recovery (fuzz: spans from
    // 1e25 to 1e37 in one line).
    refuseKnots();
  }
  std::vector<std::array<double, 6>> xBezier(n);
  std::vector<std::array<Vec3, 6>> cBezier(n);
  std::vector<double> knots(n + 1);
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < 6; ++j)
    {
      double x = 0.0;
      Vec3 c = Vec3::Zero();
      for (int m = 0; m < 6; ++m)
      {
        x += weights[i](j, m) * abscissa(xi, i - 2 + m, n, closed, period);
        c += weights[i](j, m) * points[storage(i - 2 + m, n, closed)];
      }
      xBezier[i][j] = x;
      cBezier[i][j] = c;
    }
    knots[i] = xBezier[i][0];
  }
  knots[n] = xBezier[n - 1][5];
  TensionQuinticSpline spline(std::move(knots), closed);
  spline.Parameters = parameters;
  spline.Xi = xi;
  spline.Points = points;
  for (int i = 0; i < n; ++i)
  {
    spline.XPower.push_back(bezierToPower(xBezier[i]));
    const std::array<Vec3, 6> cPower = bezierToPower(cBezier[i]);
    std::array<Eigen::Vector4d, 6> xcPower;
    for (int k = 0; k < 6; ++k)
    {
      xcPower[k] << spline.XPower.back()[k], cPower[k];
    }
    spline.XCPower.push_back(xcPower);
  }
  spline.XBezier = std::move(xBezier);
  return spline;
}

namespace
{
/// One solve of the knot system (34) for the knots target; xi empty if it is singular.
std::vector<double> solveKnotSystem(const std::vector<double>& t, const std::vector<double>& target,
  const Lookup& k, const std::vector<SpanWeights>& weights, bool closed, DeferredCondition& condition)
{
  const int n = k.spans();
  const int knots = closed ? n : n + 1;
  const int unknowns = closed ? n : n + 5;
  const double period = t.back() - t.front();
  Triplets a;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(unknowns, 3);
  for (int i = 0; i < knots; ++i)
  {
    const auto [w, base] = knotRow(weights, i);
    addRow(a, i, w, base, n, closed);
    rhs(i, 0) = target[i];
    if (closed)
    {
      // The shifted abscissae of de Boor points one period away are constants.
      for (int m = 0; m < 6; ++m)
      {
        rhs(i, 0) -= w[m] * floorDiv(base + m, n) * period;
      }
    }
  }
  if (!closed)
  {
    // The two outer abscissae at each end stay at their Greville values (21),
    // which give X(t) = t when all parameters are 1.
    const std::vector<double> greville = TensionQuinticSpline::grevilleAbscissae(t, false);
    for (const int m : { 0, 1, n + 3, n + 4 })
    {
      const int row = m < 2 ? n + 1 + m : m;
      a.emplace_back(row, m, 1.0);
      rhs(row, 0) = greville[m];
    }
  }
  try
  {
    const Eigen::MatrixX3d xi = solveSparse(unknowns, a, rhs, &condition);
    return std::vector<double>(xi.col(0).data(), xi.col(0).data() + unknowns);
  }
  catch (const std::runtime_error&)
  {
    return {};
  }
}
} // namespace

TensionQuinticSpline::Abscissae TensionQuinticSpline::solveAbscissae(const std::vector<double>& t,
  const QuinticParameters& parameters, bool closed, bool recover, WeightsMemo* memo)
{
  const int n = static_cast<int>(t.size()) - 1;
  const int knots = closed ? n : n + 1;
  parameters.check(knots);
  const double period = t.back() - t.front();
  const std::vector<double> greville = grevilleAbscissae(t, closed);
  Abscissae result;
  result.Parameters = parameters;
  // Per knot, how far the requested knot moves towards the knot that the
  // Greville abscissae give (always increasing X): 0 is where asked.
  std::vector<double> relax(knots, 0.0);
  constexpr int RelaxRounds = 12;
  constexpr int MaxRecoveries = 64;
  for (;;)
  {
    if (result.Recoveries == MaxRecoveries)
    {
      // Parameters all 1 with the Greville abscissae give X(t) = t.
      std::fill(result.Parameters.Gamma.begin(), result.Parameters.Gamma.end(), 1.0);
      std::fill(result.Parameters.Lambda.begin(), result.Parameters.Lambda.end(), 1.0);
      std::fill(relax.begin(), relax.end(), 1.0);
    }
    const Lookup k = lookup(t, result.Parameters, closed);
    std::vector<SpanWeights> weights = memoizedSpanWeights(k, t, memo);
    std::vector<double> target(knots);
    for (int i = 0; i < knots; ++i)
    {
      double x = 0.0;
      if (relax[i] > 0.0)
      {
        const auto [w, base] = knotRow(weights, i);
        for (int m = 0; m < 6; ++m)
        {
          x += w[m] * abscissa(greville, base + m, n, closed, period);
        }
      }
      target[i] = (1.0 - relax[i]) * t[i] + relax[i] * x;
    }
    result.Condition = DeferredCondition();
    result.Xi = solveKnotSystem(t, target, k, weights, closed, result.Condition);
    std::vector<int> bad;
    if (result.Xi.empty())
    {
      for (int i = 0; i < n; ++i)
      {
        bad.push_back(i);
      }
    }
    else
    {
      bad = nonIncreasingSpans(weights, result.Xi, closed, period);
    }
    result.Increasing = bad.empty();
    result.KnotsMoved = *std::max_element(relax.begin(), relax.end()) > 0.0;
    if (recover && !result.Increasing && result.Recoveries == MaxRecoveries)
    {
      // Even X(t) = t has no solution (fuzz: spans 2e-12 of their neighbours',
      // a singular knot system): no abscissae to build the curve on.
      refuseKnots();
    }
    if (result.Increasing || !recover)
    {
      result.Weights = std::move(weights);
      return result;
    }
    // Footnote 3: move the requested knots around a bad span halfway towards
    // the Greville knots, at most RelaxRounds times; then pull the parameters
    // there halfway to 1 (the construction's weights may be negative).
    ++result.Recoveries;
    std::vector<char> near(knots, 0);
    for (int span : bad)
    {
      for (int j = span - 3; j <= span + 4; ++j)
      {
        near[k.knot(j) % knots] = 1;
      }
    }
    const bool relaxed = result.Recoveries > RelaxRounds;
    for (int j = 0; j < knots; ++j)
    {
      if (!near[j])
      {
        continue;
      }
      if (!relaxed)
      {
        relax[j] = result.Recoveries == RelaxRounds ? 1.0 : 0.5 * (1.0 + relax[j]);
        continue;
      }
      result.Parameters.Gamma[j] = 0.5 * (1.0 + result.Parameters.Gamma[j]);
      if (!result.Parameters.Lambda.empty())
      {
        result.Parameters.Lambda[j] = 0.5 * (1.0 + result.Parameters.Lambda[j]);
      }
    }
  }
}

TensionQuinticSpline::EndDerivatives TensionQuinticSpline::dataEnds(
  const std::vector<Vec3>& points, const std::vector<double>& knots)
{
  return { polynomialEndDerivatives(points, knots, true, 6),
    polynomialEndDerivatives(points, knots, false, 6) };
}

TensionQuinticSpline TensionQuinticSpline::interpolate(const std::vector<Vec3>& points,
  const std::vector<double>& knots, const QuinticParameters& parameters, bool closed,
  const EndDerivatives* ends, WeightsMemo* memo)
{
  const int count = static_cast<int>(points.size());
  const int n = closed ? count : count - 1;
  if (count < 3 || static_cast<int>(knots.size()) != n + 1)
  {
    throw std::invalid_argument("tension quintic spline: too few points or knots of the wrong size");
  }
  Abscissae abscissae = solveAbscissae(knots, parameters, closed, true, memo);
  const std::vector<SpanWeights>& weights = abscissae.Weights;
  const int unknowns = closed ? n : n + 5;
  Triplets a;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(unknowns, 3);
  for (int i = 0; i < count; ++i)
  {
    const auto [w, base] = knotRow(weights, i);
    addRow(a, i, w, base, n, closed);
    rhs.row(i) = points[i].transpose();
  }
  if (!closed)
  {
    // s' = C'/X' and s'' = (C'' - s' X'')/X'^2 given: linear in the de Boor points.
    const double period = 0.0;
    const EndDerivatives polynomialEnds = ends ? *ends : dataEnds(points, knots);
    for (const bool start : { true, false })
    {
      const int base = start ? -2 : n - 3;
      const auto rows = endRows(start ? weights.front() : weights.back(), start);
      double xd[2];
      for (int r = 0; r < 2; ++r)
      {
        xd[r] = 0.0;
        for (int m = 0; m < 6; ++m)
        {
          xd[r] += rows[r][m] * abscissa(abscissae.Xi, base + m, n, false, period);
        }
      }
      // Tension at the end knot blends s' towards the end chord and s'' towards 0,
      // the derivatives of the limit polygon.
      const int knot = start ? 0 : n;
      const QuinticParameters& p = abscissae.Parameters;
      const double w = std::min(
        { 1.0, p.Gamma[knot], p.Continuity == QuinticContinuity::C3 ? p.Lambda[knot] : 1.0 });
      const auto& polynomial = polynomialEnds[start ? 0 : 1];
      const Vec3 chord = start ? Vec3((points[1] - points[0]) / (knots[1] - knots[0]))
                               : Vec3((points[n] - points[n - 1]) / (knots[n] - knots[n - 1]));
      const Vec3 first = w * polynomial[0] + (1.0 - w) * chord;
      const Vec3 second = w * polynomial[1];
      const int row = start ? count : count + 2;
      addRow(a, row, rows[0], base, n, false);
      rhs.row(row) = (first * xd[0]).transpose();
      addRow(a, row + 1, rows[1], base, n, false);
      rhs.row(row + 1) = (second * xd[0] * xd[0] + first * xd[1]).transpose();
    }
  }
  DeferredCondition condition;
  const Eigen::MatrixX3d solution = solveSparse(unknowns, a, rhs, &condition);
  return fromSolution(knots, std::move(abscissae), solution, std::move(condition), closed);
}

TensionQuinticSpline TensionQuinticSpline::fromSolution(const std::vector<double>& t,
  Abscissae abscissae, const Eigen::MatrixX3d& solution, DeferredCondition condition, bool closed)
{
  std::vector<Vec3> deBoor(solution.rows());
  for (Eigen::Index m = 0; m < solution.rows(); ++m)
  {
    deBoor[m] = solution.row(m).transpose();
  }
  TensionQuinticSpline spline =
    fromWeights(t, abscissae.Xi, deBoor, abscissae.Parameters, closed, abscissae.Weights);
  spline.Recoveries = abscissae.Recoveries;
  spline.Condition = std::move(condition);
  spline.Condition.merge(std::move(abscissae.Condition));
  return spline;
}

std::pair<std::array<double, 5>, Derivatives> TensionQuinticSpline::parametricDerivatives(
  int span, double tau, int order) const
{
  const auto xc =
    powerDerivatives(this->XCPower[span], tau, order, Eigen::Vector4d(Eigen::Vector4d::Zero()));
  std::pair<std::array<double, 5>, Derivatives> out;
  for (int r = 0; r <= MaxDerivativeOrder; ++r)
  {
    out.first[r] = xc[r][0];
    out.second[r] = xc[r].tail<3>();
  }
  return out;
}

double TensionQuinticSpline::localParameter(int span, double x) const
{
  const std::array<double, 6>& xb = this->XBezier[span];
  // X is a strictly increasing quintic on [0,1]: safeguarded Newton.
  if (x >= xb[5])
  {
    return 1.0;
  }
  if (x <= xb[0])
  {
    return 0.0;
  }
  // Start from the inverse of X's cubic Hermite interpolant at the span's
  // ends (slopes 1 / X'), a step or two closer than the chord's guess.
  const double width = xb[5] - xb[0];
  const double s = (x - xb[0]) / width;
  const double startSlope = width / (5.0 * (xb[1] - xb[0]));
  const double endSlope = width / (5.0 * (xb[5] - xb[4]));
  const double guess =
    s * s * (3.0 - 2.0 * s) + s * (1.0 - s) * ((1.0 - s) * startSlope - s * endSlope);
  double u = guess > 0.0 && guess < 1.0 ? guess : s;
  double lo = 0.0, hi = 1.0;
  for (int iteration = 0; iteration < 200; ++iteration)
  {
    const auto d = powerDerivatives(this->XPower[span], u, 1, 0.0); // X and X'
    const double f = d[0] - x;
    if (f == 0.0)
    {
      break;
    }
    (f < 0.0 ? lo : hi) = u;
    double next = u - f / d[1];
    const bool newton = next > lo && next < hi;
    if (!newton)
    {
      next = 0.5 * (lo + hi);
    }
    // Newton converges quadratically: after a step of 1e-10 the error is ~1e-20 X''/X'.
    const bool converged = newton && std::abs(next - u) <= 1e-10;
    u = next;
    if (converged || hi - lo <= 2e-16)
    {
      break;
    }
  }
  return u;
}

TensionQuinticSpline TensionQuinticSpline::approximate(const std::vector<Vec3>& points,
  const std::vector<double>& u, const std::vector<double>& knots,
  const QuinticParameters& parameters, bool closed, WeightsMemo* memo)
{
  const int n = static_cast<int>(knots.size()) - 1;
  const int unknowns = closed ? n : n + 5;
  if (n < (closed ? 3 : 1) || u.size() < points.size() || static_cast<int>(points.size()) < unknowns)
  {
    throw std::invalid_argument("tension quintic spline: too few points to approximate");
  }
  Abscissae abscissae = solveAbscissae(knots, parameters, closed, true, memo);
  const std::vector<SpanWeights>& weights = abscissae.Weights;
  // The same X with any de Boor points: it maps the data parameters to spans and t.
  const TensionQuinticSpline shape = fromWeights(knots, abscissae.Xi,
    std::vector<Vec3>(unknowns, Vec3::Zero()), abscissae.Parameters, closed, weights);
  NormalEquations normal(unknowns);
  for (size_t j = 0; j < points.size(); ++j)
  {
    const int span = shape.findSpan(u[j]);
    const double tau = shape.localParameter(span, u[j]);
    Eigen::Matrix<double, 1, 6> bernstein;
    for (int b = 0; b < 6; ++b)
    {
      static const double binomial[6] = { 1, 5, 10, 10, 5, 1 };
      bernstein[b] = binomial[b] * std::pow(tau, b) * std::pow(1.0 - tau, 5 - b);
    }
    const Eigen::Matrix<double, 1, 6> row = bernstein * weights[span];
    int column[6]; // the span's de Boor points D_span-2..D_span+3 (wrapping when closed)
    for (int m = 0; m < 6; ++m)
    {
      column[m] = storage(span - 2 + m, n, closed);
    }
    normal.add(column, row, 6, points[j]);
  }
  DeferredCondition condition;
  const Eigen::MatrixX3d solution = normal.solve(&condition);
  return fromSolution(knots, std::move(abscissae), solution, std::move(condition), closed);
}

std::vector<SpanParameter> TensionQuinticSpline::spanParameters() const
{
  const int spans = this->numberOfSpans();
  const int knots = static_cast<int>(this->Parameters.Gamma.size());
  auto perSpan = [&](const std::vector<double>& perKnot, const char* name) {
    SpanParameter p{ name, std::vector<double>(spans), false };
    for (int j = 0; j < spans; ++j)
    {
      p.Values[j] = std::min(perKnot[j], perKnot[(j + 1) % knots]);
    }
    return p;
  };
  std::vector<SpanParameter> out{ perSpan(this->Parameters.Gamma, "Gamma") };
  if (this->Parameters.Continuity == QuinticContinuity::C3)
  {
    out.push_back(perSpan(this->Parameters.Lambda, "Lambda"));
  }
  return out;
}

double TensionQuinticSpline::arcLengthOnSpan(int span, double a, double b) const
{
  auto speed = [&](double u) {
    return powerDerivatives(this->XCPower[span], u, 1, Eigen::Vector4d(Eigen::Vector4d::Zero()))[1]
      .tail<3>()
      .norm();
  };
  return gaussLegendre(speed, this->localParameter(span, a), this->localParameter(span, b));
}

Derivatives TensionQuinticSpline::evaluateOnSpan(int span, double x, int order) const
{
  const double u = this->localParameter(span, x);
  const auto xc =
    powerDerivatives(this->XCPower[span], u, order, Eigen::Vector4d(Eigen::Vector4d::Zero()));
  auto c = [&](int r) -> Vec3 { return xc[r].tail<3>(); };
  // Y(u) = s(X(u)) differentiated by Faa di Bruno, solved for the x-derivatives
  // of s; one division (by X'), the powers of its inverse multiply.
  Derivatives s;
  s.fill(Vec3::Zero());
  s[0] = c(0);
  const double x1 = xc[1][0], x2 = xc[2][0], x3 = xc[3][0], x4 = xc[4][0];
  const double inverse = 1.0 / x1;
  if (order >= 1)
  {
    s[1] = c(1) * inverse;
  }
  if (order >= 2)
  {
    s[2] = (c(2) - s[1] * x2) * (inverse * inverse);
  }
  if (order >= 3)
  {
    s[3] = (c(3) - 3.0 * s[2] * x1 * x2 - s[1] * x3) * (inverse * inverse * inverse);
  }
  if (order >= 4)
  {
    s[4] = (c(4) - 6.0 * s[3] * x1 * x1 * x2 - s[2] * (3.0 * x2 * x2 + 4.0 * x1 * x3) - s[1] * x4) *
      (inverse * inverse * inverse * inverse);
  }
  return s;
}
} // namespace shapesplines
