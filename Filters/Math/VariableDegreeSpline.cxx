#include "VariableDegreeSpline.h"

#include "Approximation.h"
#include "AutomaticShape.h"
#include "ExtendedIndex.h"
#include "SparseSolve.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shapesplines
{
namespace
{
/// x^n for a whole n >= 0 by squaring: the automatic degrees are whole, and
/// std::pow took a sixth of the automatic mode's time on noisy helices. Its
/// rounding grows with n (1 - v rounds, see complementPower): powers() takes
/// it up to n = 64 only, within 64 ulps.
double wholePower(double x, unsigned n)
{
  double result = 1.0;
  for (; n != 0; n >>= 1, x *= x)
  {
    result = (n & 1u) ? result * x : result;
  }
  return result;
}

/// x^(e - n) for n = 0..5, x in [0, 1], e >= 5: one power, then products.
/// oneMinus: x = 1 - v (complementPower).
std::array<double, 6> powers(double e, double v, bool oneMinus)
{
  const double x = oneMinus ? 1.0 - v : v;
  const double lowest = e - 5.0;
  double base = 1.0;
  if (lowest == std::floor(lowest) && lowest <= 64.0)
  {
    base = wholePower(x, static_cast<unsigned>(lowest));
  }
  else if (lowest != 0.0)
  {
    base = oneMinus ? complementPower(v, lowest) : std::pow(x, lowest);
  }
  std::array<double, 6> out;
  for (int n = 5; n >= 0; --n)
  {
    out[n] = base;
    base *= x;
  }
  return out;
}

/**
 * Spacings h_j, degrees k_i and tensions lambda_i at any index: periodic for
 * a closed curve, mirrored about the end knots of an open one (h_-1 = h_0,
 * k_-1 = k_1, ...), clamped when the curve is too short to mirror.
 */
class Extension
{
public:
  Extension(const std::vector<double>& knots, bool closed, const VariableDegreeParameters& p)
    : Knots(knots)
    , Closed(closed)
    , Parameters(p)
    , Spans(static_cast<int>(knots.size()) - 1)
  {
  }

  double h(int j) const
  {
    const int s = this->span(j);
    return this->Knots[s + 1] - this->Knots[s];
  }
  double lambda(int i) const { return this->Parameters.Lambda[this->knot(i)]; }
  double delta(int i) const { return 1.0 / this->Parameters.Degree[this->knot(i)]; }
  double degree(int i) const { return this->Parameters.Degree[this->knot(i)]; }

private:
  int span(int j) const { return extendedIndex(j, this->Spans, this->Closed, Beyond::MirrorIntervals); }
  int knot(int i) const
  {
    return extendedIndex(i, this->Closed ? this->Spans : this->Spans + 1, this->Closed, Beyond::MirrorEntries);
  }

  const std::vector<double>& Knots;
  bool Closed;
  const VariableDegreeParameters& Parameters;
  int Spans;
};

/**
 * The corner cutting of Costantini & Manni (VDPS) (section 3 and appendix)
 * giving the pseudo Bezier points b_i0..b_i5 of span
 * i from the de Boor points deBoor(j), j = i-2..i+3. T is a point, or a
 * vector of weights when the construction is applied to unit vectors.
 * r_i is the text's (h_{i+1} F_i^- + (h_{i-2} + h_{i-1} + h_i) F_i^+) /
 * (h_{i-2} + h_{i-1} + h_i + h_{i+1}), as in Cravero, Manni & Sampoli (13):
 * the appendix's version is a typo that still joins C3 but is not the C4
 * quintic at degree 5, lambda 1 (fourth-derivative jumps O(1), not 1e-13).
 */
template <class T, class DeBoor>
std::array<T, 6> spanNet(const Extension& e, int i, const DeBoor& deBoor)
{
  // On leg D_j D_j+1, cut in proportion lambda_j (h_j-2 + h_j-1) : h_j :
  // lambda_j+1 (h_j+1 + h_j+2): F_j^+ (first cut) and F_j+1^- (second cut).
  auto legPoint = [&](int j, bool second) -> T {
    const double a = e.lambda(j) * (e.h(j - 2) + e.h(j - 1));
    const double b = e.h(j);
    const double c = e.lambda(j + 1) * (e.h(j + 1) + e.h(j + 2));
    const double f = (second ? a + b : a) / (a + b + c);
    const T from = deBoor(j);
    return T(from + f * (deBoor(j + 1) - from));
  };
  // p_j and r_j on F_j^- F_j^+, in proportion h_j-2 : h_j-1 + h_j : h_j+1.
  struct Pair
  {
    T P, R;
  };
  auto pair = [&](int j) {
    const T minus = legPoint(j - 1, true);
    const T plus = legPoint(j, false);
    const double s = e.h(j - 2) + e.h(j - 1) + e.h(j) + e.h(j + 1);
    const T step = plus - minus;
    return Pair{ T(minus + e.h(j - 2) / s * step),
      T(minus + (e.h(j - 2) + e.h(j - 1) + e.h(j)) / s * step) };
  };
  // b_j2 and b_j3 on r_j p_j+1, in proportion delta_j h_j-1 :
  // (1 - 2 delta_j - 2 delta_j+1) h_j : delta_j+1 h_j+1.
  auto inner = [&](int j, const Pair& left, const Pair& right) {
    const double a = e.delta(j) * e.h(j - 1);
    const double b = (1.0 - 2.0 * e.delta(j) - 2.0 * e.delta(j + 1)) * e.h(j);
    const double c = e.delta(j + 1) * e.h(j + 1);
    const T step = right.P - left.R;
    return std::array<T, 2>{ T(left.R + a / (a + b + c) * step),
      T(left.R + (a + b) / (a + b + c) * step) };
  };
  // At knot j: q_j on p_j r_j, then b_j-1,4, b_j1 and b_j0, all in proportion h_j-1 : h_j.
  auto at = [&](int j, const T& thirdBefore, const T& secondAfter, const Pair& pr) {
    const double before = e.h(j - 1);
    const double after = e.h(j);
    const double sum = before + after;
    const T q = (after * pr.P + before * pr.R) / sum;
    const T fourth = (after * thirdBefore + before * q) / sum;
    const T first = (after * q + before * secondAfter) / sum;
    return std::array<T, 3>{ fourth, first, T((after * fourth + before * first) / sum) };
  };
  const Pair p0 = pair(i - 1), p1 = pair(i), p2 = pair(i + 1), p3 = pair(i + 2);
  const auto before = inner(i - 1, p0, p1);
  const auto own = inner(i, p1, p2);
  const auto after = inner(i + 1, p2, p3);
  const auto left = at(i, before[1], own[0], p1);
  const auto right = at(i + 1, own[1], after[0], p2);
  return { left[2], left[1], own[0], own[1], right[0], right[2] };
}

using Weights = Eigen::Matrix<double, 6, 1>;

/// Unit vector of de Boor index j's colour (j mod 6): the six de Boor points
/// of a span have distinct colours, so one construction gives all weights.
Weights colour(int j)
{
  Weights w = Weights::Zero();
  w[((j % 6) + 6) % 6] = 1.0;
  return w;
}

/// The de Boor index (i-2..i+3) that colour c stands for on span i.
int deBoorIndex(int span, int c)
{
  return span - 2 + (((c - (span - 2)) % 6) + 6) % 6;
}

/// How each pseudo Bezier point of a span depends on the de Boor points.
std::array<Weights, 6> spanWeights(const Extension& e, int span)
{
  return spanNet<Weights>(e, span, colour);
}

/// Adds row . weights to a row of triplets, de Boor index j to column(j).
template <class Column>
void addRow(Triplets& entries, int row, const Weights& weights, int span, double scale,
  const Column& column)
{
  for (int c = 0; c < 6; ++c)
  {
    if (weights[c] != 0.0)
    {
      entries.emplace_back(row, column(deBoorIndex(span, c)), scale * weights[c]);
    }
  }
}

/// sum_n B_n^(r)(v) weights(b_n): a derivative of the span as weights of de Boor points.
Weights derivativeWeights(const std::array<Jet, 6>& basis, const std::array<Weights, 6>& net, int r)
{
  Weights w = Weights::Zero();
  for (int n = 0; n < 6; ++n)
  {
    w += basis[n][r] * net[n];
  }
  return w;
}

void checkParameters(const std::vector<double>& knots, bool closed, const VariableDegreeParameters& p)
{
  const size_t knotCount = closed ? knots.size() - 1 : knots.size();
  if (knots.size() < 2 || p.Degree.size() != knotCount || p.Lambda.size() != knotCount)
  {
    throw std::invalid_argument(
      "variable degree spline: need a degree and a tension per knot and at least one span");
  }
  knotSpacings(knots, "variable degree spline"); // checks them
  for (size_t i = 0; i < knotCount; ++i)
  {
    if (!(p.Degree[i] >= LowestVariableDegree) || !std::isfinite(p.Degree[i]) ||
      !(p.Lambda[i] > 0.0) || !std::isfinite(p.Lambda[i]))
    {
      throw std::invalid_argument(
        "variable degree spline: degrees must be at least 5 and tensions positive and finite");
    }
  }
}

std::vector<Vec3> toPoints(const Eigen::MatrixX3d& solution)
{
  std::vector<Vec3> points(solution.rows());
  for (Eigen::Index j = 0; j < solution.rows(); ++j)
  {
    points[j] = solution.row(j).transpose();
  }
  return points;
}
} // namespace

std::array<Jet, 6> pseudoBernstein(double k, double m, double v, int order)
{
  const std::array<double, 6> a = powers(k, v, true);  // (1-v)^(k-n)
  const std::array<double, 6> b = powers(m, v, false); // v^(m-n)
  const double w = 1.0 - v;
  const double inverseK = 1.0 / k, inverseM = 1.0 / m;
  const double mix = 1.0 / (1.0 - 2.0 * inverseK - 2.0 * inverseM);
  // Falling factorials (k)_n, (k - 1)_n, (m)_n, (m - 1)_n, and the last two at n - 1.
  double fallingK = 1.0, fallingK1 = 1.0, fallingM = 1.0, fallingM1 = 1.0;
  double fallingK1Before = 0.0, fallingM1Before = 0.0;
  std::array<Jet, 6> out{};
  for (int n = 0; n <= order; ++n)
  {
    const double sign = n % 2 == 0 ? 1.0 : -1.0;
    // B1 = k v g, g = (1-v)^(k-1); B4 = m f (1-v), f = v^(m-1) (Leibniz).
    const double g = sign * fallingK1 * a[n + 1];
    const double gBefore = -sign * fallingK1Before * a[n];
    const double f = fallingM1 * b[n + 1];
    const double fBefore = fallingM1Before * b[n];
    out[0][n] = sign * fallingK * a[n];
    out[1][n] = k * (v * g + n * gBefore);
    out[4][n] = m * (f * w - n * fBefore);
    out[5][n] = fallingM * b[n];
    // B2 + B3 = rest and (2/k) B2 + (1 - 2/m) B3 = linear (precision at the abscissae).
    const double rest = (n == 0 ? 1.0 : 0.0) - out[0][n] - out[1][n] - out[4][n] - out[5][n];
    const double linear = (n == 0 ? v : (n == 1 ? 1.0 : 0.0)) - out[1][n] * inverseK -
      (1.0 - inverseM) * out[4][n] - out[5][n];
    out[3][n] = (linear - 2.0 * inverseK * rest) * mix;
    out[2][n] = rest - out[3][n];
    fallingK1Before = fallingK1;
    fallingM1Before = fallingM1;
    fallingK *= k - n;
    fallingK1 *= k - 1.0 - n;
    fallingM *= m - n;
    fallingM1 *= m - 1.0 - n;
  }
  return out;
}

VariableDegreeSpline::VariableDegreeSpline(std::vector<double> knots, bool closed)
  : Curve(std::move(knots), closed)
{
}

void VariableDegreeSpline::setNet()
{
  const Extension e(this->Knots, this->Closed, this->Parameters);
  const int spans = this->numberOfSpans();
  const int count = static_cast<int>(this->DeBoor.size());
  auto deBoor = [&](int j) -> Vec3 {
    return this->Closed ? this->DeBoor[((j % count) + count) % count] : this->DeBoor[j + 2];
  };
  this->Net.resize(spans);
  this->QuinticPower.resize(spans);
  this->Quintic.resize(spans);
  for (int i = 0; i < spans; ++i)
  {
    this->Net[i] = spanNet<Vec3>(e, i, deBoor);
    this->Quintic[i] = e.degree(i) == LowestVariableDegree && e.degree(i + 1) == LowestVariableDegree;
    if (this->Quintic[i])
    {
      this->QuinticPower[i] = bezierToPower(this->Net[i]);
    }
  }
}

VariableDegreeSpline VariableDegreeSpline::fromDeBoor(const std::vector<double>& knots,
  bool closed, const VariableDegreeParameters& parameters, const std::vector<Vec3>& deBoor)
{
  checkParameters(knots, closed, parameters);
  const size_t expected = closed ? knots.size() - 1 : knots.size() + 4;
  if (deBoor.size() != expected)
  {
    throw std::invalid_argument("variable degree spline: wrong number of de Boor points");
  }
  VariableDegreeSpline spline(knots, closed);
  spline.Parameters = parameters;
  spline.DeBoor = deBoor;
  spline.setNet();
  return spline;
}

VariableDegreeSpline VariableDegreeSpline::interpolate(const std::vector<Vec3>& points,
  const std::vector<double>& knots, bool closed, const VariableDegreeParameters& parameters,
  VariableDegreeEnds ends)
{
  const int spans = static_cast<int>(knots.size()) - 1;
  if (static_cast<int>(points.size()) != (closed ? spans : spans + 1) || (closed && spans < 3))
  {
    throw std::invalid_argument("variable degree spline: one point per knot, three or more when closed");
  }
  checkParameters(knots, closed, parameters);
  const Extension e(knots, closed, parameters);
  const int unknowns = closed ? spans : spans + 5;
  // Open: de Boor index j is unknown j + 2, and the data row of knot i is
  // row i + 2, so D_i sits on the diagonal; rows 0, 1 and the last two hold the ends.
  auto column = [&](int j) { return closed ? wrapIndex(j, spans) : j + 2; };
  const int offset = closed ? 0 : 2;
  Triplets entries;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(unknowns, 3);
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
  {
    // s(u_i) = b_i0, or b_m-1,5 at the last knot of an open curve.
    const int span = std::min(i, spans - 1);
    const Weights w = spanWeights(e, span)[i == span ? 0 : 5];
    addRow(entries, i + offset, w, span, 1.0, column);
    rhs.row(i + offset) = points[i].transpose();
  }
  if (!closed)
  {
    const int last = unknowns - 1;
    if (ends == VariableDegreeEnds::Clamped)
    {
      for (const auto& [row, a, b] : { std::array<int, 3>{ 0, -2, -1 }, { 1, -1, 0 },
             { last - 1, spans + 1, spans }, { last, spans + 2, spans + 1 } })
      {
        entries.emplace_back(row, column(a), 1.0);
        entries.emplace_back(row, column(b), -1.0);
      }
    }
    else
    {
      // s'' and s''' at both ends: zero (natural) or the end quintic's, each
      // row scaled to a largest entry of 1 (derivatives in the local v: h^r
      // times those in u).
      for (const int end : { 0, 1 })
      {
        const int span = end == 0 ? 0 : spans - 1;
        const auto basis = pseudoBernstein(e.degree(span), e.degree(span + 1), end);
        const auto net = spanWeights(e, span);
        const double h = knots[span + 1] - knots[span];
        const double fade = std::pow(LowestVariableDegree / e.degree(end == 0 ? 0 : spans), 3);
        const auto polynomial = ends == VariableDegreeEnds::Polynomial
          ? polynomialEndDerivatives(points, knots, end == 0, 6)
          : std::array<Vec3, 3>{ Vec3::Zero(), Vec3::Zero(), Vec3::Zero() };
        for (const int r : { 2, 3 })
        {
          const Weights w = derivativeWeights(basis, net, r);
          const int row = end == 0 ? r - 2 : last - 3 + r;
          const double scale = 1.0 / w.cwiseAbs().maxCoeff();
          addRow(entries, row, w, span, scale, column);
          rhs.row(row) = (scale * fade * std::pow(h, r) * polynomial[r - 1]).transpose();
        }
      }
    }
  }
  VariableDegreeSpline spline(knots, closed);
  spline.Parameters = parameters;
  spline.DeBoor = toPoints(solveSparse(unknowns, entries, rhs, &spline.Condition));
  spline.setNet();
  return spline;
}

VariableDegreeSpline VariableDegreeSpline::approximate(const std::vector<Vec3>& points,
  const std::vector<double>& u, const std::vector<double>& knots, bool closed,
  const VariableDegreeParameters& parameters, const std::vector<double>& weights,
  const std::vector<Vec3>& anchors, bool clampedEnds)
{
  const int spans = static_cast<int>(knots.size()) - 1;
  checkParameters(knots, closed, parameters);
  const size_t knotCount = closed ? spans : spans + 1;
  if (u.size() < points.size() || weights.size() != knotCount || anchors.size() != knotCount ||
    points.size() < (closed || clampedEnds ? knotCount : knotCount + 4) || (closed && spans < 3))
  {
    throw std::invalid_argument("variable degree spline: too few points to approximate, or a "
                                "weight and an anchor missing for some knot");
  }
  const Extension e(knots, closed, parameters);
  std::vector<std::array<Weights, 6>> nets(spans);
  for (int i = 0; i < spans; ++i)
  {
    nets[i] = spanWeights(e, i);
  }
  // Clamped ends: D_-2 = D_-1 = D_0 and D_m+2 = D_m+1 = D_m, so the unknowns
  // are D_0..D_m (the polygon limit of Theorem 4 then ends at psi's ends);
  // free ones, all m + 5; a closed curve's D_j wrap around.
  auto column = [&](int j) {
    return closed ? wrapIndex(j, spans) : (clampedEnds ? std::clamp(j, 0, spans) : j + 2);
  };
  const int unknowns = closed || clampedEnds ? static_cast<int>(knotCount) : spans + 5;
  NormalEquations normal(unknowns);
  auto addSquare = [&](const Weights& w, int span, double weight, const Vec3& target) {
    int columns[6];
    for (int a = 0; a < 6; ++a)
    {
      columns[a] = column(deBoorIndex(span, a));
    }
    normal.add(columns, w, 6, target, weight);
  };
  for (size_t j = 0; j < points.size(); ++j)
  {
    const int span = std::clamp(
      static_cast<int>(std::upper_bound(knots.begin(), knots.end(), u[j]) - knots.begin()) - 1, 0,
      spans - 1);
    const double v = std::clamp((u[j] - knots[span]) / (knots[span + 1] - knots[span]), 0.0, 1.0);
    addSquare(derivativeWeights(pseudoBernstein(e.degree(span), e.degree(span + 1), v), nets[span], 0),
      span, 1.0, points[j]);
  }
  for (int i = 0; i < static_cast<int>(knotCount); ++i)
  {
    if (weights[i] > 0.0)
    {
      const int span = std::min(i, spans - 1);
      addSquare(nets[span][i == span ? 0 : 5], span, weights[i], anchors[i]);
    }
  }
  VariableDegreeSpline spline(knots, closed);
  spline.Parameters = parameters;
  const std::vector<Vec3> free =
    toPoints(normal.solve(&spline.Condition));
  for (int j = closed ? 0 : -2; j <= (closed ? spans - 1 : spans + 2); ++j)
  {
    spline.DeBoor.push_back(free[column(j)]);
  }
  spline.setNet();
  return spline;
}

Derivatives VariableDegreeSpline::evaluateOnSpan(int span, double u, int order) const
{
  const double h = this->Knots[span + 1] - this->Knots[span];
  const double v = std::clamp((u - this->Knots[span]) / h, 0.0, 1.0);
  Derivatives out;
  if (this->Quintic[span])
  {
    // The quintic Bernstein basis: the span's power form.
    out = powerDerivatives(this->QuinticPower[span], v, order, Vec3(Vec3::Zero()));
    scaleDerivatives(out, h, order);
    return out;
  }
  const int knots = static_cast<int>(this->Parameters.Degree.size());
  const auto basis = pseudoBernstein(
    this->Parameters.Degree[span], this->Parameters.Degree[(span + 1) % knots], v, order);
  const auto& net = this->Net[span];
  out.fill(Vec3::Zero());
  double scale = 1.0; // h^-r: derivatives with respect to u
  for (int r = 0; r <= order; ++r)
  {
    for (int n = 0; n < 6; ++n)
    {
      out[r] += (scale * basis[n][r]) * net[n];
    }
    scale /= h;
  }
  return out;
}

std::vector<SpanParameter> VariableDegreeSpline::spanParameters() const
{
  const int spans = this->numberOfSpans();
  const int knots = static_cast<int>(this->Parameters.Degree.size());
  SpanParameter degree{ "Degree", std::vector<double>(spans), true };
  for (int j = 0; j < spans; ++j)
  {
    degree.Values[j] = std::max(this->Parameters.Degree[j], this->Parameters.Degree[(j + 1) % knots]);
  }
  return { degree };
}

double raisedDegree(double degree, double maxDegree)
{
  return std::max(degree, std::min(std::ceil(std::cbrt(2.0) * degree), maxDegree));
}

namespace
{
/// The parameters of the options for the given degrees; naturalEnds (or
/// polynomial ends, the same system): lambda falls as 5 / k at the two knots
/// next to each end (see VariableDegreeOptions).
VariableDegreeParameters parametersFor(
  const std::vector<double>& degrees, const VariableDegreeOptions& options, bool naturalEnds)
{
  const int knots = static_cast<int>(degrees.size());
  VariableDegreeParameters p{ degrees, degrees };
  for (int i = 0; i < knots; ++i)
  {
    const bool end = naturalEnds && (i < 2 || i >= knots - 2);
    p.Lambda[i] = options.ScaleLambdaWithDegree
      ? options.Lambda * std::pow(LowestVariableDegree / degrees[i], end ? 1 : 3)
      : options.Lambda;
  }
  return p;
}

/// The degrees per knot at the ladder's levels per span, from the start degrees.
std::vector<double> degreesAt(const std::vector<double>& start, const std::vector<int>& levels,
  bool closed, double maxDegree)
{
  const std::vector<int> perKnot = knotLevels(levels, closed);
  std::vector<double> degrees(start.size());
  for (size_t i = 0; i < start.size(); ++i)
  {
    degrees[i] = raisedTimes(start[i], perKnot[i], [&](double k) { return raisedDegree(k, maxDegree); });
  }
  return degrees;
}

int topLevel(const std::vector<double>& start, double maxDegree)
{
  return stepsToCap(*std::min_element(start.begin(), start.end()),
    [&](double k) { return raisedDegree(k, maxDegree); });
}

BuiltCurve interpolateData(const FitContext& context, const VariableDegreeOptions& options,
  const std::vector<double>& startDegrees)
{
  const CleanPolyline& data = context.Data;
  ShapeLadder ladder;
  ladder.TopLevel = topLevel(startDegrees, options.MaxDegree);
  ladder.MaxRounds = options.MaxRounds;
  ladder.Reach = 3; // a knot's parameter moves the spans on both sides and the global solve
  ladder.RetrySpanBySpan = true; // the interpolation is meant to reach zero violations
  ladder.RetryFromCommonLevel = true;
  ladder.RefineBackToLevelZero = false;
  ladder.Build = [&](const std::vector<int>& levels) -> std::unique_ptr<Curve> {
    const std::vector<double> degrees = degreesAt(startDegrees, levels, data.Closed, options.MaxDegree);
    return std::make_unique<VariableDegreeSpline>(VariableDegreeSpline::interpolate(data.Points,
      context.Knots, data.Closed,
      parametersFor(degrees, options, !data.Closed && options.Ends != VariableDegreeEnds::Clamped),
      options.Ends));
  };
  return fixedOrAutomatic(options.Automatic, context, data, ladder);
}

BuiltCurve approximateData(const FitContext& context, const VariableDegreeOptions& options,
  const ApproximationPlan& plan, int knotCount, double startDegree)
{
  // knotCount knots, the distinct ones of a closed line (the closing knot repeats the first).
  const bool closed = context.Data.Closed;
  const int spans = closed ? knotCount : knotCount - 1;
  const ExtendedData data = extendForApproximation(context.Data.Points, plan.Parameters, knotCount, closed);
  const int allKnots = closed ? knotCount : static_cast<int>(data.Knots.size());
  ReferencePolygon psi = referencePolygon(data, closed, plan.NoiseLevel);
  const std::vector<double> start(allKnots, startDegree);
  const bool local = options.Mode == VariableDegreeMode::ApproximateLocal;
  // The local scheme also pulls the curve towards psi at the knots of raised
  // spans: an anchor's first weight counts like the points of one span, and
  // it grows 4x a level up to a million times that (then the curve all but
  // passes through psi).
  const double firstWeight = static_cast<double>(context.Data.Points.size()) / spans;
  ShapeLadder ladder;
  ladder.TopLevel = topLevel(start, options.MaxDegree);
  ladder.MaxRounds = options.MaxRounds;
  ladder.Reach = 3; // a knot's parameter moves the spans on both sides and the global solve
  ladder.Uniform = !local; // the global scheme: every degree together (Theorem 4)
  ladder.ReferenceNoise = psi.VertexNoise;
  ladder.Bounds.CurvatureChange = 2.0; // keeping psi's shape must not flatten the fit
  ladder.Build = [&](const std::vector<int>& levels) -> std::unique_ptr<Curve> {
    const std::vector<int> all = data.Extra > 0 ? extendedLevels(levels, data.Extra) : levels;
    const std::vector<int> perKnot = knotLevels(all, closed);
    std::vector<double> weights(allKnots, 0.0);
    for (int i = 0; i < allKnots && local; ++i)
    {
      weights[i] = perKnot[i] == 0 ? 0.0 : firstWeight * std::min(std::pow(4.0, perKnot[i] - 1), 1e6);
    }
    auto whole = std::make_unique<VariableDegreeSpline>(VariableDegreeSpline::approximate(data.Points,
      data.Parameters, data.Knots, closed,
      parametersFor(degreesAt(start, all, closed, options.MaxDegree), options, false), weights, psi.Whole,
      false));
    if (data.Extra == 0)
    {
      return whole;
    }
    return std::make_unique<TrimmedCurve>(std::move(whole), data.Extra, spans);
  };
  BuiltCurve built = fixedOrAutomatic(options.Automatic, context, psi.Polygon, ladder);
  built.ShapeReference = std::move(psi.Polygon);
  built.ReferenceNoise = std::move(psi.VertexNoise);
  return built;
}
} // namespace

CurveBuilder variableDegreeBuilder(const VariableDegreeOptions& options)
{
  return [options](const FitContext& context) {
    const int count = static_cast<int>(context.Data.Points.size());
    // Degrees below 5 do not exist; automatic rounds stop at the cap or the start.
    const double start = std::max(LowestVariableDegree, options.Degree);
    VariableDegreeOptions capped = options;
    capped.MaxDegree = std::max(start, options.MaxDegree);
    if (options.Mode != VariableDegreeMode::Interpolate)
    {
      const bool closed = context.Data.Closed;
      const int highest = count / 2;
      std::optional<BuiltCurve> approximation = approximateWithPlan(context.Data.Points,
        context.Knots, options.ApproximationKnots, closed, highest, options.CorrectParameters,
        context.Options.Progress,
        [&](const ApproximationPlan& plan, int knots) {
          return approximateData(context, capped, plan, knots, start);
        });
      if (approximation)
      {
        return std::move(*approximation);
      }
    }
    std::vector<double> degrees(count, start);
    const auto& given = context.PointValues;
    for (size_t i = 0; i < degrees.size() && !given.empty(); ++i)
    {
      const double value = given[i % given.size()];
      if (std::isfinite(value) && value >= LowestVariableDegree)
      {
        degrees[i] = std::min(value, HighestVariableDegree);
      }
    }
    return interpolateData(context, capped, degrees);
  };
}
} // namespace shapesplines
