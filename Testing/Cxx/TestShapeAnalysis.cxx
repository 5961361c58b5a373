// Discrete shape of polylines and the Definition 1 audit (Costantini & Manni (VDPS)).
#include "MathTestUtilities.h"

#include "ShapeAnalysis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>

using namespace shapesplines;
using namespace shapesplines::test;

namespace
{
int failures(const ShapeAudit& audit, ShapeCriterion criterion)
{
  return audit.Failures[static_cast<int>(criterion)];
}

/// Audit samples of a fitted curve, frames changed by `edit`.
template <typename Edit>
std::vector<AuditSample> editedSamples(const FittedPolyline& fit, Edit edit)
{
  const SampledCurve sampled = sampleFit(fit);
  std::vector<AuditSample> samples(sampled.Samples.size());
  for (int k = 0; k < sampled.Samples.size(); ++k)
  {
    samples[k].Span = sampled.Samples.Span[k];
    samples[k].Frame = sampled.Frames[k];
    edit(samples[k].Frame);
  }
  markKnots(samples, fit.Data.Closed);
  return samples;
}

/// TorsionSignOnSpan failures of an open fit whose torsion is made
/// torsion(u, the curve's torsion), u in spans from the first point.
int torsionFailures(const FittedPolyline& fit, const std::function<double(double, double)>& torsion)
{
  const SampledCurve sampled = sampleFit(fit);
  std::vector<AuditSample> samples(sampled.Samples.size());
  for (int k = 0; k < sampled.Samples.size(); ++k)
  {
    samples[k].Span = sampled.Samples.Span[k];
    samples[k].Frame = sampled.Frames[k];
    samples[k].Frame.Torsion =
      torsion(samples[k].Span + sampled.Samples.SpanFraction[k], sampled.Frames[k].Torsion);
  }
  markKnots(samples, false);
  return failures(auditShape(fit.Data, fit.Shape, samples), ShapeCriterion::TorsionSignOnSpan);
}

/// torsionFailures of a torsion of u alone (u in spans from the first point).
int failuresWithTorsion(const FittedPolyline& fit, const std::function<double(double)>& torsion)
{
  return torsionFailures(fit, [&](double u, double) { return torsion(u); });
}

/// The torsion's slope of crossingAt: steep next to the discrete torsion's
/// steps on quarticTwist (about 3 a span), which within two spans of a
/// reversal the audit allows a wrong sign of half of.
constexpr double CrossingSlope = 40.0;

/// A torsion that changes sign, from negative to positive, at u = where.
std::function<double(double)> crossingAt(double where)
{
  return [where](double u) { return CrossingSlope * (u - where); };
}

/// The largest step of the discrete torsion between neighbouring segments
/// among segments first..last.
double largestTorsionStep(const DiscreteShape& shape, int first, int last)
{
  double step = 0.0;
  for (int k = first + 1; k <= last; ++k)
  {
    step = std::max(step, std::abs(shape.Torsion[k] - shape.Torsion[k - 1]));
  }
  return step;
}

/// (t, t^2, t^4) at t = first + 0.25 i, i = 0..8: its torsion
/// 48 t / |r' x r''|^2 changes sign at t = 0.
std::vector<Vec3> quarticTwist(double first)
{
  std::vector<Vec3> points;
  for (int i = 0; i <= 8; ++i)
  {
    const double t = first + 0.25 * i;
    points.emplace_back(t, t * t, t * t * t * t);
  }
  return points;
}

/// (t, t^2, t^5) at t = -1.125 + 0.25 i, i = 0..9: its torsion
/// 120 t^2 / |r' x r''|^2 touches zero in the middle of segment 4 and keeps its sign.
std::vector<Vec3> quinticTouch()
{
  std::vector<Vec3> points;
  for (int i = 0; i <= 9; ++i)
  {
    const double t = -1.125 + 0.25 * i;
    points.emplace_back(t, t * t, std::pow(t, 5));
  }
  return points;
}
} // namespace

TEST(DiscreteShape, HelixHasPositiveTorsionAndConvergingCurvature)
{
  for (const int perTurn : { 8, 32 })
  {
    const CleanPolyline line = cleanPolyline(helix(perTurn, 2), false);
    const DiscreteShape shape = discreteShape(line);
    const int n = static_cast<int>(line.Points.size());
    for (int i = 1; i < n - 2; ++i)
    {
      EXPECT_GT(shape.Torsion[i], 0.0);
      EXPECT_TRUE(shape.Twisted[i]);
    }
    EXPECT_EQ(shape.Torsion.front(), 0.0); // undefined at open ends
    // Menger curvature of the helix samples tends to 0.4 (second order).
    const double error = std::abs(shape.Curvature[n / 2] - 0.4) / 0.4;
    EXPECT_LT(error, perTurn == 8 ? 0.1 : 0.005);
  }
}

