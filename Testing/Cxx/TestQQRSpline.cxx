// Quartic Bernstein-like (qqr) basis and cubic B-spline-like curves (Wang & Zhang):
// Theorem 1, the B-spline basis (Theorems 5, 6, 8, 10), the reduction to the
// classical cubic B-splines, the Bezier form, the local interpolation of
// section 3.6, the automatic mode on the shape data sets and the helix.
#include "QQRSpline.h"
#include "SparseSolve.h"
#include "MathTestUtilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <tuple>

using namespace shapesplines;
using namespace shapesplines::test;

namespace
{
using LongJet = std::array<long double, 5>;

/// d^m/dx^m x^p in long double, x > 0.
long double powDerivative(long double x, long double p, int m)
{
  long double factor = 1;
  for (int j = 0; j < m; ++j)
  {
    factor *= p - j;
  }
  return factor == 0 ? 0 : factor * std::pow(x, p - m);
}

/// The qqr basis and its derivatives straight from (2.1), in long double, 0 < t < 1:
/// A1 = alpha (s^(alpha-1) - s^alpha), A3 = beta (t^(beta-1) - t^beta), A2 = 1 - the others.
std::array<LongJet, 5> referenceBasis(long double t, long double alpha, long double beta)
{
  const long double s = 1 - t;
  std::array<LongJet, 5> a{};
  for (int m = 0; m < 5; ++m)
  {
    const long double sign = m % 2 == 0 ? 1 : -1;
    a[0][m] = sign * powDerivative(s, alpha, m);
    a[1][m] = sign * alpha * (powDerivative(s, alpha - 1, m) - powDerivative(s, alpha, m));
    a[3][m] = beta * (powDerivative(t, beta - 1, m) - powDerivative(t, beta, m));
    a[4][m] = powDerivative(t, beta, m);
    a[2][m] = (m == 0 ? 1 : 0) - a[0][m] - a[1][m] - a[3][m] - a[4][m];
  }
  return a;
}

const std::vector<double> ShapeGrid = { 2.0, 2.5, 3.0, 3.7, 4.0, 5.5, 10.0, 37.0, 100.0, 200.0 };

/// The largest |A_j^(m)| over j: the scale of the m-th derivatives at t.
double derivativeScale(const std::array<Jet, 5>& a, int m)
{
  double scale = 0.0;
  for (const Jet& j : a)
  {
    scale = std::max(scale, std::abs(j[m]));
  }
  return scale;
}
} // namespace

TEST(QQRBasis, Theorem1PartitionOfUnitySymmetryAndDerivativesOnAGrid)
{
  double largestValueError = 0.0, largestDerivativeError = 0.0;
  for (const double alpha : ShapeGrid)
  {
    for (const double beta : ShapeGrid)
    {
      for (int k = 0; k <= 128; ++k)
      {
        const double t = k / 128.0; // dyadic: 1 - t is exact, so the mirror point is too
        const auto a = qqrBasis(t, alpha, beta);
        // (2) Partition of unity, and the derivatives sum to 0.
        double sum = 0.0;
        for (const Jet& j : a)
        {
          sum += j[0];
        }
        ASSERT_NEAR(sum, 1.0, 1e-15) << alpha << " " << beta << " t " << t;
        for (int m = 1; m < 5; ++m)
        {
          double derivativeSum = 0.0;
          for (const Jet& j : a)
          {
            derivativeSum += j[m];
          }
          const double scale = derivativeScale(a, m);
          if (std::isfinite(scale))
          {
            ASSERT_LE(std::abs(derivativeSum), 1e-13 * scale + 1e-300) << alpha << " " << beta << " t " << t << " m " << m;
          }
        }
        // (3) Symmetry A_i(t; alpha, beta) = A_{4-i}(1 - t; beta, alpha), for every i
        // (the paper states i = 0, 1; A2 follows), derivatives with (-1)^m.
        const auto mirrored = qqrBasis(1.0 - t, beta, alpha);
        for (int i = 0; i < 5; ++i)
        {
          for (int m = 0; m < 5; ++m)
          {
            const double expected = (m % 2 == 0 ? 1 : -1) * mirrored[4 - i][m];
            if (std::isinf(expected))
            {
              ASSERT_EQ(a[i][m], expected);
              continue;
            }
            ASSERT_NEAR(a[i][m], expected, 4e-16 * std::max(1.0, derivativeScale(a, m)))
              << "A" << i << " m " << m << " " << alpha << " " << beta << " t " << t;
          }
        }
        // Values and derivatives against long double on the open interval.
        if (k == 0 || k == 128)
        {
          continue;
        }
        const auto reference = referenceBasis(t, alpha, beta);
        for (int m = 0; m < 5; ++m)
        {
          // (A floor above the subnormal range, where t^(beta-4) ends up for beta = 200.)
          const double scale = std::max(derivativeScale(a, m), 1e-280);
          for (int i = 0; i < 5; ++i)
          {
            const double error = std::abs(a[i][m] - static_cast<double>(reference[i][m])) / scale;
            (m == 0 ? largestValueError : largestDerivativeError) =
              std::max(m == 0 ? largestValueError : largestDerivativeError, error);
            ASSERT_LE(error, m == 0 ? 1e-15 : 1e-13)
              << "A" << i << " m " << m << " alpha " << alpha << " beta " << beta << " t " << t;
          }
        }
      }
    }
  }
  std::printf("qqr basis against long double, alpha, beta in [2, 200]: values %.2g, "
              "derivatives 1..4 %.2g (relative to the largest of the five)\n",
    largestValueError, largestDerivativeError);
}

TEST(QQRBasis, DerivativesAgreeWithFiniteDifferences)
{
  for (const double alpha : { 2.0, 3.7, 4.0, 10.0, 200.0 })
  {
    for (const double beta : { 2.5, 4.0, 37.0, 200.0 })
    {
      for (const double t : { 0.013, 0.2, 0.5, 0.77, 0.987 })
      {
        const double step = 1e-5 / std::max(alpha, beta);
        const auto above = qqrBasis(t + step, alpha, beta);
        const auto below = qqrBasis(t - step, alpha, beta);
        const auto here = qqrBasis(t, alpha, beta);
        for (int m = 1; m < 5; ++m)
        {
          const double scale = derivativeScale(here, m);
          for (int i = 0; i < 5; ++i)
          {
            const double difference = (above[i][m - 1] - below[i][m - 1]) / (2 * step);
            EXPECT_NEAR(difference, here[i][m], 1e-5 * scale + 1e-9 * derivativeScale(here, m - 1) / step)
              << "A" << i << " m " << m << " " << alpha << " " << beta << " t " << t;
          }
        }
      }
    }
  }
}

TEST(QQRBasis, Theorem1EndPointValuesWithTheirRangeOfValidity)
{
  for (const double alpha : ShapeGrid)
  {
    for (const double beta : ShapeGrid)
    {
      const auto a0 = qqrBasis(0.0, alpha, beta);
      const auto a1 = qqrBasis(1.0, alpha, beta);
      // Values: A0(0) = A4(1) = 1, all others 0 at both ends.
      for (int i = 0; i < 5; ++i)
      {
        EXPECT_EQ(a0[i][0], i == 0 ? 1.0 : 0.0) << i << " " << alpha << " " << beta;
        EXPECT_EQ(a1[i][0], i == 4 ? 1.0 : 0.0) << i << " " << alpha << " " << beta;
      }
      // First derivatives: A0'(0) = -alpha, A1'(0) = alpha, A3'(1) = -beta, A4'(1) = beta.
      // The paper's zeros for A3'(0), A2'(0) (A1'(1), A2'(1)) need beta > 2 (alpha > 2):
      // for beta = 2, A3 = 2 t (1 - t) and A3'(0) = 2, A2'(0) = -2.
      const double tolerance = 1e-12 * alpha * beta;
      EXPECT_NEAR(a0[0][1], -alpha, tolerance);
      EXPECT_NEAR(a0[1][1], alpha, tolerance);
      EXPECT_NEAR(a0[3][1], beta == 2.0 ? 2.0 : 0.0, tolerance) << beta;
      EXPECT_NEAR(a0[2][1], beta == 2.0 ? -2.0 : 0.0, tolerance) << beta;
      EXPECT_EQ(a0[4][1], 0.0);
      EXPECT_NEAR(a1[4][1], beta, tolerance);
      EXPECT_NEAR(a1[3][1], -beta, tolerance);
      EXPECT_NEAR(a1[1][1], alpha == 2.0 ? -2.0 : 0.0, tolerance) << alpha;
      EXPECT_NEAR(a1[2][1], alpha == 2.0 ? 2.0 : 0.0, tolerance) << alpha;
      EXPECT_EQ(a1[0][1], 0.0);
      // Second derivatives as listed, for alpha, beta > 3 (the paper says > 2:
      // below 3, A3''(0) = beta (beta-1) (beta-2) t^(beta-3) is unbounded).
      if (alpha > 3.0 && beta > 3.0)
      {
        const double t2 = 1e-12 * alpha * alpha * beta * beta;
        EXPECT_NEAR(a0[0][2], alpha * alpha - alpha, t2);
        EXPECT_NEAR(a0[1][2], 2 * alpha * (1 - alpha), t2);
        EXPECT_NEAR(a0[2][2], alpha * alpha - alpha, t2);
        EXPECT_EQ(a0[3][2], 0.0);
        EXPECT_EQ(a0[4][2], 0.0);
        EXPECT_EQ(a1[0][2], 0.0);
        EXPECT_EQ(a1[1][2], 0.0);
        EXPECT_NEAR(a1[2][2], beta * beta - beta, t2);
        EXPECT_NEAR(a1[3][2], 2 * beta * (1 - beta), t2);
        EXPECT_NEAR(a1[4][2], beta * beta - beta, t2);
      }
      if (beta == 3.0)
      {
        EXPECT_NEAR(a0[3][2], 6.0, 1e-12);
        EXPECT_NEAR(a0[2][2], alpha * alpha - alpha - 6.0, 1e-12 * alpha * alpha);
      }
      if (beta > 2.0 && beta < 3.0)
      {
        EXPECT_TRUE(std::isinf(a0[3][2])) << beta;
      }
      if (beta == 2.0)
      {
        EXPECT_EQ(a0[3][2], -4.0); // A3 = 2 (t - t^2)
      }
    }
  }
}

