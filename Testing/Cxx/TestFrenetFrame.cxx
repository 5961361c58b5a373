// Curvature, torsion and frames from exact derivatives of curves with closed forms.
#include "FrenetFrame.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace shapesplines;

namespace
{
FrenetFrame frameOf(const Vec3& d1, const Vec3& d2, const Vec3& d3)
{
  Derivatives d;
  d.fill(Vec3::Zero());
  d[1] = d1;
  d[2] = d2;
  d[3] = d3;
  return frenetFrames({ d }, 1e-12).front();
}

void expectOrthonormal(const FrenetFrame& f)
{
  EXPECT_NEAR(f.Tangent.norm(), 1.0, 1e-12);
  EXPECT_NEAR(f.Normal.norm(), 1.0, 1e-12);
  EXPECT_NEAR(f.Binormal.norm(), 1.0, 1e-12);
  EXPECT_NEAR(f.Tangent.dot(f.Normal), 0.0, 1e-12);
  EXPECT_NEAR(f.Tangent.cross(f.Normal).dot(f.Binormal), 1.0, 1e-12);
}
} // namespace

TEST(FrenetFrame, HelixClosedForm)
{
  // (a cos t, a sin t, b t), a = 2, b = 1, at t = 0.7.
  const double a = 2, b = 1, t = 0.7;
  const FrenetFrame f = frameOf(Vec3(-a * std::sin(t), a * std::cos(t), b),
    Vec3(-a * std::cos(t), -a * std::sin(t), 0), Vec3(a * std::sin(t), -a * std::cos(t), 0));
  EXPECT_NEAR(f.Curvature, 0.4, 1e-14);
  EXPECT_NEAR(f.Torsion, 0.2, 1e-14);
  expectOrthonormal(f);
  // The principal normal of a helix points at its axis.
  EXPECT_NEAR(f.Normal.dot(Vec3(-std::cos(t), -std::sin(t), 0)), 1.0, 1e-14);
}

TEST(FrenetFrame, ConicalHelixViviniTrefoilClosedForms)
{
  // Derivatives at t = 0, worked out by hand from the parametrizations.
  // Conical helix (t cos t, t sin t, t): kappa 1, tau 3/4.
  FrenetFrame f = frameOf(Vec3(1, 0, 1), Vec3(0, 2, 0), Vec3(-3, 0, 0));
  EXPECT_NEAR(f.Curvature, 1.0, 1e-14);
  EXPECT_NEAR(f.Torsion, 0.75, 1e-14);
  // Viviani's curve (1 + cos t, sin t, 2 sin(t/2)): kappa 1/2, tau 3/8.
  f = frameOf(Vec3(0, 1, 1), Vec3(-1, 0, 0), Vec3(0, -1, -0.25));
  EXPECT_NEAR(f.Curvature, 0.5, 1e-14);
  EXPECT_NEAR(f.Torsion, 0.375, 1e-14);
  // Trefoil (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t): kappa 7/34, tau 6/17.
  f = frameOf(Vec3(5, 0, -3), Vec3(0, 7, 0), Vec3(-17, 0, 27));
  EXPECT_NEAR(f.Curvature, 7.0 / 34.0, 1e-14);
  EXPECT_NEAR(f.Torsion, 6.0 / 17.0, 1e-14);
  expectOrthonormal(f);
}

TEST(FrenetFrame, MirrorFlipsTorsionOnly)
{
  const Vec3 d1(1, 0, 1), d2(0, 2, 0), d3(-3, 0, 0);
  const Vec3 m(1, 1, -1); // reflection z -> -z
  const FrenetFrame f = frameOf(d1, d2, d3);
  const FrenetFrame g = frameOf(d1.cwiseProduct(m), d2.cwiseProduct(m), d3.cwiseProduct(m));
  EXPECT_NEAR(g.Curvature, f.Curvature, 1e-14);
  EXPECT_NEAR(g.Torsion, -f.Torsion, 1e-14);
}