namespace
{
/// randomlySpacedHelix() tilted out of the axes (a circle's plane too).
std::vector<Vec3> tiltedRandomlySpacedHelix(int count, double b, unsigned seed)
{
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).matrix();
  std::vector<Vec3> points = randomlySpacedHelix(count, b, seed);
  for (Vec3& p : points)
  {
    p = tilt * p;
  }
  return points;
}
} // namespace

TEST(DiscreteShape, CloseSamplesOfAHelixAreNotCoplanar)
{
  // Four close points of a twisting curve have a triple product third order
  // in their spacing, below epsilon_1, while the planes at their ends turn by
  // more than epsilon_2: the audit demanded a planar span there, which no
  // curve close to the helix has (an interpolating cubic failed 101 of such
  // spans, 400 points). Points of a plane stay coplanar however close.
  const CleanPolyline twisting = cleanPolyline(tiltedRandomlySpacedHelix(400, 0.25, 3), false);
  const DiscreteShape shape = discreteShape(twisting);
  const ShapeTolerances tolerances;
  int tinyTripleProducts = 0;
  for (int i = 1; i < twisting.numberOfSpans() - 1; ++i)
  {
    const Vec3 a = twisting.segment(i - 1).normalized();
    const Vec3 b = twisting.segment(i).normalized();
    const Vec3 c = twisting.segment(i + 1).normalized();
    const double endPlanesTurn = a.cross(b).normalized().cross(b.cross(c).normalized()).norm();
    if (endPlanesTurn > 2.0 * tolerances.Curve)
    {
      tinyTripleProducts += std::abs(a.dot(b.cross(c))) <= tolerances.Data;
      EXPECT_FALSE(shape.Coplanar[i]) << i;
      EXPECT_GT(shape.Torsion[i], 0.0) << i;
    }
  }
  EXPECT_GT(tinyTripleProducts, 50); // the case above occurs in these data

  const CleanPolyline planar = cleanPolyline(tiltedRandomlySpacedHelix(400, 0.0, 3), false);
  const DiscreteShape flat = discreteShape(planar);
  for (int i = 1; i < planar.numberOfSpans() - 1; ++i)
  {
    EXPECT_TRUE(flat.Coplanar[i]) << i;
  }
}

TEST(DiscreteShape, ALoneCoplanarSegmentBetweenOppositeTwistsIsATorsionSignChange)
{
  // Points evenly spaced about a zero of the torsion, r(t) = (t, t^2 / 2,
  // t^4 / 4) at t = +-1/2, +-3/2, +-5/2: the middle four are coplanar
  // (mirror images), the segments on either side twist opposite ways. No
  // curve that twists on both sides is planar along the middle span: it is
  // not coplanar, nor twisted (no criterion). Two such segments in a row
  // stay coplanar (a planar stretch), as does a lone one between segments
  // twisted the same way.
  auto onCurve = [](double t) { return Vec3(t, t * t / 2.0, t * t * t * t / 4.0); };
  std::vector<Vec3> points;
  for (const double t : { -2.5, -1.5, -0.5, 0.5, 1.5, 2.5 })
  {
    points.push_back(onCurve(t));
  }
  const DiscreteShape crossing = discreteShape(cleanPolyline(points, false));
  EXPECT_LT(crossing.Torsion[1], 0.0);
  EXPECT_FALSE(crossing.Coplanar[2]);
  EXPECT_FALSE(crossing.Twisted[2]);
  EXPECT_GT(crossing.Torsion[3], 0.0);

  // The last point moved into the middle four's plane: a planar stretch of
  // two segments; mirrored through that plane: both sides twist one way.
  const Vec3 normal = (points[2] - points[1]).cross(points[3] - points[2]).normalized();
  const double offPlane = (points[5] - points[1]).dot(normal);
  std::vector<Vec3> planarStretch = points, sameWay = points;
  planarStretch[5] -= offPlane * normal;
  sameWay[5] -= 2.0 * offPlane * normal;
  const DiscreteShape stretch = discreteShape(cleanPolyline(planarStretch, false));
  EXPECT_TRUE(stretch.Coplanar[2]);
  EXPECT_TRUE(stretch.Coplanar[3]);
  const DiscreteShape touching = discreteShape(cleanPolyline(sameWay, false));
  ASSERT_GT(touching.Torsion[1] * touching.Torsion[3], 0.0);
  EXPECT_TRUE(touching.Coplanar[2]);
}