TEST(QQRBasis, NonNegativeForExponentsFromThreeButNotFromTwo)
{
  // Theorem 1 (1) and Lemma 1 claim alpha, beta >= 2; Lemma 1's F(t; 2) =
  // -2 t^2 (1 - t) < 0, and F(t; lambda) >= F(t; 3) = 0 only from 3 on.
  double lowest = 0.0;
  for (const double alpha : ShapeGrid)
  {
    for (const double beta : ShapeGrid)
    {
      for (int k = 0; k <= 200; ++k)
      {
        const double t = k / 200.0;
        const auto a = qqrBasis(t, alpha, beta);
        for (int i : { 0, 1, 3, 4 })
        {
          ASSERT_GE(a[i][0], 0.0);
        }
        if (alpha >= 3.0 && beta >= 3.0)
        {
          ASSERT_GE(a[2][0], -3e-16) << alpha << " " << beta << " t " << t;
        }
        lowest = std::min(lowest, a[2][0]);
        if (alpha == 2.0 && beta == 2.0)
        {
          ASSERT_NEAR(a[2][0], -2.0 * t * (1.0 - t), 3e-16);
        }
        if (alpha == 3.0 && beta == 3.0)
        {
          // A2 = 0: the cubic Bernstein basis (and no linear independence).
          ASSERT_NEAR(a[2][0], 0.0, 3e-16);
          ASSERT_NEAR(a[1][0], 3 * t * (1 - t) * (1 - t), 1e-15);
        }
        if (alpha == 4.0 && beta == 4.0)
        {
          // Remark 1: the quartic Bernstein basis.
          ASSERT_NEAR(a[2][0], 6 * t * t * (1 - t) * (1 - t), 1e-15);
        }
      }
    }
  }
  EXPECT_LT(lowest, -0.2); // the paper's claim fails for exponents below 3
  std::printf("lowest A2 over alpha, beta in [2, 200]: %.3f (alpha = beta = 2: -2 t (1 - t))\n", lowest);
}

TEST(QQRBasis, NoCancellationNearTheEndsUpToExponent200)
{
  // A2 ~ alpha (alpha - 1) t^2 / 2 near t = 0: 1 - A0 - A1 - A3 - A4 would keep
  // only eps / t^2 of it. Reference: the binomial tail sum_{k>=2} C(a, k) t^k
  // (1 - t)^(a-k) (all terms positive) for integer a, in long double.
  for (const int a : { 4, 10, 50, 200 })
  {
    for (const double t : { 1e-9, 1e-6, 1e-4, 1e-2, 0.3 })
    {
      long double tail = 0, binomial = 1;
      for (int k = 0; k <= a; ++k)
      {
        if (k >= 2)
        {
          tail += binomial * std::pow(static_cast<long double>(t), k) *
            std::pow(1 - static_cast<long double>(t), a - k);
        }
        binomial = binomial * (a - k) / (k + 1);
      }
      const double g = qqrTail(t, a, 0)[0];
      EXPECT_NEAR(g, static_cast<double>(tail), 1e-15 * static_cast<double>(tail)) << a << " " << t;
      // A2 = G(t; alpha) - (A3 + A4); A3 + A4 is ~t^(beta-1), negligible or exact here.
      const auto basis = qqrBasis(t, a, 200.0);
      EXPECT_NEAR(basis[2][0], static_cast<double>(tail), 1e-15 * static_cast<double>(tail)) << a << " " << t;
    }
  }
}

namespace
{
/// Cox-de Boor: the m-th derivative of the cubic B-spline N_{i,3} on knots u at
/// u, inside knot interval `span` (one-sided at its ends).
double coxDeBoor(const std::vector<double>& u, int i, int degree, int m, int span, double x)
{
  if (m > degree)
  {
    return 0.0;
  }
  if (degree == 0)
  {
    return i == span ? 1.0 : 0.0;
  }
  if (m > 0)
  {
    const double left = degree * coxDeBoor(u, i, degree - 1, m - 1, span, x) / (u[i + degree] - u[i]);
    const double right = degree * coxDeBoor(u, i + 1, degree - 1, m - 1, span, x) / (u[i + degree + 1] - u[i + 1]);
    return left - right;
  }
  return (x - u[i]) / (u[i + degree] - u[i]) * coxDeBoor(u, i, degree - 1, 0, span, x) +
    (u[i + degree + 1] - x) / (u[i + degree + 1] - u[i + 1]) * coxDeBoor(u, i + 1, degree - 1, 0, span, x);
}

std::vector<double> RandomKnots(int count, std::mt19937& random, double spread)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> knots = { 0.0 };
  for (int i = 1; i < count; ++i)
  {
    knots.push_back(knots.back() + 1.0 + spread * (unit(random) - 0.5));
  }
  return knots;
}

std::vector<double> Intervals(const std::vector<double>& knots)
{
  std::vector<double> h;
  for (size_t i = 0; i + 1 < knots.size(); ++i)
  {
    h.push_back(knots[i + 1] - knots[i]);
  }
  return h;
}

/// Random local parameters satisfying (3.3) strictly: x, y > 0, x + y < 1, 0 < z < 1.
QQRLocalParameters RandomLocal(int m, std::mt19937& random)
{
  std::uniform_real_distribution<double> unit(0.05, 0.45);
  std::uniform_real_distribution<double> bias(0.1, 0.9);
  QQRLocalParameters local;
  for (int i = 0; i < m; ++i)
  {
    local.X.push_back(unit(random));
    local.Y.push_back(unit(random));
    local.Z.push_back(bias(random));
  }
  return local;
}

/// Derivatives of B_i at knot j from the left and from the right.
std::pair<Jet, Jet> AtKnot(const QQRBSplineBasis& basis, int i, int j)
{
  const double u = basis.knots()[j];
  const int spans = static_cast<int>(basis.knots().size()) - 1;
  const Jet left = j > 0 ? basis.value(i, u, 4, j - 1) : Jet{};
  const Jet right = j < spans ? basis.value(i, u, 4, j) : Jet{};
  return { left, right };
}
} // namespace

TEST(QQRBSplineBasis, Theorem5PartitionOfUnityAndTheorem6Positivity)
{
  std::mt19937 random(5);
  for (const double spread : { 0.0, 1.6 })
  {
    for (const auto& [alpha, beta] : std::vector<std::pair<double, double>>{
           { 3.0, 3.0 }, { 4.0, 4.0 }, { 3.5, 9.0 }, { 7.5, 7.5 }, { 50.0, 20.0 }, { 200.0, 200.0 } })
    {
      const std::vector<double> knots = RandomKnots(13, random, spread); // n = 8
      const QQRBSplineBasis basis(knots, alpha, beta, RandomLocal(12, random));
      const int n = basis.size() - 1;
      for (int span = 3; span <= n; ++span)
      {
        for (int s = 0; s <= 20; ++s)
        {
          const double u = knots[span] + s / 20.0 * (knots[span + 1] - knots[span]);
          double sum = 0.0;
          for (int i = 0; i <= n; ++i)
          {
            const double b = basis.value(i, u, 0, span)[0];
            sum += b;
            ASSERT_GE(b, 0.0) << i << " at " << u;
            // Theorem 6: B_i > 0 inside its support (where t^beta does not underflow).
            if (span >= i && span <= i + 3 && s >= 2 && s <= 18)
            {
              ASSERT_GT(b, 0.0) << "B_" << i << " at " << u << " alpha " << alpha << " beta " << beta;
            }
            if (span < i || span > i + 3)
            {
              ASSERT_EQ(b, 0.0);
            }
          }
          ASSERT_NEAR(sum, 1.0, 1e-15) << "u " << u << " alpha " << alpha << " beta " << beta;
        }
      }
    }
  }
  // Exponents below 3 break Theorem 6 even with (3.3), once the knots are
  // non-uniform (A2 < 0 enters B_{i,1}, B_{i,2}); from 3 on it holds.
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double alpha : { 2.0, 2.5, 3.0, 4.0, 10.0 })
  {
    std::mt19937 search(7);
    double lowest = 1.0;
    for (int trial = 0; trial < 300; ++trial)
    {
      std::vector<double> knots = { 0.0 };
      QQRLocalParameters local;
      for (int i = 0; i < 8; ++i)
      {
        knots.push_back(knots.back() + std::exp(3.0 * (unit(search) - 0.5)));
        double x = unit(search), y = unit(search) * (1.0 - x);
        if (unit(search) < 0.5)
        {
          std::swap(x, y);
        }
        local.X.push_back(x);
        local.Y.push_back(y);
        local.Z.push_back(unit(search));
      }
      const QQRBSplineBasis basis(knots, alpha, alpha, local);
      for (int s = 0; s <= 200; ++s)
      {
        lowest = std::min(lowest, basis.value(2, knots[2] + s / 200.0 * (knots[6] - knots[2]), 0)[0]);
      }
    }
    std::printf("alpha = beta = %g, local parameters satisfying (3.3), random knots: lowest B_2 %.3g\n",
      alpha, lowest);
    if (alpha < 3.0)
    {
      EXPECT_LT(lowest, -1e-2) << alpha;
    }
    else
    {
      EXPECT_GE(lowest, -1e-16) << alpha;
    }
  }
}

