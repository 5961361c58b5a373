// The classical C2 cubic spline: interpolation, continuity, end conditions,
// polynomial reproduction and curvature/torsion accuracy on the helix.
#include "MathTestUtilities.h"
#include "SparseSolve.h"

#include "Parameterization.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

using namespace shapesplines;
using namespace shapesplines::test;

namespace
{
struct RandomData
{
  std::vector<Vec3> Points;
  std::vector<double> Knots;
};

RandomData randomData(int n, unsigned seed)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::uniform_real_distribution<double> step(0.1, 2.0);
  RandomData data;
  double t = 0.0;
  for (int i = 0; i < n; ++i)
  {
    data.Points.emplace_back(coordinate(generator), coordinate(generator), coordinate(generator));
    data.Knots.push_back(t);
    t += step(generator);
  }
  return data;
}

/// Largest jump of derivative `order` across the interior knots, relative to its size.
double largestJump(const Curve& curve, int order)
{
  double jump = 0.0;
  double size = 1e-300;
  const auto& knots = curve.knots();
  const int last = curve.isClosed() ? curve.numberOfSpans() : curve.numberOfSpans() - 1;
  for (int i = 1; i <= last; ++i)
  {
    const int right = i % curve.numberOfSpans();
    const Vec3 left = curve.evaluateOnSpan(i - 1, knots[i], order)[order];
    const Vec3 start = curve.evaluateOnSpan(right, knots[right], order)[order];
    jump = std::max(jump, (left - start).norm());
    size = std::max({ size, left.norm(), start.norm() });
  }
  return jump / size;
}
} // namespace

TEST(CubicSpline, InterpolatesWithEveryEndCondition)
{
  const RandomData data = randomData(12, 1);
  for (const auto ends :
    { CubicEndCondition::Natural, CubicEndCondition::NotAKnot, CubicEndCondition::Clamped })
  {
    const CubicSpline s = CubicSpline::interpolate(data.Points, data.Knots, false, ends);
    for (size_t i = 0; i < data.Points.size(); ++i)
    {
      EXPECT_LT((s.evaluate(data.Knots[i])[0] - data.Points[i]).norm(), 1e-12);
    }
  }
}

TEST(CubicSpline, IsC2AndNotC3)
{
  const RandomData data = randomData(15, 2);
  const CubicSpline s = CubicSpline::interpolate(data.Points, data.Knots, false);
  for (int order = 0; order <= 2; ++order)
  {
    EXPECT_LT(largestJump(s, order), 1e-12) << "order " << order;
  }
  // The third derivative does jump: the test measures what it claims.
  EXPECT_GT(largestJump(s, 3), 1e-2);
}

TEST(CubicSpline, EndConditionsHold)
{
  const RandomData data = randomData(9, 3);
  const auto& t = data.Knots;
  const double t0 = t.front(), tn = t.back();

  const CubicSpline natural =
    CubicSpline::interpolate(data.Points, t, false, CubicEndCondition::Natural);
  EXPECT_LT(natural.evaluate(t0)[2].norm(), 1e-12);
  EXPECT_LT(natural.evaluate(tn)[2].norm(), 1e-12);

  const CubicSpline::EndDerivatives given{ Vec3(1, -2, 3), Vec3(-0.5, 0.25, 4) };
  const CubicSpline clamped =
    CubicSpline::interpolate(data.Points, t, false, CubicEndCondition::Clamped, given);
  EXPECT_LT((clamped.evaluate(t0)[1] - given.first).norm(), 1e-12);
  EXPECT_LT((clamped.evaluate(tn)[1] - given.second).norm(), 1e-12);

  const CubicSpline notAKnot = CubicSpline::interpolate(data.Points, t, false);
  for (const int i : { 1, static_cast<int>(t.size()) - 2 })
  {
    const Vec3 left = notAKnot.evaluateOnSpan(i - 1, t[i], 3)[3];
    const Vec3 right = notAKnot.evaluateOnSpan(i, t[i], 3)[3];
    EXPECT_LT((left - right).norm(), 1e-10 * left.norm());
  }
}

TEST(CubicSpline, PeriodicIsC2AcrossTheSeam)
{
  RandomData data = randomData(10, 4);
  data.Knots.push_back(data.Knots.back() + 0.7); // closing span
  const CubicSpline s = CubicSpline::interpolate(data.Points, data.Knots, true);
  const double t0 = data.Knots.front(), tn = data.Knots.back();
  for (int order = 0; order <= 2; ++order)
  {
    const Vec3 start = s.evaluateOnSpan(0, t0, order)[order];
    const Vec3 end = s.evaluateOnSpan(s.numberOfSpans() - 1, tn, order)[order];
    EXPECT_LT((start - end).norm(), 1e-12 * std::max(1.0, start.norm())) << "order " << order;
  }
  EXPECT_LT(largestJump(s, 2), 1e-12);
}

