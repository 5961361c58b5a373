// C2 generalized cubic splines (Costantini & Manni (generalized cubics)): kernels, the generalized
// Bernstein basis, the generalized B-splines of section 3, interpolation,
// automatic tension and accuracy.
#include "GeneralizedCubicSpline.h"
#include "MathTestUtilities.h"

#include <gtest/gtest.h>

#include <Eigen/QR>

#include <cmath>
#include <cstdio>
#include <random>

using namespace shapesplines;
using namespace shapesplines::test;

namespace
{
struct KindTension
{
  SpaceKind Kind;
  double Tension;
};

/// Every kind over its range of tension, from the cubic limit to the polygon limit.
std::vector<KindTension> Kernels()
{
  std::vector<KindTension> all = { { SpaceKind::Polynomial, 0.0 } };
  for (const double p : { 1e-9, 1e-3, 0.1, 0.9, 1.0, 2.0, 10.0, 100.0, 700.0, 1000.0 })
  {
    all.push_back({ SpaceKind::Exponential, p });
  }
  for (const double p : { 1e-9, 1e-3, 0.5, 1.0, 2.0, 3.0, 3.1 })
  {
    all.push_back({ SpaceKind::Trigonometric, p });
  }
  for (const double k : { 3.0, 3.5, 4.0, 7.0, 20.0, 200.0 })
  {
    all.push_back({ SpaceKind::VariableDegree, k });
  }
  return all;
}

/// The kernels straight from their definitions in long double (no rescaling, no series).
long double referenceU(SpaceKind kind, long double p, long double t)
{
  const long double x = p * (1 - t);
  switch (kind)
  {
    case SpaceKind::Exponential:
      return (std::sinh(x) - x) / (std::sinh(p) - p);
    case SpaceKind::Trigonometric:
      return (x - std::sin(x)) / (p - std::sin(p));
    case SpaceKind::VariableDegree:
      return std::pow(1 - t, p);
    default:
      return std::pow(1 - t, 3.0L);
  }
}
} // namespace

TEST(GeneralizedCubicKernel, NormalisationAndDerivativesForEveryKindAndTension)
{
  for (const auto& [kind, p] : Kernels())
  {
    const SpaceKernel kernel(kind, p);
    const Jet u0 = kernel.u(0.0);
    const Jet u1 = kernel.u(1.0);
    // (4): u(0) = 1, u(1) = u'(1) = u''(1) = 0; (5) for v by symmetry.
    EXPECT_NEAR(u0[0], 1.0, 1e-14) << int(kind) << " " << p;
    EXPECT_EQ(u1[0], 0.0);
    EXPECT_EQ(u1[1], 0.0);
    EXPECT_EQ(u1[2], 0.0);
    EXPECT_NEAR(kernel.v(1.0)[0], 1.0, 1e-14);
    EXPECT_EQ(kernel.v(0.0)[2], 0.0);
    // (6), (7): u' < 0, u'' > 0 on [0, 1), -u'(0) > 2 (so xi + eta < 1).
    EXPECT_GT(kernel.uSlope(), 2.0);
    for (const double t : { 0.0, 0.1, 0.5, 0.9 })
    {
      const Jet u = kernel.u(t);
      for (const double value : u)
      {
        ASSERT_TRUE(std::isfinite(value)) << int(kind) << " " << p << " t " << t;
      }
      // Strictly where e^(-p t) is representable; it underflows to 0 beyond.
      EXPECT_LE(u[1], 0.0);
      EXPECT_GE(u[2], 0.0);
      if (p * t < 600)
      {
        EXPECT_LT(u[1], 0.0) << int(kind) << " " << p << " t " << t;
        EXPECT_GT(u[2], 0.0) << int(kind) << " " << p << " t " << t;
      }
    }
    // Derivatives against central differences of the next lower one.
    for (const double t : { 0.2, 0.5, 0.8 })
    {
      const double step = 1e-6 / std::max(1.0, p / 10.0);
      const Jet above = kernel.u(t + step);
      const Jet below = kernel.u(t - step);
      const Jet here = kernel.u(t);
      for (int m = 1; m < 5; ++m)
      {
        const double difference = (above[m - 1] - below[m - 1]) / (2 * step);
        const double scale = std::max({ std::abs(here[m]), std::abs(here[m - 1]) / step * 1e-9, 1e-300 });
        EXPECT_NEAR(difference, here[m], 1e-5 * scale + 1e-7 * std::abs(here[m]))
          << "kind " << int(kind) << " p " << p << " t " << t << " order " << m;
      }
    }
  }
}