TEST(QQRBSplineBasis, Theorem8C2ForEqualExponentsAboveThreeAndG1Otherwise)
{
  std::mt19937 random(8);
  for (const double alpha : { 3.2, 4.0, 7.0, 25.0, 200.0, 3.0, 2.5 })
  {
    const std::vector<double> knots = RandomKnots(14, random, 1.6);
    const QQRBSplineBasis basis(knots, alpha, alpha, RandomLocal(13, random));
    double largest[5] = {};
    for (int i = 0; i < basis.size(); ++i)
    {
      for (int j = i; j <= i + 4; ++j)
      {
        const auto [left, right] = AtKnot(basis, i, j);
        for (int m = 0; m <= 3; ++m)
        {
          // Relative to the scale of B_i's m-th derivative, 1 / h^m.
          const double scale = std::max({ std::abs(left[m]), std::abs(right[m]), std::pow(knots[j + 1 < (int)knots.size() ? j + 1 : j] - knots[j > 0 ? j - 1 : j], -m) * 1e-2 });
          const double jump = std::isfinite(left[m] - right[m]) ? std::abs(left[m] - right[m]) / scale : INFINITY;
          largest[m] = std::max(largest[m], jump);
        }
      }
    }
    std::printf("alpha = beta = %g: relative jumps at the knots, orders 0..3: %.1e %.1e %.1e %.1e\n",
      alpha, largest[0], largest[1], largest[2], largest[3]);
    EXPECT_LE(largest[0], 1e-12);
    EXPECT_LE(largest[1], 1e-12);
    if (alpha > 3.0)
    {
      EXPECT_LE(largest[2], 1e-9) << alpha;
      EXPECT_GT(largest[3], 1e-3) << alpha << ": only C2 is claimed, the third derivative jumps";
    }
    else
    {
      // The paper says alpha = beta in (2, inf): at 3, A3''(0) = 6 breaks the
      // second derivative's join; below 3 it is unbounded at the knots.
      EXPECT_GT(largest[2], 1e-2) << alpha;
    }
  }
  // alpha != beta: the tangents at a knot agree in direction only: B'(u+) / alpha = B'(u-) / beta.
  const std::vector<double> knots = RandomKnots(12, random, 1.6);
  const double alpha = 5.0, beta = 9.0;
  const QQRBSplineBasis basis(knots, alpha, beta, RandomLocal(11, random));
  double largestG1 = 0.0, largestC1 = 0.0;
  for (int i = 0; i < basis.size(); ++i)
  {
    for (int j = i + 1; j <= i + 3; ++j)
    {
      const auto [left, right] = AtKnot(basis, i, j);
      largestG1 = std::max(largestG1, std::abs(right[1] / alpha - left[1] / beta));
      largestC1 = std::max(largestC1, std::abs(right[1] - left[1]));
    }
  }
  EXPECT_LT(largestG1, 1e-13);
  EXPECT_GT(largestC1, 1e-2);
}

TEST(QQRBSplineBasis, ReducesToTheClassicalCubicBSplineWithThePapersLocalParameters)
{
  std::mt19937 random(13);
  for (const double spread : { 0.0, 0.8, 1.9 })
  {
    const std::vector<double> knots = RandomKnots(15, random, spread);
    const std::vector<double> h = Intervals(knots);
    const QQRBSplineBasis basis(knots, 4.0, 4.0, cubicLocalParameters(h));
    double largest = 0.0, fourth = 0.0;
    for (int i = 0; i < basis.size(); ++i)
    {
      for (int span = i; span <= i + 3; ++span)
      {
        for (int s = 0; s <= 10; ++s)
        {
          const double u = knots[span] + s / 10.0 * h[span];
          const Jet b = basis.value(i, u, 4, span);
          for (int m = 0; m <= 3; ++m)
          {
            const double scale = std::pow(h[span], -m);
            largest = std::max(largest, std::abs(b[m] - coxDeBoor(knots, i, 3, m, span, u)) / scale);
          }
          fourth = std::max(fourth, std::abs(b[4]) * std::pow(h[span], 4));
        }
      }
    }
    std::printf("knot spread %.1f: qqr (alpha = beta = 4) minus cubic B-spline, derivatives 0..3: "
                "%.1e; 4th derivative %.1e\n",
      spread, largest, fourth);
    EXPECT_LT(largest, 1e-12) << spread;
    EXPECT_LT(fourth, 1e-11) << spread;
    if (spread > 0.0)
    {
      // Read with the index of x, y, z shifted by one, it is not the cubic B-spline.
      QQRLocalParameters shifted = cubicLocalParameters(h);
      std::rotate(shifted.X.begin(), shifted.X.begin() + 1, shifted.X.end());
      std::rotate(shifted.Y.begin(), shifted.Y.begin() + 1, shifted.Y.end());
      std::rotate(shifted.Z.begin(), shifted.Z.begin() + 1, shifted.Z.end());
      const QQRBSplineBasis wrong(knots, 4.0, 4.0, shifted);
      double difference = 0.0;
      for (int i = 1; i + 2 < wrong.size(); ++i)
      {
        for (int span = i; span <= i + 3; ++span)
        {
          const double u = knots[span] + 0.5 * h[span];
          difference = std::max(difference, std::abs(wrong.value(i, u, 0, span)[0] - coxDeBoor(knots, i, 3, 0, span, u)));
        }
      }
      EXPECT_GT(difference, 1e-3) << spread;
    }
  }
}

TEST(QQRBSplineBasis, Theorem10KnotValuesAndTheCorrectedLocalInterpolationConditions)
{
  std::mt19937 random(21);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_real_distribution<double> bias(0.1, 0.9);
  const std::vector<double> knots = RandomKnots(14, random, 1.6);
  const std::vector<double> h = Intervals(knots);
  const int m = static_cast<int>(h.size());
  for (const double alpha : { 3.5, 4.0, 12.0 })
  {
    // Theorem 10 (3) for arbitrary local parameters (its Q'' with z_{i-2} in the first term).
    const QQRLocalParameters local = RandomLocal(m, random);
    const QQRBSplineBasis basis(knots, alpha, alpha, local);
    std::vector<double> p(basis.size());
    for (double& v : p)
    {
      v = value(random);
    }
    const auto& [x, y, z] = local;
    double largest = 0.0, withPrintedIndex = 0.0;
    for (int i = 3; i <= basis.size(); ++i)
    {
      Jet q{};
      for (int j = i - 3; j <= i - 1; ++j)
      {
        const Jet b = basis.value(j, knots[i], 2, i);
        for (int d = 0; d <= 2; ++d)
        {
          q[d] += b[d] * p[j];
        }
      }
      const double mu = basis.mu(i - 1), up = basis.upsilon(i - 1), sum = h[i - 1] + h[i];
      const double value0 = up * (2 * mu * y[i - 1] + up * (1 - z[i - 2])) * p[i - 3] +
        basis.rho(i - 2) * p[i - 2] + mu * (mu * z[i - 1] + 2 * up * x[i - 1]) * p[i - 1];
      const double value1 = alpha / sum *
        (((2 * mu - 1) * y[i - 1] + up * (1 - z[i - 2])) * (p[i - 2] - p[i - 3]) +
          ((1 - 2 * mu) * x[i - 1] + mu * z[i - 1]) * (p[i - 1] - p[i - 2]));
      auto second = [&](double zFirst) {
        return (alpha * alpha - alpha) / (sum * sum) *
          ((2 * y[i - 1] + zFirst - 1) * (p[i - 2] - p[i - 3]) + (z[i - 1] - 2 * x[i - 1]) * (p[i - 1] - p[i - 2]));
      };
      largest = std::max({ largest, std::abs(q[0] - value0), std::abs(q[1] - value1) * sum,
        std::abs(q[2] - second(z[i - 2])) * sum * sum / (alpha * alpha) });
      withPrintedIndex = std::max(withPrintedIndex, std::abs(q[2] - second(z[i - 1])) * sum * sum / (alpha * alpha));
    }
    EXPECT_LT(largest, 1e-13) << alpha;
    EXPECT_GT(withPrintedIndex, 1e-3) << alpha << ": the printed z_{i-1} should not fit";

    // (3.18) as corrected, x_{i-1} = -h_{i-1} z_{i-1} / (2 h_i): Q(u_i) = P_{i-2}.
    // As printed (no 1/2), it does not interpolate.
    for (const bool printed : { false, true })
    {
      QQRLocalParameters interpolating{ std::vector<double>(m, 0.0), std::vector<double>(m, 0.0),
        std::vector<double>(m) };
      for (double& v : interpolating.Z)
      {
        v = bias(random);
      }
      for (int j = 1; j + 1 < m; ++j)
      {
        interpolating.X[j] = -(printed ? 1.0 : 0.5) * h[j] / h[j + 1] * interpolating.Z[j];
        interpolating.Y[j] = -0.5 * h[j + 1] / h[j] * (1 - interpolating.Z[j - 1]);
      }
      const QQRBSplineBasis local2(knots, alpha, alpha, interpolating);
      double miss = 0.0;
      for (int i = 3; i <= local2.size(); ++i)
      {
        double q = 0.0;
        for (int j = i - 3; j <= i - 1; ++j)
        {
          q += local2.value(j, knots[i], 0, i)[0] * p[j];
        }
        miss = std::max(miss, std::abs(q - p[i - 2]));
      }
      if (printed)
      {
        EXPECT_GT(miss, 1e-2) << alpha;
      }
      else
      {
        EXPECT_LT(miss, 1e-14) << alpha;
      }
    }
  }
}

namespace
{
/// The paper's knot vector behind a QQRSpline on data knots t_0..t_N (open):
/// u_2 = t_0, the intervals beyond the data mirrored (the class's decision),
/// stored from the paper's index -1 on (entry p + 1 is u_p), up to u_{N+5}.
std::vector<double> PaperKnots(const std::vector<double>& t)
{
  const int spans = static_cast<int>(t.size()) - 1;
  auto dh = [&](int j) {
    j = j < 0 ? -1 - j : (j >= spans ? 2 * spans - 1 - j : j);
    return t[j + 1] - t[j];
  };
  std::vector<double> u(spans + 7);
  u[3] = t[0]; // paper u_2
  for (int p = 3; p <= spans + 5; ++p)
  {
    u[p + 1] = u[p] + dh(p - 3); // h_{p-1} = dh_{p-3}
  }
  for (int p = 1; p >= -1; --p)
  {
    u[p + 1] = u[p + 2] - dh(p - 2); // h_p = dh_{p-2}
  }
  return u;
}

std::vector<Vec3> RandomPoints(int count, std::mt19937& random)
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i)
  {
    points.emplace_back(unit(random), unit(random), unit(random));
  }
  return points;
}

