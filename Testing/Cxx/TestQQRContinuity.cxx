// Theorem 13 of Wang & Zhang: with x = y = 0 and alpha = beta >= l + 3 the qqr
// B-spline curves are C2 and Frenet frame continuous (FC(2l+3)) at every
// knot, although the third derivative jumps; with the paper's cubic B-spline
// parameters (x, y != 0) the torsion jumps instead.
#include "FrenetFrame.h"
#include "MathTestUtilities.h"
#include "QQRSpline.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

using namespace shapesplines;
using namespace shapesplines::test;

namespace
{
struct Jumps
{
  double Frame = 0.0;     ///< largest |left - right| of T, N, B
  double Curvature = 0.0; ///< relative
  double Torsion = 0.0;   ///< relative to the largest |torsion| along the curve
  double Third = 0.0;     ///< relative jump of s'''
};

Jumps jumpsAtKnots(const QQRSpline& curve)
{
  Jumps jumps;
  // The torsion's scale: its largest value on 64 samples per span.
  double torsionScale = 0.0;
  for (int j = 0; j < curve.numberOfSpans(); ++j)
  {
    for (int k = 1; k < 64; ++k)
    {
      const double u = curve.knots()[j] + (curve.knots()[j + 1] - curve.knots()[j]) * k / 64.0;
      torsionScale =
        std::max(torsionScale, std::abs(frenetFrames({ curve.evaluateOnSpan(j, u, 3) }, 1e-12)[0].Torsion));
    }
  }
  std::vector<std::pair<FrenetFrame, FrenetFrame>> sides;
  for (int j = 1; j < curve.numberOfSpans(); ++j)
  {
    const double u = curve.knots()[j];
    const Derivatives left = curve.evaluateOnSpan(j - 1, u, 3);
    const Derivatives right = curve.evaluateOnSpan(j, u, 3);
    const FrenetFrame a = frenetFrames({ left }, 1e-12)[0];
    const FrenetFrame b = frenetFrames({ right }, 1e-12)[0];
    jumps.Frame = std::max({ jumps.Frame, (a.Tangent - b.Tangent).norm(), (a.Normal - b.Normal).norm(),
      (a.Binormal - b.Binormal).norm() });
    jumps.Curvature = std::max(jumps.Curvature, std::abs(a.Curvature - b.Curvature) / a.Curvature);
    jumps.Third = std::max(jumps.Third, relativeJump(left[3], right[3]));
    sides.emplace_back(a, b);
  }
  for (const auto& [a, b] : sides)
  {
    jumps.Torsion = std::max(jumps.Torsion, std::abs(a.Torsion - b.Torsion) / torsionScale);
  }
  return jumps;
}
} // namespace

TEST(QQRTheorem13, ZeroLocalParametersGiveFrenetFrameContinuityWhereThePapersDoNot)
{
  std::mt19937 random(13);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> points;
  std::vector<double> knots = { 0.0 };
  for (int i = 0; i < 12; ++i)
  {
    points.emplace_back(unit(random), unit(random), unit(random));
    knots.push_back(knots.back() + 1.5 + unit(random));
  }
  knots.pop_back();
  for (const double alpha : { 4.0, 6.0, 9.0 })
  {
    const auto frenet = QQRSpline::make(QQRConstruction::ControlPolygon, points, knots, false, alpha, alpha, { 0.0, 0.0, 0.5 });
    const Jumps fc = jumpsAtKnots(frenet);
    std::printf("alpha = beta = %g, x = y = 0: jumps of frame %.1e, curvature %.1e, torsion %.1e, "
                "third derivative %.2f\n",
      alpha, fc.Frame, fc.Curvature, fc.Torsion, fc.Third);
    EXPECT_LT(fc.Frame, 1e-9) << alpha;
    EXPECT_LT(fc.Curvature, 1e-9) << alpha;
    EXPECT_LT(fc.Torsion, 1e-8) << alpha;
    EXPECT_GT(fc.Third, 1e-3) << alpha; // not C3: the torsion's continuity is Theorem 13's
  }
  const auto cubic = QQRSpline::make(QQRConstruction::ControlPolygon, points, knots, false, 4.0, 4.0);
  const Jumps c2 = jumpsAtKnots(cubic);
  std::printf("the paper's cubic B-spline parameters: torsion jumps %.2f of its largest value\n", c2.Torsion);
  EXPECT_LT(c2.Curvature, 1e-9); // C2
  EXPECT_GT(c2.Torsion, 1e-2);   // but not FC3
}

TEST(QQRTheorem13, ConvexControlPolygonsGiveConvexCurves)
{
  // (3.17): with x = y = 0 and alpha = beta, Q'' is a non-negative combination
  // of the polygon's turning edges, so a convex polygon gives a curve whose
  // signed curvature keeps the polygon's sign. Convex data: an uneven parabola.
  std::vector<Vec3> points;
  std::vector<double> knots;
  for (const double x : { -3.0, -2.2, -1.0, -0.7, 0.1, 0.4, 1.5, 1.7, 2.8, 3.0 })
  {
    points.emplace_back(x, 0.3 * x * x, 0.0);
    knots.push_back(knots.empty() ? 0.0 : knots.back() + (points.back() - points[points.size() - 2]).norm());
  }
  for (const double alpha : { 4.0, 7.0, 20.0 })
  {
    for (const double z : { 0.2, 0.5, 0.8 })
    {
      const auto curve = QQRSpline::make(QQRConstruction::ControlPolygon, points, knots, false, alpha, alpha, { 0.0, 0.0, z });
      // The doubled end points make the curvature vanish at the ends: strictly
      // positive inside, zero up to rounding on the end spans.
      double inside = 1e300, ends = 1e300;
      for (int j = 0; j < curve.numberOfSpans(); ++j)
      {
        const bool end = j == 0 || j == curve.numberOfSpans() - 1;
        for (int k = 0; k <= 32; ++k)
        {
          const double u = knots[j] + (knots[j + 1] - knots[j]) * k / 32.0;
          const Derivatives d = curve.evaluateOnSpan(j, u, 2);
          double& smallest = end ? ends : inside;
          smallest = std::min(smallest, d[1].cross(d[2]).z() / std::pow(d[1].norm(), 3));
        }
      }
      EXPECT_GT(inside, 0.0) << "alpha " << alpha << " z " << z;
      EXPECT_GT(ends, -1e-10) << "alpha " << alpha << " z " << z;
    }
  }
}