TEST(CubicSpline, NotAKnotReproducesCubicsAndClampedWithParabolaEndsReproducesParabolas)
{
  std::vector<Vec3> points;
  std::vector<double> t;
  for (int i = 0; i < 7; ++i)
  {
    const double x = 0.3 * i * i + i; // uneven knots
    t.push_back(x);
    points.emplace_back(x * x * x - 2 * x, 1 - x * x, 0.5 * x);
  }
  const CubicSpline s = CubicSpline::interpolate(points, t, false);
  for (double x = t.front(); x <= t.back(); x += 0.137)
  {
    const Vec3 exact(x * x * x - 2 * x, 1 - x * x, 0.5 * x);
    EXPECT_LT((s.evaluate(x)[0] - exact).norm(), 1e-10 * (1 + exact.norm()));
    EXPECT_NEAR(s.evaluate(x)[3].x(), 6.0, 1e-8);
  }
  // Three points: the not-a-knot spline is the parabola through them.
  const std::vector<Vec3> three = { Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(3, 9, 0) };
  const CubicSpline p = CubicSpline::interpolate(three, { 0, 1, 3 }, false);
  EXPECT_NEAR(p.evaluate(2.0)[0].y(), 4.0, 1e-12);
  EXPECT_NEAR(p.evaluate(0.5)[2].y(), 2.0, 1e-12);
  // Clamped with the default (parabola) end derivatives reproduces a parabola.
  std::vector<Vec3> parabola;
  for (const double x : t)
  {
    parabola.emplace_back(x, x * x, 0);
  }
  const CubicSpline c = CubicSpline::interpolate(parabola, t, false, CubicEndCondition::Clamped);
  EXPECT_NEAR(c.evaluate(2.345)[0].y(), 2.345 * 2.345, 1e-10);
}

TEST(CubicSpline, RejectsBadKnots)
{
  const std::vector<Vec3> points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 1, 0) };
  EXPECT_THROW(CubicSpline::interpolate(points, { 0, 1, 1 }, false), std::invalid_argument);
  EXPECT_THROW(CubicSpline::interpolate(points, { 0, 1 }, false), std::invalid_argument);
  EXPECT_THROW(CubicSpline::interpolate({ Vec3(0, 0, 0) }, { 0 }, false), std::invalid_argument);
}

TEST(CubicSpline, HelixCurvatureAndTorsionConvergeAtSecondOrder)
{
  // Helix a = 2, b = 1: curvature 0.4, torsion 0.2. Interior: two turns away from the ends.
  FitOptions options;
  options.Sampling.Subdivisions = 20;
  RelativeErrors previous;
  for (const int perTurn : { 8, 16, 32 })
  {
    const FittedPolyline fit = fitPolyline(helix(perTurn, 6), options, cubicBuilder());
    const RelativeErrors e = interiorErrors(fit, 0.4, 0.2, 2 * perTurn);
    std::printf("helix %2d points/turn: max interior error curvature %.3e torsion %.3e", perTurn,
      e.Curvature, e.Torsion);
    if (perTurn > 8)
    {
      std::printf("  observed order %.2f %.2f", std::log2(previous.Curvature / e.Curvature),
        std::log2(previous.Torsion / e.Torsion));
      EXPECT_GT(std::log2(previous.Curvature / e.Curvature), 1.7);
      EXPECT_GT(std::log2(previous.Torsion / e.Torsion), 1.7);
    }
    std::printf("\n");
    previous = e;
  }
  // At 32 points per turn a C2 cubic is good to about 1%.
  EXPECT_LT(previous.Curvature, 1e-2);
  EXPECT_LT(previous.Torsion, 1e-2);
  EXPECT_GT(previous.Torsion, 1e-5); // and it is not exact: the figure is measured
}

TEST(CubicSpline, PlanarDataGiveZeroTorsion)
{
  FitOptions options;
  const FittedPolyline fit = fitPolyline(akima(), options, cubicBuilder());
  for (const auto& f : sampleFit(fit).Frames)
  {
    EXPECT_LE(std::abs(f.Torsion), 1e-12);
  }
}

TEST(CubicSpline, LargeInputSolvesInLinearMemory)
{
  // 2e5 points: a dense solve would need 320 GB; the sparse banded solve is instant.
  const std::vector<Vec3> points = helix(50, 4000);
  const CleanPolyline line = cleanPolyline(points, false);
  const auto knots = computeKnots(line, Parameterization::ChordLength);
  const CubicSpline s = CubicSpline::interpolate(line.Points, knots, false);
  EXPECT_LT((s.evaluate(knots[123456])[0] - line.Points[123456]).norm(), 1e-9);
}