TEST(DiscreteShape, ALoneCollinearPointBetweenOppositeTurnsIsAnInflection)
{
  // y = x^3 at x = -1.5 ... 1.5: the points at -0.5, 0, 0.5 are collinear
  // (odd symmetry) and the curve turns opposite ways on either side. No
  // curve that bends on both sides is straight on the two spans around 0:
  // (i) does not apply there. Two collinear points in a row (a straight
  // run), or one between turns the same way (a square's side with its
  // midpoint), stay collinear.
  std::vector<Vec3> cubic;
  for (int k = -3; k <= 3; ++k)
  {
    const double x = 0.5 * k;
    cubic.emplace_back(x, x * x * x, 0.0);
  }
  const DiscreteShape inflection = discreteShape(cleanPolyline(cubic, false));
  EXPECT_TRUE(inflection.Convex[2] && inflection.Convex[4]);
  EXPECT_LT(inflection.Binormal[2].dot(inflection.Binormal[4]), 0.0);
  EXPECT_FALSE(inflection.Collinear[3]);
  EXPECT_FALSE(inflection.Convex[3]);

  std::vector<Vec3> run = cubic;
  run.insert(run.begin() + 4, Vec3(0.25, 0.0625, 0.0)); // on the line through -0.5, 0, 0.5
  const DiscreteShape straight = discreteShape(cleanPolyline(run, false));
  EXPECT_TRUE(straight.Collinear[3]);
  EXPECT_TRUE(straight.Collinear[4]);

  const std::vector<Vec3> square = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0),
    Vec3(2, 2, 0), Vec3(1, 2, 0), Vec3(0, 2, 0), Vec3(0, 1, 0) };
  const DiscreteShape sides = discreteShape(cleanPolyline(square, true));
  for (const int midpoint : { 1, 3, 5, 7 })
  {
    EXPECT_TRUE(sides.Collinear[midpoint]) << midpoint;
  }
}

TEST(DiscreteShape, APointNextToAnInflectionHasNoConvexityToKeep)
{
  // y = x^3 at x = -1, -0.5, 0.05, 0.5, 1, 1.5: the point at 0.05 turns the
  // way of the points after it, by far less than the point before it turns
  // the other way; the curve's inflection is that close to it, and a spline
  // may put it on either side. Points that turn well away from an
  // inflection (at 0.5, 1) keep their convexity.
  std::vector<Vec3> points;
  for (const double x : { -1.0, -0.5, 0.05, 0.5, 1.0, 1.5 })
  {
    points.emplace_back(x, x * x * x, 0.0);
  }
  const DiscreteShape shape = discreteShape(cleanPolyline(points, false));
  ASSERT_GT(shape.Binormal[2].dot(shape.Binormal[3]), 0.0);
  ASSERT_LT(shape.Binormal[1].dot(shape.Binormal[2]), 0.0);
  EXPECT_LT(2.0 * shape.Curvature[2], shape.Curvature[1]);
  EXPECT_FALSE(shape.Convex[2]);
  EXPECT_FALSE(shape.Collinear[2]);
  EXPECT_TRUE(shape.Convex[1]);
  EXPECT_TRUE(shape.Convex[3]);
  EXPECT_TRUE(shape.Convex[4]);
}

TEST(DiscreteShape, TurnsWithinTheCoordinatesRoundingAreNoShape)
{
  // A helix with one point doubled at 1e-6 of its size, off in a direction
  // of its own: what float coordinates (7 digits) make of a repeated point.
  std::vector<Vec3> points = helix(16, 2);
  const int twin = 10;
  points.insert(points.begin() + twin + 1, points[twin] + 1e-6 * Vec3(0.3, -0.5, 0.8));
  const CleanPolyline line = cleanPolyline(points, false);
  const double rounding = 1e-7; // float coordinates of this helix, relative to its size
  const DiscreteShape exact = discreteShape(line);
  const DiscreteShape rounded = discreteShape(line, {}, {}, rounding);
  for (const int i : { twin, twin + 1 })
  {
    EXPECT_TRUE(exact.Convex[i]) << i;
    EXPECT_FALSE(rounded.Convex[i]) << i;
  }
  EXPECT_TRUE(exact.Twisted[twin]);
  EXPECT_FALSE(rounded.Twisted[twin]);
  for (const int i : { 3, 20 })
  {
    EXPECT_TRUE(rounded.Convex[i]) << i;
    EXPECT_TRUE(rounded.Twisted[i]) << i;
  }
}