TEST(GeneralizedCubicKernel, MatchesTheDefinitionWhereItCanBeEvaluatedDirectly)
{
  // Long double on the raw formulas, where they neither overflow nor cancel.
  for (const auto& [kind, p] : std::vector<KindTension>{ { SpaceKind::Exponential, 0.5 },
         { SpaceKind::Exponential, 3.0 }, { SpaceKind::Exponential, 30.0 },
         { SpaceKind::Trigonometric, 0.5 }, { SpaceKind::Trigonometric, 2.5 },
         { SpaceKind::VariableDegree, 7.0 }, { SpaceKind::VariableDegree, 200.0 } })
  {
    const SpaceKernel kernel(kind, p);
    for (const double t : { 0.0, 0.05, 0.3, 0.5, 0.77, 0.95 })
    {
      const double reference = static_cast<double>(referenceU(kind, p, t));
      EXPECT_NEAR(kernel.u(t)[0], reference, 1e-13 * std::max(reference, 1e-3))
        << int(kind) << " " << p << " " << t;
    }
  }
  // Tension to 0: the exponential and trigonometric kernels tend to the cubic, as p^2.
  for (const SpaceKind kind : { SpaceKind::Exponential, SpaceKind::Trigonometric })
  {
    double previous = 1.0;
    for (const double p : { 0.4, 0.2, 0.1, 0.05 })
    {
      const double difference =
        std::abs(SpaceKernel(kind, p).u(0.4)[0] - std::pow(0.6, 3.0));
      EXPECT_LT(difference, 0.3 * previous) << int(kind) << " " << p;
      previous = difference;
    }
  }
}