/// The largest misses at the knots of a qqr curve on data knots t: of the
/// data points, the tangent (3.20) and second derivative (3.21) (relative;
/// interpolation only, at points whose (3.20) stencil lies inside an open
/// line), the C2 jumps (derivatives 0..2, relative), and the largest
/// third-derivative jump (relative).
struct KnotMisses
{
  double Position = 0.0, Tangent = 0.0, Second = 0.0, C2 = 0.0, ThirdJump = 0.0;
};

/// spanZ(k): the z of span k (its middle Bezier point) the check expects.
KnotMisses knotMisses(const QQRSpline& curve, const std::vector<Vec3>& points,
  const std::vector<double>& t, const std::vector<double>& kappa,
  const std::function<double(int)>& spanZ, bool interpolates)
{
  const bool closed = curve.isClosed();
  const int n = static_cast<int>(points.size());
  const int spans = curve.numberOfSpans();
  auto dh = [&](int j) {
    j = closed ? (j % spans + spans) % spans : j;
    return t[j + 1] - t[j];
  };
  KnotMisses misses;
  for (int k = 0; k < spans; ++k)
  {
    const Derivatives right = curve.evaluateOnSpan(k, t[k], 3);
    // (3.20), (3.21) at u_i, i = k + 2: h_{i-1} = dh_{k-1}, h_i = dh_k,
    // z_{i-2}, z_{i-1}; P_{i-3}, P_{i-2}, P_{i-1} = D_{k-1}, D_k, D_{k+1}.
    if (interpolates)
    {
      misses.Position = std::max(misses.Position, (right[0] - points[k]).norm());
      if (closed || (k >= 2 && k + 2 <= spans))
      {
        const Vec3& before = points[(k - 1 + n) % n];
        const Vec3& after = points[(k + 1) % n];
        const double a = kappa[k], h0 = dh(k - 1), h1 = dh(k);
        const double z0 = spanZ((k - 1 + n) % n), z1 = spanZ(k);
        const Vec3 backward = (points[k] - before) / h0, forward = (after - points[k]) / h1;
        const Vec3 expectedTangent = a / (2 * (h0 + h1)) * (h1 * (1 - z0) * backward + h0 * z1 * forward);
        const Vec3 expectedSecond = (a * a - a) / (h0 + h1) * (z1 * forward - (1 - z0) * backward);
        misses.Tangent =
          std::max(misses.Tangent, (right[1] - expectedTangent).norm() / expectedTangent.norm());
        misses.Second =
          std::max(misses.Second, (right[2] - expectedSecond).norm() / expectedSecond.norm());
      }
    }
    if (k > 0 || closed)
    {
      const int previous = (k - 1 + spans) % spans;
      const Derivatives left = curve.evaluateOnSpan(previous, t[previous + 1], 3);
      for (int m = 0; m <= 2; ++m)
      {
        misses.C2 = std::max(misses.C2, (left[m] - right[m]).norm() / std::max(right[m].norm(), 1e-300));
      }
      misses.ThirdJump = std::max(misses.ThirdJump, (left[3] - right[3]).norm() / right[3].norm());
    }
  }
  if (interpolates && !closed)
  {
    misses.Position = std::max(misses.Position, (curve.evaluate(t.back(), 0)[0] - points.back()).norm());
  }
  return misses;
}
} // namespace

TEST(QQRSpline, BezierFormEqualsTheBSplineCurveAndReducesToTheCubicBSplineCurve)
{
  std::mt19937 random(34);
  const std::vector<Vec3> points = RandomPoints(9, random);
  const std::vector<double> t = RandomKnots(9, random, 1.5);
  const int spans = 8;
  const std::vector<double> u = PaperKnots(t);
  for (const auto& [alpha, beta, local] : std::vector<std::tuple<double, double, QQRLocalShape>>{
         { 3.5, 9.0, QQRLocalShape{ 0.1, 0.3, 0.6 } }, { 4.0, 4.0, QQRLocalShape{} },
         { 30.0, 30.0, QQRLocalShape{} } })
  {
    const QQRSpline curve = QQRSpline::make(QQRConstruction::ControlPolygon, points, t, false, alpha, beta, local);
    // (3.6) with the control points P_{-1} = P_0, P_0..P_N, P_{N+1} = P_N.
    const std::vector<double> h = Intervals(u);
    QQRLocalParameters parameters = cubicLocalParameters(h);
    for (int i = 0; i < static_cast<int>(h.size()); ++i)
    {
      parameters.X[i] = std::isnan(local.X) ? parameters.X[i] : local.X;
      parameters.Y[i] = std::isnan(local.Y) ? parameters.Y[i] : local.Y;
      parameters.Z[i] = std::isnan(local.Z) ? parameters.Z[i] : local.Z;
    }
    const QQRBSplineBasis basis(u, alpha, beta, parameters);
    double largest = 0.0, fromCubic = 0.0;
    for (int k = 0; k < spans; ++k)
    {
      for (int s = 0; s <= 8; ++s)
      {
        const double x = t[k] + s / 8.0 * (t[k + 1] - t[k]);
        const Derivatives q = curve.evaluateOnSpan(k, x, 3);
        Derivatives b, cubic;
        b.fill(Vec3::Zero());
        cubic.fill(Vec3::Zero());
        for (int j = k - 1; j <= k + 2; ++j) // paper B_j, stored at j + 1
        {
          const Vec3& p = points[std::clamp(j, 0, spans)];
          const Jet value = basis.value(j + 1, x, 3, k + 3);
          for (int m = 0; m <= 3; ++m)
          {
            b[m] += value[m] * p;
            cubic[m] += coxDeBoor(u, j + 1, 3, m, k + 3, x) * p;
          }
        }
        for (int m = 0; m <= 3; ++m)
        {
          const double scale = std::pow(t[k + 1] - t[k], -m);
          largest = std::max(largest, (q[m] - b[m]).norm() / (scale + b[m].norm()));
          fromCubic = std::max(fromCubic, (q[m] - cubic[m]).norm() / scale);
        }
      }
    }
    std::printf("alpha %g, beta %g: Bezier form minus sum B_j P_j %.1e; minus the cubic B-spline curve %.1e\n",
      alpha, beta, largest, fromCubic);
    EXPECT_LT(largest, 1e-12);
    if (alpha == 4.0 && beta == 4.0 && std::isnan(local.X))
    {
      EXPECT_LT(fromCubic, 1e-12);
    }
    else
    {
      EXPECT_GT(fromCubic, 1e-3);
    }
  }
}

TEST(QQRSpline, LocalInterpolationPassesThroughTheDataWithTangent320AndCurvature321)
{
  std::mt19937 random(55);
  std::uniform_real_distribution<double> exponent(3.2, 60.0);
  for (const bool closed : { false, true })
  {
    for (const double fixedZ : { std::numeric_limits<double>::quiet_NaN(), 0.3 })
    {
      const std::vector<Vec3> points = RandomPoints(11, random);
      const int n = static_cast<int>(points.size());
      const int spans = closed ? n : n - 1;
      const std::vector<double> t = RandomKnots(spans + 1, random, 1.5);
      std::vector<double> kappa(n);
      for (double& k : kappa)
      {
        k = exponent(random);
      }
      kappa[2] = 4.0;
      const QQRSpline curve = QQRSpline::make(QQRConstruction::LocalInterpolation, points, t, closed, kappa, QQRLocalShape{ NAN, NAN, fixedZ });
      auto dh = [&](int j) {
        j = closed ? (j % spans + spans) % spans : j;
        return t[j + 1] - t[j];
      };
      auto zAt = [&](int j) { // the paper's z with H(j) = dh_{j-2}
        return std::isnan(fixedZ)
          ? (2 * dh(j - 2) + dh(j - 1)) / (2 * (dh(j - 2) + dh(j - 1) + dh(j)))
          : fixedZ;
      };
      // Span k's z is the paper's z_{k+1}.
      const KnotMisses misses =
        knotMisses(curve, points, t, kappa, [&](int k) { return zAt(k + 1); }, true);
      std::printf("%s, z %s: data %.1e, tangent (3.20) %.1e, second derivative (3.21) %.1e, "
                  "C2 jumps %.1e, third-derivative jump %.2f\n",
        closed ? "closed" : "open", std::isnan(fixedZ) ? "paper's" : "0.3", misses.Position,
        misses.Tangent, misses.Second, misses.C2, misses.ThirdJump);
      EXPECT_LT(misses.Position, 1e-12);
      EXPECT_LT(misses.Tangent, 1e-12);
      EXPECT_LT(misses.Second, 1e-11);
      EXPECT_LT(misses.C2, 1e-9);
      EXPECT_GT(misses.ThirdJump, 1e-3);
    }
  }
}

TEST(QQRSpline, PerKnotExponentsKeepC2ForTheControlPolygonCurveOpenAndClosed)
{
  std::mt19937 random(89);
  std::uniform_real_distribution<double> exponent(3.2, 150.0);
  for (const bool closed : { false, true })
  {
    const std::vector<Vec3> points = RandomPoints(10, random);
    const int n = static_cast<int>(points.size());
    const int spans = closed ? n : n - 1;
    const std::vector<double> t = RandomKnots(spans + 1, random, 1.5);
    std::vector<double> kappa(n);
    for (double& k : kappa)
    {
      k = exponent(random);
    }
    const QQRSpline curve = QQRSpline::make(QQRConstruction::ControlPolygon, points, t, closed, kappa);
    for (int k = closed ? 0 : 1; k < spans; ++k)
    {
      EXPECT_EQ(curve.exponents(k)[0], kappa[k]);
      EXPECT_EQ(curve.exponents((k - 1 + spans) % spans)[1], kappa[k]);
    }
    const KnotMisses misses = knotMisses(curve, points, t, kappa, {}, false);
    std::printf("control polygon, %s, an exponent per knot in [3.2, 150]: C2 jumps %.1e, third %.2f\n",
      closed ? "closed" : "open", misses.C2, misses.ThirdJump);
    EXPECT_LT(misses.C2, 1e-9);
    EXPECT_GT(misses.ThirdJump, 1e-3);
  }
  // Through fitPolyline, a closed line: the curve closes C2 at its seam and interpolates.
  std::vector<Vec3> ring;
  for (int i = 0; i < 12; ++i)
  {
    ring.emplace_back(std::cos(0.5 * i) * (1 + 0.3 * std::sin(1.5 * i)), std::sin(0.5 * i), 0.2 * std::cos(i));
  }
  FitOptions options;
  options.Closed = true;
  const FittedPolyline fit = fitPolyline(ring, options, qqrBuilder(QQROptions{}));
  const Curve& spline = *fit.Spline;
  const Derivatives seamLeft = spline.evaluateOnSpan(spline.numberOfSpans() - 1, spline.lastParameter(), 2);
  const Derivatives seamRight = spline.evaluateOnSpan(0, spline.firstParameter(), 2);
  for (int m = 0; m <= 2; ++m)
  {
    EXPECT_LT((seamLeft[m] - seamRight[m]).norm(), 1e-12 * std::max(1.0, seamRight[m].norm())) << m;
  }
  for (int k = 0; k < spline.numberOfSpans(); ++k)
  {
    EXPECT_LT((spline.evaluateOnSpan(k, spline.knots()[k], 0)[0] - fit.Data.Points[k]).norm(), 1e-14);
  }
}