TEST(DiscreteShape, TurnsAndTwistsTheDecimalsRoundingCanMakeAreNoShape)
{
  // A straight run in a tilted direction and a planar zigzag in a tilted
  // plane (a protein's beta strand), written with three decimals: their
  // points turn and twist either way by their rounding, which taken as exact
  // are convex points and twisted segments. The most rounding to 1e-3 can
  // move a point is sqrt(3) / 2 1e-3: within that bound nothing counts, and
  // the zigzag's own turns still do.
  const double step = 1e-3;
  const double moved = 0.5 * std::sqrt(3.0) * step;
  const Vec3 along = Vec3(1.0, 2.0, 2.0) / 3.0, across = Vec3(2.0, 1.0, -2.0) / 3.0;
  std::vector<Vec3> run, zigzag;
  for (int i = 0; i < 12; ++i)
  {
    const Vec3 p = Vec3(0.1, 0.2, 0.3) + 0.37 * i * along;
    run.push_back((p / step).array().round().matrix() * step);
    const Vec3 q = p + (i % 2 ? 0.15 : -0.15) * across;
    zigzag.push_back((q / step).array().round().matrix() * step);
  }
  const CleanPolyline straight = cleanPolyline(run, false);
  const DiscreteShape exactRun = discreteShape(straight);
  const DiscreteShape roundedRun = discreteShape(straight, {}, {}, 0.0, Vec3::Constant(step));
  EXPECT_GE(std::count(exactRun.Convex.begin(), exactRun.Convex.end(), 1), 5);
  EXPECT_EQ(std::count(roundedRun.Convex.begin(), roundedRun.Convex.end(), 1), 0);
  const CleanPolyline strand = cleanPolyline(zigzag, false);
  const DiscreteShape exactStrand = discreteShape(strand);
  const DiscreteShape roundedStrand = discreteShape(strand, {}, {}, 0.0, Vec3::Constant(step));
  EXPECT_GE(std::count(exactStrand.Twisted.begin(), exactStrand.Twisted.end(), 1), 6);
  EXPECT_EQ(std::count(roundedStrand.Twisted.begin(), roundedStrand.Twisted.end(), 1), 0);
  EXPECT_EQ(roundedStrand.Convex, exactStrand.Convex);
  EXPECT_EQ(std::count(roundedStrand.Convex.begin(), roundedStrand.Convex.end(), 1), 10);

  // A turn the rounding cannot make counts: at point 1 of (0, 0, 0),
  // (1, 0, 0), (2, y, 0) rounding turns the sine by at most 2 moved (1 + 1 /
  // |segment 1|), about 3.5e-3; the bound is the line between 0.9 and 1.1 of it.
  for (const double factor : { 0.9, 1.1 })
  {
    const double bound = 2.0 * moved * 2.0;
    const double y = factor * bound; // sine of the turn, to 1e-5 of itself
    const CleanPolyline turn =
      cleanPolyline({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, y, 0) }, false);
    EXPECT_EQ(discreteShape(turn, {}, {}, 0.0, Vec3::Constant(step)).Convex[1], factor > 1.0) << factor;
    EXPECT_TRUE(discreteShape(turn).Convex[1]) << factor;
  }

  // Straight or planar within epsilon_1 by the rounding's chance is no
  // straight run and no plane either (no criterion); exactly, it still is
  // (points 3, 6 and 9 of the run above lie on its decimals' lattice line).
  const std::vector<Vec3> bent{ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 5e-7, 0), Vec3(3, 1, 0),
    Vec3(4, 1.5, 3e-7) };
  const DiscreteShape exactBent = discreteShape(cleanPolyline(bent, false));
  const DiscreteShape roundedBent = discreteShape(cleanPolyline(bent, false), {}, {}, 0.0, Vec3::Constant(step));
  EXPECT_TRUE(exactBent.Collinear[1]);
  EXPECT_FALSE(roundedBent.Collinear[1] || roundedBent.Convex[1]);
  EXPECT_TRUE(exactBent.Coplanar[2]);
  EXPECT_FALSE(roundedBent.Coplanar[2] || roundedBent.Twisted[2]);
  for (const int i : { 3, 6, 9 })
  {
    EXPECT_TRUE(roundedRun.Collinear[i]) << i;
  }
  // Float rounding of short segments far from the origin makes such planes
  // by chance too (the aorta's floats: a triple product of 1.3e-7 where
  // rounding moves it by 1e-4); its straight runs are not questioned (float
  // tool paths off the axes would lose theirs).
  const DiscreteShape floatBent = discreteShape(cleanPolyline(bent, false), {}, {}, moved);
  EXPECT_FALSE(floatBent.Coplanar[2] || floatBent.Twisted[2]);
  EXPECT_TRUE(floatBent.Collinear[1]);
}