TEST(CubicSpline, NaturalEndMomentsAreExactlyZeroAtAnyScale)
{
  // Regression: with chord lengths of 1e6 next to the unit row M_0 = 0, pivoting
  // left M_0 at rounding level, and the curvature there (above the flatness
  // floor) produced a torsion of 1e9. The end rows are now scaled like the others.
  for (const double scale : { 1e-6, 1.0, 1e6 })
  {
    const RandomData data = randomData(10, 5);
    std::vector<Vec3> points;
    std::vector<double> knots;
    for (size_t i = 0; i < data.Points.size(); ++i)
    {
      points.push_back(scale * data.Points[i]);
      knots.push_back(scale * data.Knots[i]);
    }
    const CubicSpline s =
      CubicSpline::interpolate(points, knots, false, CubicEndCondition::Natural);
    EXPECT_EQ(s.evaluateOnSpan(0, knots.front(), 2)[2].norm(), 0.0) << scale;
  }
}

TEST(SparseSolve, ConditionEstimateIsWithinAFactorOfThreeOfTheTrueOne)
{
  // Tridiagonal and cyclic systems like the splines', with one span from mild to tiny,
  // and one badly scaled row, which the estimate must see through.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double smallest : { 0.5, 1e-3, 1e-8 })
  {
    for (const bool cyclic : { false, true })
    {
      const int n = 40;
      std::vector<double> h(n);
      for (double& v : h)
      {
        v = 0.5 + unit(random);
      }
      h[n / 2] = smallest;
      Triplets entries;
      Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
      for (int i = 0; i < n; ++i)
      {
        const int prev = (i + n - 1) % n;
        for (const auto& [column, value] : { std::pair<int, double>{ prev, h[prev] },
               { i, 2.0 * (h[prev] + h[i]) }, { (i + 1) % n, h[i] } })
        {
          if (cyclic || std::abs(column - i) <= 1)
          {
            const double rowScale = i == 3 ? 1e-9 : 1.0;
            entries.emplace_back(i, column, rowScale * value);
            dense(i, column) += rowScale * value;
          }
        }
      }
      const Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Random(n, 3);
      DeferredCondition condition;
      const Eigen::MatrixX3d x = solveSparse(n, entries, rhs, &condition);
      const double estimate = condition.value();
      EXPECT_LT((dense * x - rhs).norm(), 1e-12 * dense.norm() * x.norm());
      // The condition of the rows scaled to a largest entry of 1.
      const Eigen::VectorXd rowMax = dense.cwiseAbs().rowwise().maxCoeff();
      const Eigen::MatrixXd scaled = rowMax.cwiseInverse().asDiagonal() * dense;
      const double exact = scaled.cwiseAbs().colwise().sum().maxCoeff() *
        scaled.inverse().cwiseAbs().colwise().sum().maxCoeff();
      // A lower bound, up to the rounding of solves with the badly scaled row.
      EXPECT_LE(estimate, exact * (1 + 1e-6)) << smallest << (cyclic ? " cyclic" : "");
      EXPECT_GE(estimate, exact / 3.0) << smallest << (cyclic ? " cyclic" : "");
    }
  }
}

TEST(SparseSolve, ConditionEstimateOfAnIllConditionedSystemIsLarge)
{
  // [[1, 1], [1, 1 + 1e-12]]: condition about 4e12, whatever the row scaling.
  const Triplets entries = { { 0, 0, 1.0 }, { 0, 1, 1.0 }, { 1, 0, 1.0 }, { 1, 1, 1.0 + 1e-12 } };
  DeferredCondition condition;
  solveSparse(2, entries, Eigen::MatrixX3d::Ones(2, 3), &condition);
  const double estimate = condition.value();
  EXPECT_GT(estimate, UntrustedCondition);
  EXPECT_NEAR(estimate, 4e12, 0.1e12);
}

TEST(SparseSolve, ADeferredConditionIsTheLargestOfItsSystemsOnceAndForAll)
{
  EXPECT_EQ(DeferredCondition().value(), 1.0); // nothing solved
  // diag(1, 1e-6) is row-scaled to the identity: condition 1. The
  // ill-conditioned pair above: about 4e12.
  const Triplets wellScaled = { { 0, 0, 1.0 }, { 1, 1, 1e-6 } };
  const Triplets nearlySingular = { { 0, 0, 1.0 }, { 0, 1, 1.0 }, { 1, 0, 1.0 },
    { 1, 1, 1.0 + 1e-12 } };
  DeferredCondition first, second;
  solveSparse(2, wellScaled, Eigen::MatrixX3d::Ones(2, 3), &first);
  solveSparse(2, nearlySingular, Eigen::MatrixX3d::Ones(2, 3), &second);
  EXPECT_NEAR(first.value(), 1.0, 1e-12);
  DeferredCondition both = first;
  both.merge(second);
  EXPECT_NEAR(both.value(), 4e12, 0.1e12);
  // Estimated, both keeps the value and no longer its systems: merged into
  // first, it is that kept value that counts.
  first.merge(both);
  EXPECT_EQ(first.value(), both.value());
}
