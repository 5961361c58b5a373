// Metamorphic tests: a rigid motion, a uniform scaling, a mirror or a
// reversal of the data must transform the fitted curve the same way. Every
// spline family joins by adding its builder to Families below.
#include "GeneralizedCubicSpline.h"
#include "MathTestUtilities.h"
#include "QQRSpline.h"
#include "TensionQuinticFit.h"
#include "VariableDegreeSpline.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cstdio>
#include <string>

using namespace shapesplines;
using namespace shapesplines::test;

namespace
{
struct Family
{
  std::string Name;
  CurveBuilder Build;
  bool Closed;
};

/// qqr with alpha = beta, fixed or as the automatic mode's start.
CurveBuilder qqr(bool interpolate, double alpha, bool automatic = false)
{
  QQROptions options;
  options.Construction = interpolate ? QQRConstruction::LocalInterpolation : QQRConstruction::ControlPolygon;
  options.Automatic = automatic;
  options.Alpha = alpha;
  options.Beta = alpha;
  return qqrBuilder(options);
}

CurveBuilder generalizedCubic(SpaceKind kind, double tension)
{
  GeneralizedCubicOptions options;
  options.Kind = kind;
  options.Automatic = false;
  options.Tension = tension;
  return generalizedCubicBuilder(options);
}

/// Fixed tension: the automatic mode drives this kinked data to gamma ~ 1e-6,
/// where curvature spikes of 1e6 carry only about 1e-9 relative precision.
CurveBuilder quinticBuilder(QuinticContinuity continuity, double gamma, double lambda)
{
  QuinticFitOptions quintic;
  quintic.Continuity = continuity;
  quintic.Automatic = false;
  quintic.Gamma = gamma;
  quintic.Lambda = lambda;
  return tensionQuinticBuilder(quintic);
}

CurveBuilder variableDegree(VariableDegreeEnds ends, double degree)
{
  VariableDegreeOptions options;
  options.Ends = ends;
  options.Automatic = false;
  options.Degree = degree;
  return variableDegreeBuilder(options);
}

std::vector<Family> Families()
{
  return { { "CubicNotAKnot", cubicBuilder(CubicEndCondition::NotAKnot), false },
    { "CubicNatural", cubicBuilder(CubicEndCondition::Natural), false },
    { "CubicClamped", cubicBuilder(CubicEndCondition::Clamped), false },
    { "CubicPeriodic", cubicBuilder(), true },
    { "GeneralizedExponentialAutomatic", generalizedCubicBuilder({}), false },
    { "GeneralizedExponentialClosed", generalizedCubicBuilder({}), true },
    { "GeneralizedTrigonometricFixed", generalizedCubic(SpaceKind::Trigonometric, 2.0), false },
    { "GeneralizedVariableDegreeFixed", generalizedCubic(SpaceKind::VariableDegree, 7.0), false },
    { "TensionQuinticC4", quinticBuilder(QuinticContinuity::C4, 0.4, 1.0), false },
    { "TensionQuinticC3", quinticBuilder(QuinticContinuity::C3, 1.3, 0.3), false },
    { "TensionQuinticC4Closed", quinticBuilder(QuinticContinuity::C4, 0.4, 1.0), true },
    { "TensionQuinticC3Closed", quinticBuilder(QuinticContinuity::C3, 0.5, 0.5), true },
    { "VariableDegreeAutomatic", variableDegreeBuilder({}), false },
    { "VariableDegreeClosed", variableDegreeBuilder({}), true },
    { "VariableDegreeClampedFixed", variableDegree(VariableDegreeEnds::Clamped, 9.0), false },
    { "QQRInterpolationAutomatic", qqrBuilder({}), false },
    { "QQRInterpolationClosed", qqrBuilder({}), true },
    { "QQRControlPolygonAutomatic", qqr(false, 4.0, true), false },
    { "QQRInterpolationFixed", qqr(true, 5.0), false },
    { "QQRControlPolygonFixed", qqr(false, 6.0), false } };
}

/// Uneven, non-planar data: a conical helix with a kink.
std::vector<Vec3> testData()
{
  std::vector<Vec3> points;
  for (int i = 0; i < 14; ++i)
  {
    const double t = 0.55 * i + 0.03 * i * i;
    points.emplace_back((1 + 0.2 * t) * std::cos(t), (1 + 0.2 * t) * std::sin(t), 0.4 * t);
  }
  points[7].z() += 0.3;
  return points;
}

struct Fitted
{
  FittedPolyline Fit;
  SampledCurve Sampled;
};

Fitted fit(const Family& family, const std::vector<Vec3>& points)
{
  FitOptions options;
  options.Closed = family.Closed;
  options.Sampling.Subdivisions = 7;
  Fitted result{ fitPolyline(points, options, family.Build), {} };
  result.Sampled = sampleFit(result.Fit);
  return result;
}

double size(const std::vector<Vec3>& points)
{
  return boundingBoxDiagonal(points);
}

/**
 * How much rounding of the derivatives, 1e5 eps relative, can move the
 * torsion at sample k: that times |s'| |s''| |s'''| / |s' x s''|^2, in data
 * units. It matters where high degrees make |s'''| >> |s''|: at a knot of
 * degree 200 of the variable degree spline, 6e3 eps was measured, 5e4 eps
 * at degree 640.
 */
double torsionRounding(const Fitted& fitted, int k)
{
  const Derivatives& d = fitted.Sampled.Samples.Values[k];
  const double area = d[1].cross(d[2]).squaredNorm();
  const double relative = 1e5 * 2.220446049250313e-16;
  const double bound = relative * d[1].norm() * d[2].norm() * d[3].norm() / area;
  return area > 0.0 ? bound / fitted.Fit.Scale : 0.0;
}

/**
 * Where the curve is all but straight, a radius of curvature beyond 1e3 times
 * the data's size (a natural end next to a knot of degree 40: curvature
 * 1e-10 to 1e-6 of the size's inverse), the torsion is a ratio of rounding
 * errors, 50% apart between equivalent inputs: it has no value to compare.
 */
bool nearlyStraight(const FrenetFrame& frame, const std::vector<Vec3>& data)
{
  return frame.Curvature * boundingBoxDiagonal(data) < 1e-3;
}

class Invariance : public ::testing::TestWithParam<Family>
{
};

/// Positions map by `map`, curvature and torsion scale by 1/scale, torsion's sign by `handedness`.
template <typename Map>
void expectTransformed(const Family& family, Map map, double scale, double handedness)
{
  const std::vector<Vec3> data = testData();
  std::vector<Vec3> moved;
  for (const Vec3& p : data)
  {
    moved.push_back(map(p));
  }
  const Fitted a = fit(family, data);
  const Fitted b = fit(family, moved);
  ASSERT_EQ(a.Sampled.Samples.size(), b.Sampled.Samples.size());
  const double extent = size(moved);
  // Curvature that vanishes is compared with rounding, 1e-9 / size: ends made
  // natural through a solve keep its rounding (condition x eps), and straight
  // pieces a shape-preserving curve puts on collinear data carry curvature of
  // rounding size (up to 3e-10 / size measured on the qqr curves).
  const double zeroCurvature = 1e-9 / size(data);
  for (int k = 0; k < a.Sampled.Samples.size(); ++k)
  {
    const Vec3 expected = map(a.Sampled.Samples.Values[k][0]);
    EXPECT_LT((b.Sampled.Samples.Values[k][0] - expected).norm(), 1e-12 * extent) << k;
    const FrenetFrame& fa = a.Sampled.Frames[k];
    const FrenetFrame& fb = b.Sampled.Frames[k];
    EXPECT_NEAR(fb.Curvature * scale, fa.Curvature, 1e-10 * fa.Curvature + zeroCurvature) << k;
    if (!nearlyStraight(fa, data))
    {
      EXPECT_NEAR(fb.Torsion * scale, handedness * fa.Torsion,
        1e-9 * (1 + std::abs(fa.Torsion)) + torsionRounding(a, k))
        << k;
    }
  }
  EXPECT_EQ(a.Fit.Audit.violations(), b.Fit.Audit.violations());
}
} // namespace