TEST(DiscreteShape, PlanesTheRoundingMakesAreNoShape)
{
  // A smooth 3D trajectory (coordinates 100-400, segments of about 0.5)
  // written with six significant digits (a step of 1e-3): one segment in
  // twenty has its four points exactly coplanar, where a coordinate rounds
  // to one value around its extremum or the second differences round alike.
  // Taken as planes, they asked every spline for a planar span amid a
  // twisting curve. A designed z-level (a tool path's), rounded alike, holds
  // more points than rounding keeps in one plane: a plane.
  const double step = 1e-3;
  std::vector<Vec3> trajectory, toolPath;
  constexpr int Points = 600;
  for (int i = 0; i < Points; ++i)
  {
    const double s = static_cast<double>(i) / (Points - 1);
    Vec3 p(250.0 + 60.0 * std::sin(Pi * s + 0.3) + 20.0 * std::sin(3.0 * Pi * s),
      200.0 + 70.0 * std::sin(2.0 * Pi * s + 1.0), 180.0 + 50.0 * std::cos(1.5 * Pi * s));
    p = (p / step).array().round().matrix() * step;
    trajectory.push_back(p);
    if (i >= 200 && i < 240)
    {
      p.z() = toolPath[199].z(); // 40 points on one z-level
    }
    toolPath.push_back(p);
  }
  const CleanPolyline data = cleanPolyline(trajectory, false);
  int exactlyPlanar = 0;
  for (int i = 1; i + 1 < data.numberOfSpans(); ++i)
  {
    const Vec3 a = data.segment(i - 1).normalized(), b = data.segment(i).normalized(),
               c = data.segment(i + 1).normalized();
    exactlyPlanar += std::abs(a.dot(b.cross(c))) < 1e-14;
  }
  EXPECT_GT(exactlyPlanar, 10);
  const DiscreteShape rounded = discreteShape(data, {}, {}, 0.0, Vec3::Constant(step));
  EXPECT_EQ(std::count(rounded.Coplanar.begin(), rounded.Coplanar.end(), 1), 0);
  // Taken as exact, they are planes.
  const DiscreteShape exact = discreteShape(data);
  EXPECT_GE(std::count(exact.Coplanar.begin(), exact.Coplanar.end(), 1), exactlyPlanar / 2);
  const DiscreteShape designed = discreteShape(cleanPolyline(toolPath, false), {}, {}, 0.0, Vec3::Constant(step));
  for (int i = 204; i < 238; ++i) // away from the step onto the level
  {
    EXPECT_TRUE(designed.Coplanar[i]) << i;
  }
}

TEST(DiscreteShape, MirrorFlipsDiscreteTorsion)
{
  std::vector<Vec3> points = helix(8, 2);
  const DiscreteShape shape = discreteShape(cleanPolyline(points, false));
  for (Vec3& p : points)
  {
    p.z() = -p.z();
  }
  const DiscreteShape mirrored = discreteShape(cleanPolyline(points, false));
  for (size_t i = 0; i < shape.Torsion.size(); ++i)
  {
    EXPECT_NEAR(mirrored.Torsion[i], -shape.Torsion[i], 1e-12);
  }
}

TEST(DiscreteShape, AkimaFlatRunIsCollinearAndDataArePlanar)
{
  const DiscreteShape shape = discreteShape(cleanPolyline(akima(), false));
  const std::vector<char> collinear = { 0, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0 };
  EXPECT_EQ(shape.Collinear, collinear);
  for (size_t i = 0; i < shape.Twisted.size(); ++i)
  {
    EXPECT_FALSE(shape.Twisted[i]);
  }
  // Turning left at x = 8, 9, 11 and 14, right at x = 12 (index 8).
  for (const int i : { 5, 6, 7, 9 })
  {
    EXPECT_GT(shape.Binormal[i].z(), 0.0) << i;
  }
  EXPECT_LT(shape.Binormal[8].z(), 0.0);
}

TEST(ShapeAudit, CubicBreaksTheAkimaShape)
{
  const FittedPolyline fit = fitPolyline(akima(), FitOptions{}, cubicBuilder());
  std::printf("Akima, not-a-knot cubic: %d violations (collinearity %d, convexity at knots %d, "
              "on spans %d)\n",
    fit.Audit.violations(), failures(fit.Audit, ShapeCriterion::Collinearity),
    failures(fit.Audit, ShapeCriterion::ConvexityAtKnot),
    failures(fit.Audit, ShapeCriterion::ConvexityOnSpan));
  EXPECT_GT(failures(fit.Audit, ShapeCriterion::Collinearity), 0);
  EXPECT_FALSE(fit.Audit.preserving());
  // Wiggles on the flat run: spans 0..4 are marked.
  EXPECT_NE(fit.Audit.SpanMask[2] & criterionBit(ShapeCriterion::Collinearity), 0u);
  EXPECT_EQ(failures(fit.Audit, ShapeCriterion::Coplanarity), 0);
}

TEST(ShapeAudit, CubicKeepsTheHelixShape)
{
  const FittedPolyline fit = fitPolyline(helix(8, 3), FitOptions{}, cubicBuilder());
  EXPECT_TRUE(fit.Audit.preserving()) << fit.Audit.violations() << " violations";
}