TEST(GeneralizedBernstein, Theorem1ForEveryKindOverItsTensionRange)
{
  for (const auto& [kind, p] : Kernels())
  {
    const SpaceKernel kernel(kind, p);
    const double xi = 1.0 / kernel.uSlope();
    const double eta = 1.0 / kernel.vSlope();
    const std::array<double, 4> tau = { 0.0, xi, 1.0 - eta, 1.0 };
    for (int i = 0; i <= 20; ++i)
    {
      const double t = i / 20.0;
      const auto b = generalizedBernstein(kernel, t);
      double sum = 0.0, linear = 0.0;
      for (int j = 0; j < 4; ++j)
      {
        sum += b[j][0];
        linear += tau[j] * b[j][0];
        // Positive in (0, 1), where u = e^(-p t) and v = e^(-p (1 - t)) do not underflow.
        EXPECT_GE(b[j][0], 0.0);
        if (i > 0 && i < 20 && p * std::max(t, 1 - t) < 600)
        {
          EXPECT_GT(b[j][0], 0.0) << "B" << j << " at " << t << " kind " << int(kind) << " p " << p;
        }
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
      EXPECT_NEAR(linear, t, 1e-14);
    }
    // The end conditions listed before Theorem 1.
    const auto at0 = generalizedBernstein(kernel, 0.0);
    const auto at1 = generalizedBernstein(kernel, 1.0);
    const double w = kernel.uSlope();
    const double tolerance = 1e-12 * std::max(1.0, w * w);
    EXPECT_NEAR(at0[0][0], 1.0, 1e-14);
    EXPECT_EQ(at1[0][0], 0.0);
    EXPECT_EQ(at1[0][1], 0.0);
    EXPECT_EQ(at1[0][2], 0.0);
    EXPECT_NEAR(at0[1][0], 0.0, 1e-14);
    EXPECT_NEAR(at0[1][1], w, tolerance);
    EXPECT_NEAR(at1[1][0], 0.0, 1e-14);
    EXPECT_NEAR(at1[1][1], 0.0, tolerance);
    EXPECT_NEAR(at0[2][0], 0.0, 1e-14);
    EXPECT_NEAR(at0[2][1], 0.0, tolerance);
    EXPECT_NEAR(at1[2][0], 0.0, 1e-14);
    EXPECT_NEAR(at1[2][1], -kernel.vSlope(), tolerance);
    EXPECT_EQ(at0[3][0], 0.0);
    EXPECT_EQ(at0[3][1], 0.0);
    EXPECT_EQ(at0[3][2], 0.0);
    EXPECT_NEAR(at1[3][0], 1.0, 1e-14);
  }
}

TEST(GeneralizedBernstein, DeCasteljauLikeEvaluationEqualsDirectEvaluation)
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coefficient(-2.0, 2.0);
  const std::vector<SpaceKernel> kernels = { SpaceKernel(SpaceKind::Polynomial, 0),
    SpaceKernel(SpaceKind::Exponential, 2.0), SpaceKernel(SpaceKind::Exponential, 40.0),
    SpaceKernel(SpaceKind::Trigonometric, 3.0), SpaceKernel(SpaceKind::VariableDegree, 10.0),
    SpaceKernel(SpaceKind::VariableDegree, 10.0, SpaceKind::Polynomial, 0.0) };
  for (const SpaceKernel& kernel : kernels)
  {
    const std::array<double, 4> b = { coefficient(random), coefficient(random),
      coefficient(random), coefficient(random) };
    for (int i = 0; i <= 10; ++i)
    {
      const double t = i / 10.0;
      const auto basis = generalizedBernstein(kernel, t);
      double direct = 0.0;
      for (int j = 0; j < 4; ++j)
      {
        direct += b[j] * basis[j][0];
      }
      EXPECT_NEAR(deCasteljau(kernel, b, t), direct, 1e-13) << "t " << t;
    }
  }
}

namespace
{
/// The paper's examples on knots 0, 2, 3, 3.5, 5, extended by three knots a
/// unit apart on each side (cubic phantom intervals).
struct PaperExample
{
  std::vector<double> Knots; // x_-3 .. x_7
  std::vector<SpaceKernel> Kernels;
};

PaperExample Example(int number)
{
  PaperExample e;
  e.Knots = { -3, -2, -1, 0, 2, 3, 3.5, 5, 6, 7, 8 };
  const SpaceKernel cubic(SpaceKind::Polynomial, 0);
  e.Kernels.assign(e.Knots.size() - 1, cubic);
  if (number == 1)
  {
    // span<1, t, exp(2t), exp(-2t)> on [2, 3] and exp(+-4t) on [3, 3.5].
    e.Kernels[4] = SpaceKernel(SpaceKind::Exponential, 2.0);
    e.Kernels[5] = SpaceKernel(SpaceKind::Exponential, 4.0);
  }
  else
  {
    // cos 3t, sin 3t; cubic; exp(+-6t); (1 - t)^10 with t^3.
    e.Kernels[3] = SpaceKernel(SpaceKind::Trigonometric, 3.0);
    e.Kernels[5] = SpaceKernel(SpaceKind::Exponential, 6.0);
    e.Kernels[6] = SpaceKernel(SpaceKind::VariableDegree, 10.0, SpaceKind::Polynomial, 0.0);
  }
  return e;
}

/// B^(i) on interval k at local t (derivatives 0..3 in x).
Jet BSpline(const PaperExample& e, int i, int k, double t)
{
  std::vector<double> deBoor(e.Knots.size(), 0.0);
  deBoor[i] = 1.0;
  const auto bezier = bezierFromDeBoor(e.Knots, e.Kernels, deBoor)[k];
  const auto basis = generalizedBernstein(e.Kernels[k], t);
  const double h = e.Knots[k + 1] - e.Knots[k];
  Jet value{};
  for (int m = 0; m < 4; ++m)
  {
    for (int j = 0; j < 4; ++j)
    {
      value[m] += bezier[j] * basis[j][m];
    }
    value[m] /= std::pow(h, m);
  }
  return value;
}
} // namespace