TEST_P(Invariance, RotationAndTranslation)
{
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  const Vec3 shift(3.5, -120.25, 7.0);
  expectTransformed(GetParam(), [&](const Vec3& p) -> Vec3 { return rotation * p + shift; }, 1.0, 1.0);
}

TEST_P(Invariance, UniformScaling)
{
  for (const double s : { 1e-6, 0.37, 1e6 })
  {
    SCOPED_TRACE(s);
    expectTransformed(GetParam(), [&](const Vec3& p) -> Vec3 { return s * p; }, s, 1.0);
  }
}

TEST_P(Invariance, MirrorFlipsTorsionOnly)
{
  expectTransformed(
    GetParam(), [](const Vec3& p) -> Vec3 { return Vec3(p.x(), -p.y(), p.z()); }, 1.0, -1.0);
}

TEST_P(Invariance, ReversalTracesTheSameCurveBackwards)
{
  const Family& family = GetParam();
  std::vector<Vec3> data = testData();
  const Fitted forward = fit(family, data);
  std::reverse(data.begin(), data.end());
  const Fitted backward = fit(family, data);
  const auto& f = forward.Sampled;
  const auto& b = backward.Sampled;
  ASSERT_EQ(f.Samples.size(), b.Samples.size());
  EXPECT_EQ(forward.Fit.Audit.violations(), backward.Fit.Audit.violations());
  const int n = f.Samples.size();
  const double extent = size(data);
  for (int k = 0; k < n; ++k)
  {
    // Reversed, a closed line starts at its last point: the samples shift by a span.
    const int r = family.Closed ? ((n - 7 - k) % n + n) % n : n - 1 - k;
    EXPECT_LT((b.Samples.Values[r][0] - f.Samples.Values[k][0]).norm(), 1e-12 * extent) << k;
    EXPECT_NEAR(b.Frames[r].Curvature, f.Frames[k].Curvature,
      1e-9 * f.Frames[k].Curvature + 1e-9 / extent)
      << k;
    // At a knot the torsion is one-sided (the third derivative of a C2 curve
    // jumps there): the sample takes the span after it, which reversal makes the
    // span before it. Between knots it must agree.
    if (k % 7 != 0 && !nearlyStraight(f.Frames[k], data))
    {
      EXPECT_NEAR(
        b.Frames[r].Torsion, f.Frames[k].Torsion, 1e-8 * (1 + std::abs(f.Frames[k].Torsion)))
        << k;
    }
    EXPECT_LT((b.Frames[r].Tangent + f.Frames[k].Tangent).norm(), 1e-10) << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Families, Invariance, ::testing::ValuesIn(Families()),
  [](const ::testing::TestParamInfo<Family>& info) { return info.param.Name; });

TEST(InvarianceLimits, CubicBendsAStraightRunBetweenCurvedData)
{
  // Four collinear points between curved neighbours: a C2 cubic cannot stay
  // straight there (it would need zero second derivative at both ends of the
  // run). Shape-preserving families must; the audit reports the cubic's bend.
  const std::vector<Vec3> points = { Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0),
    Vec3(4, 0, 0), Vec3(5, 1, 0) };
  const FittedPolyline cubic = fitPolyline(points, FitOptions{}, cubicBuilder());
  EXPECT_GT(cubic.Audit.Failures[static_cast<int>(ShapeCriterion::Collinearity)], 0);
}