TEST(ShapeAudit, EachCriterionCanFail)
{
  const FittedPolyline helixFit = fitPolyline(helix(8, 3), FitOptions{}, cubicBuilder());
  // Wrong-handed torsion: torsion sign at knots and on spans.
  ShapeAudit audit = auditShape(helixFit.Data, helixFit.Shape,
    editedSamples(helixFit, [](FrenetFrame& f) { f.Torsion = -f.Torsion; }));
  EXPECT_GT(failures(audit, ShapeCriterion::TorsionSignAtKnot), 0);
  EXPECT_EQ(failures(audit, ShapeCriterion::TorsionSignOnSpan), helixFit.Data.numberOfSpans() - 2);
  // Curving the wrong way: convexity at knots and on spans.
  audit = auditShape(helixFit.Data, helixFit.Shape,
    editedSamples(helixFit, [](FrenetFrame& f) { f.Binormal = -f.Binormal; }));
  EXPECT_GT(failures(audit, ShapeCriterion::ConvexityAtKnot), 0);
  EXPECT_GT(failures(audit, ShapeCriterion::ConvexityOnSpan), 0);

  // Planar data, osculating plane tilted by 0.1 rad: coplanarity.
  const FittedPolyline planarFit = fitPolyline(akima(), FitOptions{}, cubicBuilder());
  audit = auditShape(planarFit.Data, planarFit.Shape, editedSamples(planarFit, [](FrenetFrame& f) {
    f.Binormal = (f.Binormal + Vec3(0.1, 0, 0)).normalized();
  }));
  EXPECT_GT(failures(audit, ShapeCriterion::Coplanarity), 0);
}

TEST(ShapeAudit, VanishingValuesAreNotSignChanges)
{
  // The data polygon itself (zero curvature and torsion everywhere) breaks no sign condition.
  const FittedPolyline fit = fitPolyline(helix(8, 2), FitOptions{}, cubicBuilder());
  const ShapeAudit audit = auditShape(fit.Data, fit.Shape, editedSamples(fit, [](FrenetFrame& f) {
    f.Curvature = 0;
    f.Torsion = 0;
  }));
  EXPECT_TRUE(audit.preserving());
}

TEST(ShapeAudit, TorsionMayChangeSignOnceAroundTheKnotWhereTheDataDo)
{
  // The torsion changes sign at point 4.
  const FittedPolyline fit = fitPolyline(quarticTwist(-1.0), FitOptions{}, cubicBuilder());
  const DiscreteShape& shape = fit.Shape;
  const int knot = 4;
  for (int j = knot - 2; j <= knot + 1; ++j)
  {
    ASSERT_TRUE(shape.Twisted[j]) << j;
    ASSERT_EQ(shape.Torsion[j] > 0, j >= knot) << j; // a single change, at the knot
  }
  EXPECT_EQ(failuresWithTorsion(fit, crossingAt(knot)), 0);       // Definition 1's own case
  EXPECT_EQ(failuresWithTorsion(fit, crossingAt(knot - 0.6)), 0); // in the span before the knot
  EXPECT_EQ(failuresWithTorsion(fit, crossingAt(knot + 0.6)), 0); // in the span after it
  // A span too early: wrong after the crossing, and the whole span before the knot.
  EXPECT_EQ(failuresWithTorsion(fit, crossingAt(knot - 1.4)), 2);
  EXPECT_EQ(failuresWithTorsion(fit, crossingAt(knot + 1.4)), 2);
  // Right at both ends of the span before the knot, wrong in its middle: three changes.
  const auto backAndForth = [](double u) {
    return u > 3.3 && u < 3.5 ? CrossingSlope : CrossingSlope * (u - knot);
  };
  EXPECT_EQ(failuresWithTorsion(fit, backAndForth), 1);
}

TEST(ShapeAudit, TorsionWaveringAboutItsZeroIsNoSignChange)
{
  // Near the torsion's zero a converging curve's torsion wavers about it by
  // its error, of the order of the discrete torsion's steps from segment to
  // segment: within two spans of the knot where the data reverse, a wrong
  // sign counts beyond half the largest step there, not before.
  const FittedPolyline fit = fitPolyline(quarticTwist(-1.0), FitOptions{}, cubicBuilder());
  const int knot = 4;
  const double step = largestTorsionStep(fit.Shape, knot - 2, knot + 1);
  ASSERT_GT(step, 0.0);
  auto wavering = [&](double size) {
    return [=](double u) { return u > 2.3 && u < 2.7 ? size * step : CrossingSlope * (u - knot); };
  };
  EXPECT_EQ(failuresWithTorsion(fit, wavering(0.4)), 0); // wrong, but within its error
  EXPECT_EQ(failuresWithTorsion(fit, wavering(0.6)), 1); // beyond it: span 2
  EXPECT_EQ(failuresWithTorsion(fit, wavering(-0.6)), 0); // the right sign
}