TEST(GeneralizedBSplines, PaperExamplesAreC2NonNegativePartitionOfUnityWithCompactSupport)
{
  for (const int number : { 1, 2 })
  {
    const PaperExample e = Example(number);
    const int intervals = static_cast<int>(e.Knots.size()) - 1;
    // Intervals 2..intervals-3 have their Bezier coefficients; B^(i) for every i.
    double largestThirdJump = 0.0;
    for (int i = 0; i < static_cast<int>(e.Knots.size()); ++i)
    {
      for (int k = 3; k <= intervals - 3; ++k)
      {
        const Jet left = BSpline(e, i, k - 1, 1.0);
        const Jet right = BSpline(e, i, k, 0.0);
        for (int m = 0; m <= 2; ++m)
        {
          const double scale = std::max({ std::abs(left[m]), std::abs(right[m]), 1.0 });
          EXPECT_LE(std::abs(left[m] - right[m]), 1e-9 * scale)
            << "example " << number << " B^(" << i << ") order " << m << " at x = " << e.Knots[k];
        }
        largestThirdJump = std::max(largestThirdJump, std::abs(left[3] - right[3]));
      }
    }
    EXPECT_GT(largestThirdJump, 1e-3) << "the third derivative should jump: only C2 is claimed";
    // On the data knots' range: non-negative, partition of unity, support (x_i-2, x_i+2).
    for (int k = 3; k <= 6; ++k)
    {
      for (int s = 0; s <= 10; ++s)
      {
        const double t = s / 10.0;
        const double x = e.Knots[k] + t * (e.Knots[k + 1] - e.Knots[k]);
        double sum = 0.0;
        for (int i = 0; i < static_cast<int>(e.Knots.size()); ++i)
        {
          const double value = BSpline(e, i, k, t)[0];
          sum += value;
          EXPECT_GE(value, -1e-14) << "example " << number << " B^(" << i << ") at " << x;
          // The de Boor point P_i sits at sigma_i, near x_i: B^(i) vanishes outside (x_i-2, x_i+2).
          if (k + 1 <= i - 2 || k >= i + 2)
          {
            EXPECT_EQ(value, 0.0) << "example " << number << " B^(" << i << ") at " << x;
          }
        }
        EXPECT_NEAR(sum, 1.0, 1e-13) << "example " << number << " at " << x;
      }
    }
  }
}

namespace
{
GeneralizedCubicSpline Interpolate(const std::vector<Vec3>& points, SpaceKind kind, double p,
  bool closed = false)
{
  CleanPolyline data = cleanPolyline(points, closed);
  const auto knots = computeKnots(data, Parameterization::ChordLength);
  const int spans = data.numberOfSpans();
  return GeneralizedCubicSpline::interpolate(
    data.Points, knots, data.Closed, std::vector<SpaceKernel>(spans, SpaceKernel(kind, p)));
}
} // namespace

