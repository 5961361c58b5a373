// Theorem 13 of paper 003: with x = y = 0 and alpha = beta >= l + 3 the qqr
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
    const auto frenet = QQRSpline::approximate(points, knots, false, alpha, alpha, { 0.0, 0.0, 0.5 });
    const Jumps fc = jumpsAtKnots(frenet);
    std::printf("alpha = beta = %g, x = y = 0: jumps of frame %.1e, curvature %.1e, torsion %.1e, "
                "third derivative %.2f\n",
      alpha, fc.Frame, fc.Curvature, fc.Torsion, fc.Third);
    EXPECT_LT(fc.Frame, 1e-9) << alpha;
    EXPECT_LT(fc.Curvature, 1e-9) << alpha;
    EXPECT_LT(fc.Torsion, 1e-8) << alpha;
    EXPECT_GT(fc.Third, 1e-3) << alpha; // not C3: the torsion's continuity is Theorem 13's
  }
  const auto cubic = QQRSpline::approximate(points, knots, false, 4.0, 4.0);
  const Jumps c2 = jumpsAtKnots(cubic);
  std::printf("the paper's cubic B-spline parameters: torsion jumps %.2f of its largest value\n", c2.Torsion);
  EXPECT_LT(c2.Curvature, 1e-9); // C2
  EXPECT_GT(c2.Torsion, 1e-2);   // but not FC3
}