TEST(ShapeAudit, TorsionTouchingZeroMayWaverThere)
{
  // Where a segment twists its neighbours' way by under a third of the less
  // twisted one, the torsion nears zero without crossing it (and on noisy
  // points, where a segment's four points happen to lie nearly in a plane):
  // a converging curve's torsion wavers about zero by its error there too,
  // so a wrong sign on that span counts beyond half the step down to its
  // discrete torsion, not before; on the other spans it counts as ever.
  const FittedPolyline fit = fitPolyline(quinticTouch(), FitOptions{}, cubicBuilder());
  const DiscreteShape& shape = fit.Shape;
  std::vector<int> dips;
  for (int j = 1; j + 1 < fit.Data.numberOfSpans(); ++j)
  {
    const double weaker = std::min(std::abs(shape.Torsion[j - 1]), std::abs(shape.Torsion[j + 1]));
    if (shape.Twisted[j - 1] && shape.Twisted[j] && shape.Twisted[j + 1] &&
      shape.Torsion[j - 1] * shape.Torsion[j] > 0 && shape.Torsion[j] * shape.Torsion[j + 1] > 0 &&
      3.0 * std::abs(shape.Torsion[j]) < weaker)
    {
      dips.push_back(j);
    }
  }
  ASSERT_EQ(dips.size(), 1u);
  const int dip = dips[0];
  const double sign = shape.Torsion[dip] > 0 ? 1.0 : -1.0;
  const double step = std::min(std::abs(shape.Torsion[dip - 1]), std::abs(shape.Torsion[dip + 1])) -
    std::abs(shape.Torsion[dip]);
  auto wrongOn = [&](int span, double size) {
    return [=](double u) { return u > span + 0.3 && u < span + 0.7 ? -sign * size * step : sign; };
  };
  EXPECT_EQ(failuresWithTorsion(fit, wrongOn(dip, 0.4)), 0); // within its error
  EXPECT_EQ(failuresWithTorsion(fit, wrongOn(dip, 0.6)), 1); // beyond it
  for (const int span : { dip - 2, dip + 2 })
  {
    EXPECT_EQ(failuresWithTorsion(fit, wrongOn(span, 0.4)), 1) << span; // no dip there
  }
}

TEST(ShapeAudit, TorsionMayChangeSignWithinASpanOfWhereTheDataPutIt)
{
  // The torsion's zero a tenth of a span before the middle of span 4: the
  // segments on either side twist opposite ways and span 4's own discrete
  // torsion is small. The sign change may happen anywhere from span 3 to
  // span 5 (from the knots), not only on the two spans around whichever
  // knot the sign of span 4's torsion picks.
  const FittedPolyline fit = fitPolyline(quarticTwist(-1.1), FitOptions{}, cubicBuilder());
  const DiscreteShape& shape = fit.Shape;
  const int span = 4;
  ASSERT_TRUE(shape.Twisted[span - 1] && shape.Twisted[span + 1]);
  ASSERT_LT(shape.Torsion[span - 1], 0.0);
  ASSERT_GT(shape.Torsion[span + 1], 0.0);
  EXPECT_LT(3.0 * std::abs(shape.Torsion[span]), shape.Torsion[span + 1]);
  EXPECT_TRUE(shape.TorsionCrossing[span]);
  EXPECT_FALSE(shape.Twisted[span] || shape.Coplanar[span]);

  for (const double where : { 3.4, 4.0, 4.4, 5.0, 5.6 })
  {
    EXPECT_EQ(failuresWithTorsion(fit, crossingAt(where)), 0) << where;
  }
  EXPECT_GT(failuresWithTorsion(fit, crossingAt(2.6)), 0); // the span before the window wrong
  EXPECT_GT(failuresWithTorsion(fit, crossingAt(6.4)), 0);

  // The zero at a knot: that knot's two spans, as before.
  const DiscreteShape knotShape = discreteShape(cleanPolyline(quarticTwist(-1.0), false));
  for (int j = 1; j < 7; ++j)
  {
    EXPECT_FALSE(knotShape.TorsionCrossing[j]) << j;
  }
}

TEST(DiscreteShape, ExactDoublingBackIsFinite)
{
  // Regression (fuzzing): I_{i+1} = I_{i-1} made the Menger curvature 0/0.
  const DiscreteShape shape = discreteShape(
    cleanPolyline({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0, 1, 0) }, false));
  for (const double k : shape.Curvature)
  {
    EXPECT_TRUE(std::isfinite(k));
  }
  EXPECT_FALSE(shape.Collinear[1]); // turning back is not a straight run
}

TEST(ShapeAudit, TorsionMayChangeSignOnceNextToAnOpenEnd)
{
  // An open line's end spans have no discrete torsion, so the data cannot
  // say whether the torsion reverses at the knot next to an end: the curve
  // may change sign once there (a trefoil's torsion does, a third of a span
  // in), as where the data reverse. Inside, and away from that knot, the
  // sign still holds on every span.
  const FittedPolyline fit = fitPolyline(helix(8, 2), FitOptions{}, cubicBuilder());
  const int spans = fit.Data.numberOfSpans();
  ASSERT_TRUE(fit.Shape.Twisted[1] && fit.Shape.Twisted[spans - 2]);
  ASSERT_FALSE(fit.Shape.Twisted[0] || fit.Shape.Twisted[spans - 1]);
  // The curve's torsion made negative where `wrong` says, u in spans from the first point.
  auto failing = [&](const std::function<bool(double)>& wrong) {
    return torsionFailures(
      fit, [&](double u, double torsion) { return wrong(u) ? -std::abs(torsion) : std::abs(torsion); });
  };
  EXPECT_EQ(failing([](double) { return false; }), 0);
  EXPECT_EQ(failing([](double u) { return u < 1.4; }), 0);          // changes once in span 1
  EXPECT_EQ(failing([&](double u) { return u > spans - 1.3; }), 0); // in the last span but one
  EXPECT_EQ(failing([](double u) { return u > 1.6 && u < 2.0; }), 1); // span 1's far end: no
  EXPECT_EQ(failing([](double u) { return u > 3.0 && u < 3.4; }), 1); // an inner span: no
  EXPECT_EQ(failing([](double u) { return u >= 1.0 && u <= 2.0; }), 1); // all of span 1: no
}