TEST(GeneralizedCubicSpline, InterpolatesAndIsC2AtEveryKnotWithMixedKinds)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const bool closed : { false, true })
  {
    std::vector<Vec3> points;
    std::vector<double> knots = { 0.0 };
    for (int i = 0; i < 12; ++i)
    {
      points.emplace_back(unit(random), unit(random), unit(random));
      knots.push_back(knots.back() + 0.2 + unit(random));
    }
    if (!closed)
    {
      knots.pop_back();
    }
    std::vector<SpaceKernel> kernels;
    for (size_t k = 0; k + 1 < knots.size(); ++k)
    {
      switch (k % 4)
      {
        case 0:
          kernels.emplace_back(SpaceKind::Polynomial, 0);
          break;
        case 1:
          kernels.emplace_back(SpaceKind::Exponential, 1.5 + 8 * unit(random));
          break;
        case 2:
          kernels.emplace_back(SpaceKind::Trigonometric, 1 + unit(random));
          break;
        default:
          kernels.emplace_back(SpaceKind::VariableDegree, 4 + 8 * unit(random));
      }
    }
    const auto spline = GeneralizedCubicSpline::interpolate(points, knots, closed, kernels);
    double thirdJump = 0.0;
    for (int j = 0; j < spline.numberOfSpans(); ++j)
    {
      EXPECT_LT((spline.evaluateOnSpan(j, knots[j], 0)[0] - points[j]).norm(), 1e-14);
      if (j == 0 && !closed)
      {
        continue;
      }
      const int before = (j - 1 + spline.numberOfSpans()) % spline.numberOfSpans();
      const Derivatives left = spline.evaluateOnSpan(before, knots[before + 1], 3);
      const Derivatives right = spline.evaluateOnSpan(j, knots[j], 3);
      for (int m = 0; m <= 2; ++m)
      {
        EXPECT_LE(relativeJump(left[m], right[m]), 1e-9) << "knot " << j << " order " << m;
      }
      thirdJump = std::max(thirdJump, relativeJump(left[3], right[3]));
    }
    EXPECT_GT(thirdJump, 1e-3);
    if (!closed)
    {
      // Natural ends.
      EXPECT_LT(spline.evaluateOnSpan(0, knots[0], 2)[2].norm(), 1e-12);
      EXPECT_LT(spline.evaluate(knots.back(), 2)[2].norm(), 1e-12);
    }
  }
}

TEST(GeneralizedBSplines, InterpolationInTheBSplineBasisIsTheInterpolatingSpline)
{
  // The interpolant, built from the paper's generalized B-splines: solve for the
  // de Boor values P_i (knots x_0..x_n of the first example's data range, mixed
  // kinds) with s(x_j) = y_j and natural ends, then compare with the solver.
  const PaperExample e = Example(2);
  const int m = static_cast<int>(e.Knots.size()) - 1; // intervals; data knots are 3..7
  const std::vector<double> y = { 1.0, -0.5, 2.0, 0.3, 1.2 };
  const int unknowns = m + 1;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(7, unknowns);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(7);
  for (int j = 0; j < 5; ++j)
  {
    const int k = std::min(3 + j, 6); // the interval starting at x_j (the last: its end)
    const double t = 3 + j <= 6 ? 0.0 : 1.0;
    for (int i = 0; i < unknowns; ++i)
    {
      a(j, i) = BSpline(e, i, k, t)[0];
    }
    b(j) = y[j];
  }
  for (int i = 0; i < unknowns; ++i)
  {
    a(5, i) = BSpline(e, i, 3, 0.0)[2]; // s''(x_0) = 0
    a(6, i) = BSpline(e, i, 6, 1.0)[2]; // s''(x_4) = 0
  }
  // Only the de Boor values whose B-splines reach [x_0, x_4] matter: least squares
  // picks the minimum-norm solution, whose curve on [x_0, x_4] is unique.
  const Eigen::VectorXd deBoor = a.completeOrthogonalDecomposition().solve(b);
  ASSERT_LT((a * deBoor - b).norm(), 1e-12);

  std::vector<Vec3> points;
  for (const double value : y)
  {
    points.emplace_back(value, 0.0, 0.0);
  }
  const std::vector<double> knots(e.Knots.begin() + 3, e.Knots.begin() + 8);
  const std::vector<SpaceKernel> kernels(e.Kernels.begin() + 3, e.Kernels.begin() + 7);
  const auto spline = GeneralizedCubicSpline::interpolate(points, knots, false, kernels);
  double largest = 0.0;
  for (int k = 3; k <= 6; ++k)
  {
    for (int s = 0; s <= 10; ++s)
    {
      const double t = s / 10.0;
      double fromBasis = 0.0;
      for (int i = 0; i < unknowns; ++i)
      {
        fromBasis += deBoor(i) * BSpline(e, i, k, t)[0];
      }
      const double x = e.Knots[k] + t * (e.Knots[k + 1] - e.Knots[k]);
      largest = std::max(largest, std::abs(spline.evaluateOnSpan(k - 3, x, 0)[0].x() - fromBasis));
    }
  }
  EXPECT_LT(largest, 1e-12);
}