TEST(FrenetFrame, StraightLineHasZeroCurvatureAndAContinuousFrame)
{
  std::vector<Derivatives> samples(5);
  for (auto& d : samples)
  {
    d.fill(Vec3::Zero());
    d[1] = Vec3(1, 2, 3);
    d[2] = Vec3(1e-17, -1e-17, 0); // rounding noise, not curvature
  }
  const auto frames = frenetFrames(samples, 1e-11);
  for (size_t k = 0; k < frames.size(); ++k)
  {
    EXPECT_LT(frames[k].Curvature, 1e-11); // rounding-level, reported as it is
    EXPECT_EQ(frames[k].Torsion, 0.0);
    expectOrthonormal(frames[k]);
    EXPECT_NEAR(frames[k].Normal.dot(frames[0].Normal), 1.0, 1e-12);
  }
}

TEST(FrenetFrame, FlatStretchCarriesTheNeighbouringNormal)
{
  // Curved, then straight (s'' = 0), then curved: the straight samples carry
  // the normal of the nearest curved sample instead of an arbitrary one.
  std::vector<Derivatives> samples(6);
  for (size_t k = 0; k < samples.size(); ++k)
  {
    samples[k].fill(Vec3::Zero());
    samples[k][1] = Vec3(1, 0, 0);
    samples[k][2] = (k == 0 || k == 5) ? Vec3(0, 0, 1) : Vec3::Zero();
  }
  const auto frames = frenetFrames(samples, 1e-12);
  for (const auto& f : frames)
  {
    EXPECT_TRUE(f.Normal.allFinite());
    EXPECT_NEAR(f.Normal.dot(Vec3(0, 0, 1)), 1.0, 1e-12);
    EXPECT_EQ(f.Torsion, 0.0);
  }
}

TEST(FrenetFrame, LeadingFlatSamplesTakeTheFirstDefinedNormal)
{
  std::vector<Derivatives> samples(4);
  for (size_t k = 0; k < samples.size(); ++k)
  {
    samples[k].fill(Vec3::Zero());
    samples[k][1] = Vec3(0, 1, 0);
    samples[k][2] = k == 3 ? Vec3(1, 0, 0) : Vec3::Zero();
  }
  const auto frames = frenetFrames(samples, 1e-12);
  for (const auto& f : frames)
  {
    EXPECT_NEAR(f.Normal.dot(Vec3(1, 0, 0)), 1.0, 1e-12);
  }
}

TEST(FrenetFrame, StationaryPointStaysFinite)
{
  // s' = 0 (a cusp of the parametrization): tangent from s'', no NaN anywhere.
  const FrenetFrame f = frameOf(Vec3::Zero(), Vec3(0, 1, 0), Vec3(1, 0, 0));
  EXPECT_NEAR(f.Tangent.dot(Vec3(0, 1, 0)), 1.0, 1e-15);
  EXPECT_TRUE(std::isfinite(f.Curvature));
  EXPECT_TRUE(std::isfinite(f.Torsion));
  expectOrthonormal(f);
}

TEST(FrenetFrame, PiecewiseFramesEqualFramesInOneGo)
{
  // Curved, flat (s'' = 0) across the cut, curved again.
  std::vector<Derivatives> samples(8);
  for (size_t k = 0; k < samples.size(); ++k)
  {
    samples[k].fill(Vec3::Zero());
    samples[k][1] = Vec3(1, 0.1 * k, 0);
    samples[k][2] = (k < 2 || k > 5) ? Vec3(0, 0.3, 1) : Vec3::Zero();
    samples[k][3] = Vec3(0, 0, 0.2);
  }
  const std::vector<double> flat(samples.size(), 1e-12);
  const auto whole = frenetFrames(samples, flat);
  const std::vector<Derivatives> first(samples.begin(), samples.begin() + 4);
  const std::vector<Derivatives> second(samples.begin() + 4, samples.end());
  const auto a = frenetFrames(first, std::vector<double>(4, 1e-12));
  const auto b = frenetFrames(second, std::vector<double>(4, 1e-12), &a.back().Normal);
  for (size_t k = 0; k < samples.size(); ++k)
  {
    const FrenetFrame& piece = k < 4 ? a[k] : b[k - 4];
    EXPECT_LT((piece.Normal - whole[k].Normal).norm(), 1e-15) << k;
    EXPECT_EQ(piece.Torsion, whole[k].Torsion) << k;
  }
  // Without the previous normal the flat start of the second piece would
  // borrow the normal of its own first curved sample instead.
  const auto alone = frenetFrames(second, std::vector<double>(4, 1e-12));
  EXPECT_GT((alone[0].Normal - whole[4].Normal).norm(), 1e-3);
}