TEST(DiscreteShape, ASegmentOfAStraightRunHasNoPlaneWhateverItsOrientation)
{
  // A 3D staircase: runs of two steps along x, y, z, x, y. Every segment has
  // a collinear end, where no plane exists: no coplanarity or torsion
  // criterion, the same on the axis-aligned points (whose triple products
  // are exactly 0) and on a rotated copy (rounding: it read torsions of
  // 0.5-2.2 of either sign; through the filter the cubic counted 13
  // violations on the axis-aligned points and 5 on the rotated ones).
  std::vector<Vec3> points = { Vec3::Zero() };
  const double runs[] = { 0.509, 1.226, 1.226, 1.837, 0.9 };
  for (int k = 0; k < 5; ++k)
  {
    for (int step = 0; step < 2; ++step)
    {
      points.push_back(points.back() + 0.5 * runs[k] * Vec3::Unit(k % 3));
    }
  }
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(1.1, Vec3::UnitZ()) *
    Eigen::AngleAxisd(-0.7, Vec3::UnitY()) * Eigen::AngleAxisd(0.3, Vec3::UnitX()))
                                     .toRotationMatrix();
  std::vector<Vec3> rotated;
  for (const Vec3& p : points)
  {
    rotated.push_back(rotation * p);
  }
  const DiscreteShape axis = discreteShape(cleanPolyline(points, false));
  const DiscreteShape turned = discreteShape(cleanPolyline(rotated, false));
  // The runs' middle points, between corners in perpendicular planes (not
  // an inflection, which a product of binormals of +-1e-17 took them for).
  const std::vector<char> collinear = { 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0 };
  EXPECT_EQ(axis.Collinear, collinear);
  EXPECT_EQ(turned.Collinear, collinear);
  for (size_t i = 0; i < axis.Torsion.size(); ++i)
  {
    for (const DiscreteShape* shape : { &axis, &turned })
    {
      EXPECT_FALSE(shape->Coplanar[i]) << i;
      EXPECT_FALSE(shape->Twisted[i]) << i;
      EXPECT_EQ(shape->Torsion[i], 0.0) << i;
    }
  }
  const FittedPolyline fit = fitPolyline(points, FitOptions{}, cubicBuilder());
  const FittedPolyline fitRotated = fitPolyline(rotated, FitOptions{}, cubicBuilder());
  EXPECT_EQ(fit.Audit.violations(), fitRotated.Audit.violations());
  EXPECT_EQ(failures(fit.Audit, ShapeCriterion::Coplanarity), 0);
  EXPECT_GT(failures(fit.Audit, ShapeCriterion::Collinearity), 0); // the cubic bends the runs
}

TEST(DiscreteShape, ReversalsAreWhereTheLineRunsStraightBack)
{
  // A to B and back to A twice: reversals at both; a hairpin that still
  // turns (170 degrees) is none; running back within the collinearity
  // tolerance (a turn of 180 degrees less 1e-8) is one; so is a closed
  // line's seam where it runs back along its first segment; a straight run
  // forwards is none (it is collinear).
  const auto reversals = [](const CleanPolyline& line) {
    const std::vector<char> flags = discreteShape(line).Reversal;
    std::vector<int> at;
    for (int i = 0; i < static_cast<int>(flags.size()); ++i)
    {
      if (flags[i])
      {
        at.push_back(i);
      }
    }
    return at;
  };
  const Vec3 bent(2 - std::cos(Pi / 18), std::sin(Pi / 18), 0);
  CleanPolyline line;
  line.Points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), bent,
    Vec3(2, 1e-8, 0) };
  EXPECT_EQ(reversals(line), std::vector<int>({ 1, 2, 5 }));
  line.Points.back() = Vec3(2, 1e-4, 0);
  EXPECT_EQ(reversals(line), std::vector<int>({ 1, 2 }));
  CleanPolyline closed;
  closed.Points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0) };
  closed.Closed = true; // 2 -> 0 runs back along 0 -> 1 -> 2
  EXPECT_EQ(reversals(closed), std::vector<int>({ 0, 2 }));
  closed.Closed = false;
  EXPECT_TRUE(reversals(closed).empty());
  EXPECT_TRUE(discreteShape(closed).Collinear[1]);
}