TEST(GeneralizedCubicSpline, PolynomialKindIsTheClassicalNaturalCubic)
{
  const std::vector<Vec3> points = helix(8, 2);
  CleanPolyline data = cleanPolyline(points, false);
  const auto knots = computeKnots(data, Parameterization::ChordLength);
  const auto cubic = CubicSpline::interpolate(data.Points, knots, false, CubicEndCondition::Natural);
  const auto general = Interpolate(points, SpaceKind::Polynomial, 0.0);
  double largest = 0.0;
  for (int j = 0; j < cubic.numberOfSpans(); ++j)
  {
    for (int s = 0; s <= 8; ++s)
    {
      const double t = knots[j] + s / 8.0 * (knots[j + 1] - knots[j]);
      const Derivatives a = cubic.evaluateOnSpan(j, t, 3);
      const Derivatives b = general.evaluateOnSpan(j, t, 3);
      for (int m = 0; m <= 3; ++m)
      {
        largest = std::max(largest, (a[m] - b[m]).norm() / std::max(1.0, a[m].norm()));
      }
    }
  }
  EXPECT_LT(largest, 1e-12);
  // The tension kinds tend to it: exponential and trigonometric as p -> 0, degree 3 exactly.
  for (const SpaceKind kind : { SpaceKind::Exponential, SpaceKind::Trigonometric })
  {
    double previous = 1.0;
    for (const double p : { 0.8, 0.4, 0.2, 0.1 })
    {
      const auto tense = Interpolate(points, kind, p);
      const double distance = (tense.evaluate(5.3, 0)[0] - cubic.evaluate(5.3, 0)[0]).norm();
      EXPECT_LT(distance, 0.3 * previous) << int(kind) << " p " << p;
      previous = distance;
    }
  }
  EXPECT_LT((Interpolate(points, SpaceKind::VariableDegree, 3.0).evaluate(5.3, 0)[0] -
              cubic.evaluate(5.3, 0)[0])
              .norm(),
    1e-13);
}

TEST(GeneralizedCubicSpline, PolynomialEndsReproduceACubicCurve)
{
  // A cubic curve on uneven knots: the cubic through the four end points is
  // the curve itself, so its s'' is the curve's and the polynomial kind with
  // polynomial ends is the curve, to rounding; natural ends are not (s'' = 0
  // where the curve's is 2 and more).
  std::vector<double> knots;
  std::vector<Vec3> points;
  for (int i = 0; i <= 9; ++i)
  {
    const double t = -1.0 + 2.0 * i / 9.0 + (i % 2 == 0 ? 0.0 : 0.07);
    knots.push_back(t);
    points.emplace_back(t, t * t, t * t * t - t);
  }
  const std::vector<SpaceKernel> kernels(9, SpaceKernel(SpaceKind::Polynomial, 0.0));
  const auto polynomial = GeneralizedCubicSpline::interpolate(
    points, knots, false, kernels, GeneralizedCubicEnds::Polynomial);
  const auto natural = GeneralizedCubicSpline::interpolate(points, knots, false, kernels);
  expectPolynomialEndsReproduce("cubic curve", polynomial, natural,
    [](double t) { return Vec3(0.0, 2.0, 6.0 * t); }, 1e-10);
}