TEST(AuditInvariance, ReversalKeepsTheAuditOfNoisyLines)
{
  // The same curve backwards must fail the same criteria on the same spans.
  // Where a point turns partly with both neighbours (in 3D), or against
  // both, the inflection test took the neighbour to compare it with by the
  // data's order: on a noisy 3D staircase of 40 points the cubic reported
  // 57 violations forward and 52 backwards; 41 of these 120 audits differed.
  GeneralizedCubicOptions generalized;
  generalized.Automatic = false;
  QuinticFitOptions quintic;
  quintic.Automatic = false;
  VariableDegreeOptions degree;
  degree.Automatic = false;
  QQROptions qqrOptions;
  qqrOptions.Automatic = false;
  const std::vector<std::pair<std::string, CurveBuilder>> fixed = { { "cubic", cubicBuilder() },
    { "generalized cubic", generalizedCubicBuilder(generalized) },
    { "tension quintic", tensionQuinticBuilder(quintic) },
    { "variable degree", variableDegreeBuilder(degree) }, { "qqr", qqrBuilder(qqrOptions) } };
  std::vector<std::vector<Vec3>> lines;
  for (unsigned seed = 1; seed <= 8; ++seed)
  {
    lines.push_back(withNoise(staircase(8, 5, seed), 0.01, seed + 100));
    lines.push_back(randomWalk(60, seed));
    lines.push_back(noisyTrefoilPoints(100, 0.01, seed));
  }
  int differing = 0;
  for (const auto& [name, builder] : fixed)
  {
    for (size_t l = 0; l < lines.size(); ++l)
    {
      std::vector<Vec3> backwards = lines[l];
      std::reverse(backwards.begin(), backwards.end());
      const ShapeAudit forward = fitPolyline(lines[l], FitOptions{}, builder).Audit;
      const ShapeAudit reversed = fitPolyline(backwards, FitOptions{}, builder).Audit;
      ASSERT_EQ(forward.SpanMask.size(), reversed.SpanMask.size());
      std::vector<unsigned> mirrored(reversed.SpanMask.rbegin(), reversed.SpanMask.rend());
      differing += forward.SpanMask != mirrored;
      EXPECT_EQ(forward.violations(), reversed.violations()) << name << ", line " << l;
      EXPECT_EQ(forward.SpanMask, mirrored) << name << ", line " << l;
    }
  }
  std::printf("%d of %zu audits differ backwards\n", differing, fixed.size() * lines.size());
}