TEST(QQRSpline, AnExponentScalesTheCurvatureAtItsKnotWithoutTurningIt)
{
  // Why no exponent mends convexity at a knot or collinearity (criteria (i),
  // (ii.1)): at a knot the qqr curve's r' = kappa (e1 - e0) / h and
  // r'' = kappa (kappa - 1) (e0 - 2 e1 + e2) / h^2, and no construction's Bezier
  // points depend on the exponents (closed: no end condition), so the
  // curvature vector there is the one at kappa = 4 times 4 (kappa - 1) / (3
  // kappa): same direction, never zero where it was not.
  std::mt19937 random(97);
  std::uniform_real_distribution<double> exponent(3.2, 150.0);
  const std::vector<Vec3> points = RandomPoints(12, random);
  const int n = static_cast<int>(points.size());
  const std::vector<double> t = RandomKnots(n + 1, random, 1.5);
  std::vector<double> kappa(n);
  for (double& k : kappa)
  {
    k = exponent(random);
  }
  auto curvatureVector = [](const Curve& curve, int k) {
    const Derivatives d = curve.evaluateOnSpan(k, curve.knots()[k], 2);
    return Vec3(d[1].cross(d[2]).cross(d[1]) / std::pow(d[1].norm(), 4));
  };
  for (const QQRConstruction construction : { QQRConstruction::Interpolation,
         QQRConstruction::LocalInterpolation, QQRConstruction::ControlPolygon })
  {
    const QQRSpline four = QQRSpline::make(construction, points, t, true, 4.0, 4.0);
    const QQRSpline raised = QQRSpline::make(construction, points, t, true, kappa);
    double worst = 0.0;
    for (int k = 0; k < n; ++k)
    {
      const Vec3 expected = curvatureVector(four, k) * 4.0 * (kappa[k] - 1.0) / (3.0 * kappa[k]);
      worst = std::max(worst, (curvatureVector(raised, k) - expected).norm() / expected.norm());
    }
    std::printf("construction %d, closed, an exponent per knot in [3.2, 150]: curvature vector at "
                "the knots against 4 (kappa - 1) / (3 kappa) times kappa = 4's, off by %.1e\n",
      static_cast<int>(construction), worst);
    EXPECT_LT(worst, 1e-9);
  }
}

TEST(QQRSpline, PerPointLocalParametersKeepC2AndTheInterpolation)
{
  // QQRKnotShape: a z (and for the control polygon an x and a y) per point,
  // anywhere in [0, 1] (x, y in [-0.2, 0.5]), with an exponent per knot: the
  // joins stay C2, the interpolation still passes through the data with the
  // tangent (3.20) and second derivative (3.21) of the z on either side.
  std::mt19937 random(144);
  std::uniform_real_distribution<double> exponent(3.2, 40.0), unit(0.0, 1.0), local(-0.2, 0.5);
  for (const bool interpolate : { true, false })
  {
    for (const bool closed : { false, true })
    {
      const std::vector<Vec3> points = RandomPoints(12, random);
      const int n = static_cast<int>(points.size());
      const int spans = closed ? n : n - 1;
      const std::vector<double> t = RandomKnots(spans + 1, random, 1.5);
      std::vector<double> kappa(n);
      QQRKnotShape shape;
      for (int j = 0; j < n; ++j)
      {
        kappa[j] = exponent(random);
        shape.Z.push_back(j % 4 == 0 ? std::round(unit(random)) : unit(random)); // some exactly 0 or 1
        shape.X.push_back(local(random));
        shape.Y.push_back(local(random));
      }
      shape.Z[3] = std::numeric_limits<double>::quiet_NaN(); // the paper's there
      // Z[4] = 1 with Z[5] = 0 would stop the interpolation at point 5.
      shape.Z[4] = 0.9;
      const QQRSpline curve = interpolate
        ? QQRSpline::make(QQRConstruction::LocalInterpolation, points, t, closed, kappa, QQRLocalShape{}, shape)
        : QQRSpline::make(QQRConstruction::ControlPolygon, points, t, closed, kappa, QQRLocalShape{}, shape);
      const QQRKnotShape& used = curve.knotShape();
      for (int j = 0; j < n; ++j)
      {
        if (j != 3)
        {
          EXPECT_EQ(used.Z[j], shape.Z[j]) << j;
        }
        if (!interpolate)
        {
          EXPECT_EQ(used.X[j], shape.X[j]) << j;
          EXPECT_EQ(used.Y[j], shape.Y[j]) << j;
        }
      }
      auto dh = [&](int j) {
        j = closed ? (j % spans + spans) % spans : j;
        return t[j + 1] - t[j];
      };
      EXPECT_NEAR(used.Z[3], (2 * dh(2) + dh(3)) / (2 * (dh(2) + dh(3) + dh(4))), 1e-15);
      const KnotMisses misses =
        knotMisses(curve, points, t, kappa, [&](int k) { return used.Z[k]; }, interpolate);
      std::printf("%s, %s, z (x, y) per point: C2 jumps %.1e, third %.2f; data %.1e, (3.20) %.1e, "
                  "(3.21) %.1e\n",
        interpolate ? "interpolation" : "control polygon", closed ? "closed" : "open", misses.C2,
        misses.ThirdJump, misses.Position, misses.Tangent, misses.Second);
      EXPECT_LT(misses.C2, 1e-9);
      EXPECT_GT(misses.ThirdJump, 1e-3);
      EXPECT_LT(misses.Position, 1e-12);
      EXPECT_LT(misses.Tangent, 1e-11);
      EXPECT_LT(misses.Second, 1e-10);
    }
  }
}