TEST(GeneralizedCubicSpline, InfiniteTensionTendsToThePolygon)
{
  const std::vector<Vec3> points = akima();
  CleanPolyline data = cleanPolyline(points, false);
  const auto knots = computeKnots(data, Parameterization::ChordLength);
  const double diameter = boundingBoxDiagonal(data.Points);
  for (const SpaceKind kind : { SpaceKind::Exponential, SpaceKind::VariableDegree })
  {
    double previous = 1e300;
    for (const double p : { 16.0, 64.0, 256.0, 1000.0 })
    {
      const auto spline = Interpolate(points, kind, kind == SpaceKind::VariableDegree ? p / 5 + 3 : p);
      double distance = 0.0;
      for (int j = 0; j < spline.numberOfSpans(); ++j)
      {
        for (int s = 1; s < 16; ++s)
        {
          const double f = s / 16.0;
          const double t = knots[j] + f * (knots[j + 1] - knots[j]);
          const Vec3 chord = (1 - f) * data.Points[j] + f * data.Points[j + 1];
          distance = std::max(distance, (spline.evaluateOnSpan(j, t, 0)[0] - chord).norm());
        }
      }
      std::printf("kind %d, tension %g: largest distance to the polygon %.3g of the diameter\n",
        int(kind), p, distance / diameter);
      EXPECT_LT(distance, previous) << int(kind) << " tension " << p;
      previous = distance;
    }
    EXPECT_LT(previous, 2e-2 * diameter) << int(kind);
  }
}

namespace
{
FittedPolyline Fit(const std::vector<Vec3>& points, SpaceKind kind, bool automatic, double tension = 0)
{
  GeneralizedCubicOptions options;
  options.Kind = kind;
  options.Automatic = automatic;
  options.Tension = tension;
  return fitPolyline(points, FitOptions{}, generalizedCubicBuilder(options));
}
} // namespace

TEST(GeneralizedCubicSpline, AutomaticTensionRemovesEveryShapeViolationTheCubicHas)
{
  const std::vector<std::pair<const char*, std::vector<Vec3>>> sets = { { "Akima", akima() },
    { "RPN 15A", rpn15a() }, { "titanium", titanium() } };
  for (const auto& [name, points] : sets)
  {
    const FittedPolyline cubic = Fit(points, SpaceKind::Polynomial, false);
    EXPECT_GT(cubic.Audit.violations(), 0) << name;
    for (const SpaceKind kind : { SpaceKind::Exponential, SpaceKind::VariableDegree })
    {
      const FittedPolyline automatic = Fit(points, kind, true, kind == SpaceKind::VariableDegree ? 3 : 0);
      const auto tension = automatic.Spline->spanParameters().at(0).Values;
      std::printf("%s, kind %d: cubic %d violations, automatic %d; largest tension %g, "
                  "spans tensioned %ld of %zu\n",
        name, int(kind), cubic.Audit.violations(), automatic.Audit.violations(),
        *std::max_element(tension.begin(), tension.end()),
        std::count_if(tension.begin(), tension.end(),
          [kind](double p) { return p > (kind == SpaceKind::VariableDegree ? 3.0 : 0.0); }),
        tension.size());
      EXPECT_EQ(automatic.Audit.violations(), 0) << name << " kind " << int(kind);
      // Only where needed: some spans keep the starting tension.
      EXPECT_LT(std::count_if(tension.begin(), tension.end(),
                  [kind](double p) { return p > (kind == SpaceKind::VariableDegree ? 3.0 : 0.0); }),
        static_cast<long>(tension.size()))
        << name;
    }
  }
}

TEST(GeneralizedCubicSpline, CollinearRunsStayStraightAndCoplanarDataFlatInAutomaticMode)
{
  // A space curve with a straight run of five points, then a planar part and a twist.
  const std::vector<Vec3> points = { { -3, 2, 0 }, { -2, 0.5, 0 }, { -1, 0, 0 }, { 0, 0, 0 },
    { 1, 0, 0 }, { 2, 0, 0 }, { 3, 0, 0 }, { 4, 0.6, 0 }, { 4.5, 2, 0.8 }, { 4, 3, 2 } };
  const FittedPolyline cubic = Fit(points, SpaceKind::Polynomial, false);
  const FittedPolyline fit = Fit(points, SpaceKind::Exponential, true);
  EXPECT_GT(cubic.Audit.Failures[int(ShapeCriterion::Collinearity)], 0);
  EXPECT_EQ(fit.Audit.violations(), 0);
  const SampledCurve sampled = sampleFit(fit);
  double offLine = 0.0;
  for (int k = 0; k < sampled.Samples.size(); ++k)
  {
    const int span = sampled.Samples.Span[k];
    const Vec3& p = sampled.Samples.Values[k][0];
    if (span >= 2 && span < 6)
    {
      offLine = std::max(offLine, std::abs(p.y()) + std::abs(p.z()));
    }
  }
  std::printf("straight run of length 4: largest distance off the line %.2e\n", offLine);
  EXPECT_LT(offLine, 1e-3 * 4.0); // the audit's tolerance: a sine of 1e-3
  // Planar data: zero torsion, exactly, whatever tension the automatic mode chose.
  std::vector<Vec3> planarPoints = points;
  for (Vec3& p : planarPoints)
  {
    p.z() = 0.0;
  }
  const FittedPolyline planarFit = Fit(planarPoints, SpaceKind::Exponential, true);
  const SampledCurve planar = sampleFit(planarFit);
  for (const FrenetFrame& frame : planar.Frames)
  {
    ASSERT_EQ(frame.Torsion, 0.0);
  }
}

TEST(GeneralizedCubicSpline, HelixCurvatureAndTorsionConverge)
{
  // Default settings (exponential kind, automatic, which leaves a helix untensioned).
  double previousCurvature = 1.0, previousTorsion = 1.0;
  for (const int perTurn : { 8, 16, 32 })
  {
    const FittedPolyline fit = Fit(helix(perTurn, 6), SpaceKind::Exponential, true);
    const RelativeErrors errors = interiorErrors(fit, 0.4, 0.2, perTurn);
    std::printf("helix, %d points per turn: curvature %.3g%%, torsion %.3g%% (orders %.2f, %.2f)\n",
      perTurn, 100 * errors.Curvature, 100 * errors.Torsion,
      std::log2(previousCurvature / errors.Curvature), std::log2(previousTorsion / errors.Torsion));
    if (perTurn == 32)
    {
      EXPECT_LT(errors.Curvature, 1e-2);
      EXPECT_LT(errors.Torsion, 1e-2);
    }
    if (perTurn > 8)
    {
      EXPECT_GT(std::log2(previousCurvature / errors.Curvature), 1.7);
      EXPECT_GT(std::log2(previousTorsion / errors.Torsion), 1.7);
    }
    previousCurvature = errors.Curvature;
    previousTorsion = errors.Torsion;
  }
}

TEST(GeneralizedCubicSpline, RejectsTensionsOutsideTheirKind)
{
  EXPECT_THROW(SpaceKernel(SpaceKind::Trigonometric, 3.2), std::invalid_argument);
  EXPECT_THROW(SpaceKernel(SpaceKind::VariableDegree, 2.5), std::invalid_argument);
  EXPECT_THROW(SpaceKernel(SpaceKind::Exponential, -1.0), std::invalid_argument);
  EXPECT_EQ(largestTension(SpaceKind::Trigonometric, 10.0), 0.99 * 3.14159265358979323846);
  EXPECT_EQ(raisedTension(SpaceKind::Exponential, 600.0, 1000.0), 1000.0);
}