TEST(QQRSpline, LocalParametersStraightenAkimasRun)
{
  // Akima's data: a straight run D_0..D_5, then D_6 off the line. The last
  // span of the run, 4, is straight when its Bezier points are on the line:
  // S_5 (from X[5]) and the middle point of span 5 (Z[5]) must be.
  const std::vector<Vec3> points = akima();
  auto fit = [&](bool interpolate, const QQRKnotShape& shape, double alpha) {
    CurveBuilder builder = [&](const FitContext& context) {
      BuiltCurve built;
      const std::vector<double> kappa(context.Data.Points.size(), alpha);
      built.Spline = std::make_unique<QQRSpline>(interpolate
          ? QQRSpline::make(QQRConstruction::LocalInterpolation, context.Data.Points, context.Knots, false, kappa, {}, shape)
          : QQRSpline::make(QQRConstruction::ControlPolygon, context.Data.Points, context.Knots, false, kappa, {}, shape));
      if (!interpolate)
      {
        built.ShapeReference = context.Data;
      }
      return built;
    };
    return fitPolyline(points, FitOptions{}, builder);
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> free(points.size(), nan);
  auto with = [&](int j, double value) {
    std::vector<double> v = free;
    v[j] = value;
    return v;
  };
  const int collinearity = int(ShapeCriterion::Collinearity);
  for (const double alpha : { 3.5, 4.0, 13.5 })
  {
    // Control polygon: the suggested x_i = z_i = 0 next to the run (X[5] =
    // Z[5] = 0) straightens it; either alone does not.
    EXPECT_EQ(fit(false, QQRKnotShape{ with(5, 0.0), {}, with(5, 0.0) }, alpha).Audit.Failures[collinearity], 0);
    EXPECT_GE(fit(false, QQRKnotShape{ with(5, 0.0), {}, {} }, alpha).Audit.Failures[collinearity], 1);
    EXPECT_GE(fit(false, QQRKnotShape{ {}, {}, with(5, 0.0) }, alpha).Audit.Failures[collinearity], 1);
    // Interpolation: (3.18) makes X[5] ~ -Z[5], so Z[5] = 0 alone does it.
    EXPECT_EQ(fit(true, QQRKnotShape{ {}, {}, with(5, 0.0) }, alpha).Audit.Failures[collinearity], 0);
  }
}

TEST(QQRSpline, AStraightenedSpanLiesOnItsChordAndKeepsC2)
{
  // QQRKnotShape::Straightness, the automatic mode's parameter: at 1 a span
  // between curved data lies on its chord (the interpolation's, the control
  // polygon's segment), and so do the spans of a straight run of the data
  // without the curve stopping at the points inside it; the joins stay C2
  // and the interpolation passes through the points. (Two straightened
  // spans with one between them would want that one's middle point at
  // both ends: the spans here are further apart.)
  std::mt19937 random(2024);
  for (const QQRConstruction construction :
    { QQRConstruction::Interpolation, QQRConstruction::ControlPolygon })
  {
    for (const bool closed : { false, true })
    {
      std::vector<Vec3> points = RandomPoints(16, random);
      const int n = static_cast<int>(points.size());
      const int spans = closed ? n : n - 1;
      // Points 8..11 on the line through 7 and 12: spans 7..11 are a straight run.
      for (int j = 8; j <= 11; ++j)
      {
        points[j] = points[7] + (j - 7) / 5.0 * (points[12] - points[7]);
      }
      const std::vector<double> t = RandomKnots(spans + 1, random, 1.5);
      QQRKnotShape shape;
      shape.Straightness.assign(spans, 0.0);
      shape.StraightThrough.assign(n, 0);
      shape.Straightness[3] = 1.0;
      for (int k = 7; k <= 11; ++k)
      {
        shape.Straightness[k] = 1.0;
        shape.StraightThrough[k] = k > 7;
      }
      shape.Straightness[14] = 0.5; // halfway: a curved span
      const QQRSpline curve = QQRSpline::make(construction, points, t, closed, 4.0, 4.0, {}, shape);
      double offChord = 0.0, c2 = 0.0, through = 0.0, slowest = 1e300, bent = 0.0;
      for (int k = 0; k < spans; ++k)
      {
        const Vec3& a = points[k];
        const Vec3 chord = (points[(k + 1) % n] - a).normalized();
        const double h = t[k + 1] - t[k];
        for (int s = 0; s <= 32; ++s)
        {
          const Derivatives d = curve.evaluateOnSpan(k, t[k] + h * s / 32.0, 1);
          const Vec3 r = d[0] - a;
          const double off = (r - r.dot(chord) * chord).norm();
          if (shape.Straightness[k] == 1.0)
          {
            offChord = std::max(offChord, off);
            slowest = std::min(slowest, d[1].norm() * h / (points[(k + 1) % n] - a).norm());
          }
          else if (k == 14)
          {
            bent = std::max(bent, off);
          }
        }
        if (closed || k > 0)
        {
          const double atKnot = k == 0 ? t[spans] : t[k]; // closed: the last span ends there
          const Derivatives left = curve.evaluateOnSpan((k - 1 + spans) % spans, atKnot, 2);
          const Derivatives right = curve.evaluateOnSpan(k, t[k], 2);
          for (int m = 0; m <= 2; ++m)
          {
            c2 = std::max(c2, (left[m] - right[m]).norm() / std::max(1.0, right[m].norm()));
          }
        }
        if (construction == QQRConstruction::Interpolation)
        {
          through = std::max(through, (curve.evaluateOnSpan(k, t[k], 0)[0] - points[k]).norm());
        }
      }
      std::printf("construction %d, closed %d: straightened spans off their chords by %.1e, "
                  "slowest %.2f of the chord speed; C2 jumps %.1e; data missed by %.1e; the "
                  "halfway span bends %.2f\n",
        static_cast<int>(construction), closed, offChord, slowest, c2, through, bent);
      EXPECT_LT(offChord, 1e-12);
      EXPECT_GT(slowest, 0.05);
      EXPECT_LT(c2, 1e-9);
      EXPECT_LT(through, 1e-12);
      EXPECT_GT(bent, 1e-3);
    }
  }
}

TEST(QQRSpline, AFlattenedKnotHasNoCurvatureAndKeepsC2)
{
  // QQRKnotShape::Flattening at 1 puts S_k at the midpoint of the middle
  // points of its two spans, where the second derivative at the knot
  // vanishes (r'' ~ R_(k-1) - 2 S_k + R_k); it is a choice of x and y, so
  // the joins stay C2 and the interpolation passes through the points. With
  // a span straightened too, that span still lies on its chord.
  std::mt19937 random(77);
  for (const QQRConstruction construction :
    { QQRConstruction::Interpolation, QQRConstruction::ControlPolygon })
  {
    for (const bool closed : { false, true })
    {
      const std::vector<Vec3> points = RandomPoints(14, random);
      const int n = static_cast<int>(points.size());
      const int spans = closed ? n : n - 1;
      const std::vector<double> t = RandomKnots(spans + 1, random, 1.5);
      QQRKnotShape shape;
      shape.Flattening.assign(n, 0.0);
      const std::vector<int> flat = { 0, 4, 5, 9 };
      for (const int k : flat)
      {
        shape.Flattening[k] = 1.0;
      }
      shape.Flattening[11] = 0.5;
      shape.Straightness.assign(spans, 0.0);
      shape.Straightness[4] = 1.0; // between the flattened knots 4 and 5
      const QQRSpline curve = QQRSpline::make(construction, points, t, closed, 4.0, 4.0, {}, shape);
      double flatCurvature = 0.0, otherCurvature = 1e300, c2 = 0.0, through = 0.0, offChord = 0.0;
      for (int k = 0; k < spans; ++k)
      {
        const Derivatives right = curve.evaluateOnSpan(k, t[k], 2);
        const bool isFlat = std::find(flat.begin(), flat.end(), k) != flat.end();
        const bool firstOfOpen = !closed && k == 0; // an open end: its own condition
        const double scale = right[1].norm() * right[1].norm();
        if (isFlat && !firstOfOpen)
        {
          flatCurvature = std::max(flatCurvature, right[2].norm() / scale);
        }
        else if (!isFlat && k != 11 && k != 4 + 1)
        {
          const double curvature = right[1].cross(right[2]).norm() / (scale * right[1].norm());
          otherCurvature = std::min(otherCurvature, curvature);
        }
        if (closed || k > 0)
        {
          const double atKnot = k == 0 ? t[spans] : t[k];
          const Derivatives left = curve.evaluateOnSpan((k - 1 + spans) % spans, atKnot, 2);
          for (int m = 0; m <= 2; ++m)
          {
            c2 = std::max(c2, (left[m] - right[m]).norm() / std::max(1.0, right[m].norm()));
          }
        }
        if (construction == QQRConstruction::Interpolation)
        {
          through = std::max(through, (right[0] - points[k]).norm());
        }
      }
      const Vec3 chord = (points[5] - points[4]).normalized();
      for (int s = 0; s <= 32; ++s)
      {
        const Vec3 r = curve.evaluateOnSpan(4, t[4] + (t[5] - t[4]) * s / 32.0, 0)[0] - points[4];
        offChord = std::max(offChord, (r - r.dot(chord) * chord).norm());
      }
      std::printf("construction %d, closed %d: |r''| / |r'|^2 at flattened knots %.1e (curvature "
                  "elsewhere at least %.2f); C2 jumps %.1e; data missed by %.1e; straightened "
                  "span off its chord by %.1e\n",
        static_cast<int>(construction), closed, flatCurvature, otherCurvature, c2, through,
        offChord);
      EXPECT_LT(flatCurvature, 1e-9);
      EXPECT_GT(otherCurvature, 1e-3);
      EXPECT_LT(c2, 1e-9);
      EXPECT_LT(through, 1e-12);
      if (construction == QQRConstruction::Interpolation)
      {
        EXPECT_LT(offChord, 1e-12);
      }
    }
  }
}

TEST(QQRSpline, ShapeKeptBetweenBuildsGivesTheCurveBuiltWhole)
{
  // A memo computes again only the local parameters (and interpolation rows)
  // that a changed straightness or flattening moves: every build must be the
  // one made without it, bit for bit, whichever spans and knots change (none,
  // a few, next to the ends), straightness and flattening together, with
  // straight runs through some knots and per-point z given.
  std::mt19937 random(91);
  for (const QQRConstruction construction : { QQRConstruction::Interpolation,
         QQRConstruction::ControlPolygon, QQRConstruction::LocalInterpolation })
  {
    const std::vector<Vec3> points = RandomPoints(20, random);
    const int n = static_cast<int>(points.size());
    const int spans = n - 1;
    const std::vector<double> t = RandomKnots(n, random, 1.5);
    std::uniform_int_distribution<int> span(0, spans - 1), point(0, n - 1), howMany(0, 3);
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    QQRKnotShape shape;
    shape.StraightThrough.assign(n, 0);
    shape.StraightThrough[6] = shape.StraightThrough[7] = 1;
    shape.Z.assign(n, std::numeric_limits<double>::quiet_NaN());
    shape.Z[12] = 0.3;
    QQRSpline::GeometryMemo memo;
    for (int build = 0; build < 40; ++build)
    {
      const std::vector<double> exponents(n, build % 3 == 0 ? 4.0 : 6.0);
      const QQRSpline kept =
        QQRSpline::make(construction, points, t, false, exponents, {}, shape, &memo);
      const QQRSpline whole = QQRSpline::make(construction, points, t, false, exponents, {}, shape);
      for (int k = 0; k < spans; ++k)
      {
        for (int j = 0; j < 5; ++j)
        {
          ASSERT_TRUE(kept.bezier(k)[j] == whole.bezier(k)[j])
            << "span " << k << " after build " << build;
        }
      }
      EXPECT_TRUE(kept.knotShape().X == whole.knotShape().X);
      EXPECT_TRUE(kept.knotShape().Y == whole.knotShape().Y);
      EXPECT_TRUE(kept.knotShape().Z == whole.knotShape().Z);
      // The next build's shape: a few spans straightened or released, a
      // few knots flattened (the ends among them every tenth build).
      shape.Straightness.resize(spans, 0.0);
      shape.Flattening.resize(n, 0.0);
      for (int changes = howMany(random); changes > 0; --changes)
      {
        const int k = build % 10 == 9 ? spans - 1 : span(random);
        shape.Straightness[k] = fraction(random) < 0.3 ? 0.0 : fraction(random);
        const int j = build % 10 == 4 ? 0 : point(random);
        shape.Flattening[j] = fraction(random) < 0.5 ? 0.0 : 1.0;
      }
    }
    EXPECT_EQ(memo.Knots, t);
  }
}

TEST(QQRSpline, OpenEndsDoubleTheEndPoints)
{
  // P_{-1} = P_0: the end tangent is along the first chord, the paper's (3.20)
  // with its backward difference gone.
  std::mt19937 random(3);
  const std::vector<Vec3> points = RandomPoints(6, random);
  const std::vector<double> t = RandomKnots(6, random, 1.0);
  const QQRSpline curve = QQRSpline::make(QQRConstruction::LocalInterpolation, points, t, false, 4.0, 4.0);
  const Vec3 start = curve.evaluate(t.front(), 1)[1];
  const Vec3 end = curve.evaluate(t.back(), 1)[1];
  EXPECT_LT(start.normalized().cross((points[1] - points[0]).normalized()).norm(), 1e-14);
  EXPECT_LT(end.normalized().cross((points[5] - points[4]).normalized()).norm(), 1e-14);
  EXPECT_GT(start.dot(points[1] - points[0]), 0.0);
}

namespace
{
FittedPolyline Fit(const std::vector<Vec3>& points, bool interpolate, bool automatic, double alpha = 4.0)
{
  QQROptions options;
  options.Construction = interpolate ? QQRConstruction::LocalInterpolation : QQRConstruction::ControlPolygon;
  options.Automatic = automatic;
  options.Alpha = options.Beta = alpha;
  return fitPolyline(points, FitOptions{}, qqrBuilder(options));
}

double LargestAlpha(const FittedPolyline& fit)
{
  const auto values = fit.Spline->spanParameters().at(0).Values;
  return *std::max_element(values.begin(), values.end());
}

double LargestCurvature(const FittedPolyline& fit)
{
  double largest = 0.0;
  for (const FrenetFrame& frame : sampleFit(fit).Frames)
  {
    largest = std::max(largest, frame.Curvature);
  }
  return largest;
}
} // namespace

TEST(QQRSpline, RaisingAlphaBendsConvexDataTheWrongWayInTheMiddleOfEachSpan)
{
  // Why the automatic mode cannot tighten the local interpolation: on a convex
  // arc, alpha = 4 touches zero curvature mid-span, alpha > 4 reverses it,
  // alpha < 4 keeps it positive. Chord-length knots on a circle arc.
  std::vector<Vec3> points;
  std::vector<double> knots;
  for (int i = 0; i < 9; ++i)
  {
    points.emplace_back(std::cos(0.3 * i), std::sin(0.3 * i), 0.0);
    knots.push_back(2 * std::sin(0.15) * i);
  }
  for (const double alpha : { 3.5, 4.0, 6.0, 20.0 })
  {
    const QQRSpline curve = QQRSpline::make(QQRConstruction::LocalInterpolation, points, knots, false, alpha, alpha);
    double lowest = 1e300;
    for (int s = 0; s <= 64; ++s)
    {
      const Derivatives d = curve.evaluateOnSpan(4, knots[4] + s / 64.0 * (knots[5] - knots[4]), 2);
      lowest = std::min(lowest, d[1].cross(d[2]).z() / std::pow(d[1].norm(), 3));
    }
    const Derivatives atKnot = curve.evaluateOnSpan(4, knots[4], 2);
    const double knotCurvature = atKnot[1].cross(atKnot[2]).norm() / std::pow(atKnot[1].norm(), 3);
    std::printf("circle arc, alpha %g: curvature at the knot %.3f (true 1), lowest on the span %.3g, "
                "speed ratio %.1e\n",
      alpha, knotCurvature, lowest, curve.speedRatio(4));
    if (alpha < 4.0)
    {
      EXPECT_GT(lowest, 0.1);
    }
    else if (alpha == 4.0)
    {
      EXPECT_NEAR(lowest, 0.0, 1e-2);
    }
    else
    {
      EXPECT_LT(lowest, -1.0);
    }
  }
}

TEST(QQRSpline, ShapeDataSetsFixedAndAutomatic)
{
  // Every construction: the automatic exponents never leave more violations
  // than alpha = beta = 4 (the best curve met is kept), the curve stays
  // regular (the speed bound) and C2 (alpha = beta at every knot).
  for (const auto& [name, points] : std::vector<std::pair<const char*, std::vector<Vec3>>>{
         { "Akima", akima() }, { "RPN 15A", rpn15a() }, { "titanium", titanium() } })
  {
    for (const QQRConstruction construction : { QQRConstruction::Interpolation,
           QQRConstruction::LocalInterpolation, QQRConstruction::ControlPolygon })
    {
      QQROptions options;
      options.Construction = construction;
      options.Automatic = false;
      const FittedPolyline fixed = fitPolyline(points, FitOptions{}, qqrBuilder(options));
      options.Automatic = true;
      const FittedPolyline automatic = fitPolyline(points, FitOptions{}, qqrBuilder(options));
      const auto& spline = dynamic_cast<const QQRSpline&>(*automatic.Spline);
      std::printf("%s, construction %d: alpha = beta = 4 %d violations, automatic %d (largest "
                  "alpha %g, curvature %.3g, fixed %.3g)\n",
        name, static_cast<int>(construction), fixed.Audit.violations(), automatic.Audit.violations(),
        LargestAlpha(automatic), LargestCurvature(automatic), LargestCurvature(fixed));
      EXPECT_LE(automatic.Audit.violations(), fixed.Audit.violations()) << name;
      for (int k = 0; k < spline.numberOfSpans(); ++k)
      {
        EXPECT_GE(spline.speedRatio(k), 1e-3) << name << " span " << k;
      }
      // The jumps relative to the largest derivative of that order at the
      // knots (a straight run has second derivatives of rounding size).
      std::array<double, 3> scale{}, jump{};
      for (int k = 1; k < spline.numberOfSpans(); ++k)
      {
        const double u = spline.knots()[k];
        const Derivatives left = spline.evaluateOnSpan(k - 1, u, 2);
        const Derivatives right = spline.evaluateOnSpan(k, u, 2);
        for (int m = 0; m <= 2; ++m)
        {
          scale[m] = std::max(scale[m], right[m].norm());
          jump[m] = std::max(jump[m], (left[m] - right[m]).norm());
        }
      }
      for (int m = 0; m <= 2; ++m)
      {
        EXPECT_LT(jump[m], 1e-10 * scale[m]) << name << " derivative " << m;
      }
    }
  }
  // No exponent fixes Akima's straight run: the span leaving it has a Bezier
  // point off the line (x_i P_i in S_{i-1}), whatever alpha (criterion (i)).
  for (const bool interpolate : { true, false })
  {
    for (const double alpha : { 3.2, 4.0, 8.0, 13.5, 50.0, 200.0 })
    {
      const FittedPolyline fit = Fit(akima(), interpolate, false, alpha);
      EXPECT_GE(fit.Audit.Failures[int(ShapeCriterion::Collinearity)], 1) << alpha;
    }
  }
  // Why the automatic mode bounds the speed: raised far enough, RPN 15A
  // "passes" the audit only because the curve has almost stopped mid-span
  // (speed 1e-17 of the chord's) and the audit counts any curvature there as
  // rounding.
  const FittedPolyline stalled = Fit(rpn15a(), true, false, 68.0);
  const auto& spline = dynamic_cast<const QQRSpline&>(*stalled.Spline);
  double slowest = 1.0;
  for (int k = 0; k < spline.numberOfSpans(); ++k)
  {
    slowest = std::min(slowest, spline.speedRatio(k));
  }
  std::printf("RPN 15A, alpha = 68 fixed: %d violations, slowest span speed ratio %.1e, largest "
              "curvature %.2g\n",
    stalled.Audit.violations(), slowest, LargestCurvature(stalled));
  EXPECT_LT(slowest, 1e-12);
}

TEST(QQRSpline, InterpolationIsTheCubicSplineAtAlphaFour)
{
  // With alpha = beta = 4 and the paper's local parameters the qqr basis is
  // the cubic B-spline basis: the curve through the points is the classical
  // cubic spline interpolant with not-a-knot ends (an independent solve).
  std::mt19937 random(11);
  for (const bool closed : { false, true })
  {
    for (const int n : { 4, 5, 9, 23 })
    {
      const std::vector<Vec3> points = RandomPoints(n, random);
      const std::vector<double> knots = RandomKnots(closed ? n + 1 : n, random, 1.0);
      const QQRSpline qqr =
        QQRSpline::make(QQRConstruction::Interpolation, points, knots, closed, 4.0, 4.0);
      const CubicSpline cubic = CubicSpline::interpolate(points, knots, closed);
      double worst = 0.0;
      for (int k = 0; k < qqr.numberOfSpans(); ++k)
      {
        for (int s = 0; s <= 8; ++s)
        {
          const double u = knots[k] + (knots[k + 1] - knots[k]) * s / 8.0;
          const Derivatives a = qqr.evaluateOnSpan(k, u, 3);
          const Derivatives b = cubic.evaluateOnSpan(k, u, 3);
          for (int m = 0; m <= 3; ++m)
          {
            worst = std::max(worst, (a[m] - b[m]).norm() / (1.0 + b[m].norm()));
          }
        }
      }
      EXPECT_LT(worst, 1e-11) << (closed ? "closed " : "open ") << n;
    }
  }
  // Three points: the natural ends (not-a-knot needs a third span).
  const std::vector<Vec3> three = { { 0, 0, 0 }, { 1, 1, 0 }, { 2, 0, 1 } };
  const QQRSpline curve = QQRSpline::make(QQRConstruction::Interpolation, three, { 0, 1, 2 }, false, 4.0, 4.0);
  EXPECT_LT(curve.evaluate(0.0, 2)[2].norm(), 1e-12);
  EXPECT_LT(curve.evaluate(2.0, 2)[2].norm(), 1e-12);
  EXPECT_LT((curve.evaluate(1.0, 0)[0] - three[1]).norm(), 1e-14);
}

TEST(QQRSpline, InterpolationPassesThroughItsPointsWithATinyEndSpan)
{
  // An end span 1.9e-6 of the others (fuzz: subnormal coordinates, centripetal
  // knots): the not-a-knot row there has entries ~1 / h^3. Solved as it
  // stood, the pivots lost the interpolation rows' accuracy and the curve
  // missed points 1 and 2 by 5e-5 at a condition estimate of 2.6e6; with the
  // rows scaled to a largest entry of 1 it passes through every point to
  // rounding.
  const std::vector<Vec3> points = { { 0, -0.5, -0.5 }, { 0, 0.5, -0.5 }, { 0, -0.5, -0.5 },
    { 0, -0.5, 0.5 }, { 0, -0.5, 0.5 + 3.6e-12 } };
  const std::vector<double> knots = { 0, 1, 2, 3, 3 + 1.9e-6 };
  const QQRSpline curve =
    QQRSpline::make(QQRConstruction::Interpolation, points, knots, false, 4.0, 4.0);
  EXPECT_LT(curve.conditionEstimate(), UntrustedCondition);
  for (size_t i = 0; i < points.size(); ++i)
  {
    EXPECT_LT((curve.evaluate(knots[i], 0)[0] - points[i]).norm(), 1e-12) << "point " << i;
  }
}

TEST(QQRSpline, HelixCurvatureAndTorsion)
{
  // The interpolation (the default) converges at second order; so does the
  // control polygon (the cubic B-spline of the data). Errors are the largest
  // over the samples beyond half a turn from either end, and for the
  // interpolation over all of them (not-a-knot ends: second order too, with a
  // larger constant).
  for (const QQRConstruction construction : { QQRConstruction::Interpolation, QQRConstruction::ControlPolygon })
  {
    RelativeErrors previous{ 1.0, 1.0 }, previousWhole{ 1.0, 1.0 };
    for (const int perTurn : { 8, 16, 32, 64 })
    {
      QQROptions options;
      options.Construction = construction;
      const FittedPolyline fit = fitPolyline(helix(perTurn, 6), FitOptions{}, qqrBuilder(options));
      const RelativeErrors errors = interiorErrors(fit, 0.4, 0.2, perTurn / 2);
      const RelativeErrors whole = interiorErrors(fit, 0.4, 0.2, 0);
      const double curvatureOrder = std::log2(previous.Curvature / errors.Curvature);
      const double torsionOrder = std::log2(previous.Torsion / errors.Torsion);
      std::printf("helix, construction %d, automatic, %d points per turn: curvature %.3g%%, torsion "
                  "%.3g%% (orders %.2f, %.2f; whole curve %.3g%%, %.3g%%, orders %.2f, %.2f), %d violations\n",
        static_cast<int>(construction), perTurn, 100 * errors.Curvature, 100 * errors.Torsion,
        curvatureOrder, torsionOrder, 100 * whole.Curvature, 100 * whole.Torsion,
        std::log2(previousWhole.Curvature / whole.Curvature),
        std::log2(previousWhole.Torsion / whole.Torsion), fit.Audit.violations());
      if (perTurn > 16)
      {
        EXPECT_GT(curvatureOrder, 1.8);
        EXPECT_GT(torsionOrder, 1.8);
      }
      // The control polygon's doubled end points straighten its ends: no
      // convergence there.
      if (construction == QQRConstruction::Interpolation)
      {
        if (perTurn > 16)
        {
          EXPECT_GT(std::log2(previousWhole.Curvature / whole.Curvature), 1.8);
          EXPECT_GT(std::log2(previousWhole.Torsion / whole.Torsion), 1.8);
        }
        EXPECT_LT(errors.Curvature, perTurn >= 64 ? 0.01 : (perTurn >= 32 ? 0.05 : 1.0));
        EXPECT_LT(errors.Torsion, perTurn >= 64 ? 0.01 : (perTurn >= 32 ? 0.05 : 1.0));
      }
      previous = errors;
      previousWhole = whole;
    }
  }
}

TEST(QQRSpline, LocalInterpolationCurvatureTendsToThreeTimesTheCurves)
{
  // Why the local interpolation is not the default: at alpha = 4 on uniform
  // knots z = 1/2, (3.20) is the central difference (P_{i+1} - P_{i-1}) / 2h
  // and (3.21) is (alpha^2 - alpha) / 2 * (1/2) * (P_{i+1} - 2 P_i + P_{i-1}) /
  // h^2, three times the second difference: at every point the curvature
  // tends to 3 times the helix's (0.4) as the points get denser.
  double previous = 0.0;
  for (const int perTurn : { 8, 16, 32, 64, 128 })
  {
    QQROptions options;
    options.Construction = QQRConstruction::LocalInterpolation;
    options.Automatic = false;
    const FittedPolyline fit = fitPolyline(helix(perTurn, 4), FitOptions{}, qqrBuilder(options));
    const SampledCurve sampled = sampleFit(fit);
    double ratio = 0.0;
    int knots = 0;
    for (int k = 0; k < sampled.Samples.size(); ++k)
    {
      const int span = sampled.Samples.Span[k];
      if (sampled.Samples.SpanFraction[k] == 0.0 && span >= 2 && span + 2 < fit.Data.numberOfSpans())
      {
        ratio += sampled.Frames[k].Curvature / 0.4;
        ++knots;
      }
    }
    ratio /= knots;
    std::printf("local interpolation, %d points per turn: curvature at the points / the helix's %.4f\n",
      perTurn, ratio);
    if (perTurn >= 32)
    {
      EXPECT_LT(std::abs(ratio - 3.0), std::abs(previous - 3.0)) << perTurn; // tends to 3
    }
    previous = ratio;
  }
  EXPECT_NEAR(previous, 3.0, 0.01);
}

TEST(QQRSpline, RejectsBadShapeParametersAndSizes)
{
  EXPECT_THROW(qqrBasis(0.5, 1.9, 4.0), std::invalid_argument);
  EXPECT_THROW(qqrBasis(0.5, 4.0, 1.0), std::invalid_argument);
  EXPECT_THROW(qqrBasis(0.5, NAN, 4.0), std::invalid_argument);
  const std::vector<Vec3> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 1 } };
  const std::vector<double> knots = { 0, 1, 2, 3 };
  EXPECT_NO_THROW(QQRSpline::make(QQRConstruction::LocalInterpolation, points, knots, false, 2.0, 2.0));
  EXPECT_THROW(QQRSpline::make(QQRConstruction::LocalInterpolation, points, knots, false, 4.0, 1.5), std::invalid_argument);
  EXPECT_THROW(QQRSpline::make(QQRConstruction::ControlPolygon, points, knots, false, 1.5, 4.0), std::invalid_argument);
  EXPECT_THROW(QQRSpline::make(QQRConstruction::LocalInterpolation, points, { 0, 1, 2 }, false, 4.0, 4.0), std::invalid_argument);
  EXPECT_THROW(QQRSpline::make(QQRConstruction::LocalInterpolation, points, knots, true, 4.0, 4.0), std::invalid_argument); // closed: 5 knots
  EXPECT_THROW(QQRSpline::make(QQRConstruction::LocalInterpolation, points, { 0, 1, 1, 3 }, false, 4.0, 4.0), std::invalid_argument);
  EXPECT_THROW(QQRSpline::make(QQRConstruction::LocalInterpolation, points, knots, false, std::vector<double>{ 4, 4, 4 }), std::invalid_argument);
  EXPECT_THROW(QQRSpline::make(QQRConstruction::LocalInterpolation, points, knots, false, std::vector<double>{ 4, 4, 1, 4 }), std::invalid_argument);
  EXPECT_THROW(QQRBSplineBasis({ 0, 1, 2, 3 }, 4, 4, {}), std::invalid_argument);
  EXPECT_THROW(QQRBSplineBasis({ 0, 1, 2, 3, 4 }, 4, 4, QQRLocalParameters{}), std::invalid_argument);
  QQROptions options;
  options.Alpha = 1.5;
  EXPECT_THROW(qqrBuilder(options), std::invalid_argument);
  options.Alpha = 4.0;
  options.Beta = -1.0;
  EXPECT_THROW(qqrBuilder(options), std::invalid_argument);
  options.Beta = 4.0;
  options.MaxAlpha = NAN;
  EXPECT_THROW(qqrBuilder(options), std::invalid_argument);
  options.Automatic = false; // MaxAlpha not used
  EXPECT_NO_THROW(qqrBuilder(options));
  // Local shape parameters per point: one per point, finite or NaN.
  const std::vector<double> kappa(4, 4.0);
  const QQRLocalShape paper;
  EXPECT_NO_THROW(QQRSpline::make(QQRConstruction::LocalInterpolation, points, knots, false, kappa, paper, QQRKnotShape{ {}, {}, { NAN, 0.2, 1, 0 } }));
  EXPECT_THROW(QQRSpline::make(QQRConstruction::LocalInterpolation, points, knots, false, kappa, paper, QQRKnotShape{ {}, {}, { 0.5, 0.5, 0.5 } }),
    std::invalid_argument);
  EXPECT_THROW(QQRSpline::make(QQRConstruction::ControlPolygon, points, knots, false, kappa, paper, QQRKnotShape{ { 0, 0, INFINITY, 0 }, {}, {} }),
    std::invalid_argument);
  // Straightness: one value in [0, 1] per span; StraightThrough: one flag per point.
  auto withStraightness = [&](std::vector<double> straightness, std::vector<char> through) {
    QQRKnotShape shape;
    shape.Straightness = std::move(straightness);
    shape.StraightThrough = std::move(through);
    return QQRSpline::make(QQRConstruction::Interpolation, points, knots, false, kappa, paper, shape);
  };
  EXPECT_NO_THROW(withStraightness({ 0, 1, 0.5 }, { 0, 0, 0, 0 }));
  EXPECT_THROW(withStraightness({ 0, 1, 0.5, 0 }, {}), std::invalid_argument);
  EXPECT_THROW(withStraightness({ 0, 1.5, 0 }, {}), std::invalid_argument);
  EXPECT_THROW(withStraightness({ 0, NAN, 0 }, {}), std::invalid_argument);
  EXPECT_THROW(withStraightness({}, { 0, 0, 0 }), std::invalid_argument);
  // Flattening: one value in [0, 1] per point.
  auto withFlattening = [&](std::vector<double> flattening) {
    QQRKnotShape shape;
    shape.Flattening = std::move(flattening);
    return QQRSpline::make(
      QQRConstruction::Interpolation, points, knots, false, kappa, paper, shape);
  };
  EXPECT_NO_THROW(withFlattening({ 0, 1, 0, 0.5 }));
  EXPECT_THROW(withFlattening({ 0, 1, 0 }), std::invalid_argument);
  EXPECT_THROW(withFlattening({ 0, -0.5, 0, 0 }), std::invalid_argument);
  EXPECT_THROW(withFlattening({ 0, NAN, 0, 0 }), std::invalid_argument);
}
