// Cleaning polylines (repeated points, closed lines) and knot spacing.
#include "Parameterization.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace shapesplines;

TEST(Parameterization, KnotSpacings)
{
  CleanPolyline line = cleanPolyline({ Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 9, 0) }, false);
  EXPECT_EQ(computeKnots(line, Parameterization::Uniform), (std::vector<double>{ 0, 1, 2 }));
  EXPECT_EQ(computeKnots(line, Parameterization::ChordLength), (std::vector<double>{ 0, 4, 13 }));
  EXPECT_EQ(computeKnots(line, Parameterization::Centripetal), (std::vector<double>{ 0, 2, 5 }));
}

TEST(Parameterization, ConsecutiveRepeatsAreMergedAndCounted)
{
  const CleanPolyline line = cleanPolyline(
    { Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 1, 0), Vec3(2, 1, 0), Vec3(2, 1, 0) },
    false);
  EXPECT_EQ(line.Points.size(), 3u);
  EXPECT_EQ(line.MergedPoints, 3);
  EXPECT_EQ(line.SourceIndex, (std::vector<int>{ 0, 2, 3 }));
  EXPECT_FALSE(line.Closed);
}

TEST(Parameterization, UnevenSpacingIsNotMerged)
{
  // 1e-7 next to 1 is data, not a repeat.
  const CleanPolyline line = cleanPolyline({ Vec3(0, 0, 0), Vec3(1e-7, 0, 0), Vec3(1, 1, 0) }, false);
  EXPECT_EQ(line.Points.size(), 3u);
}

TEST(Parameterization, NearRepeatsAreMerged)
{
  // A segment under 1e-8 of each neighbouring one is a repeat whose
  // direction is noise: its later point goes, or at the line's end the
  // earlier one; one as short next to one as short is kept.
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(2, 1, 0);
  const Vec3 tiny(0, 0, 1e-9);
  CleanPolyline line = cleanPolyline({ a, b, b + tiny, c, d }, false);
  EXPECT_EQ(line.Points.size(), 4u);
  EXPECT_EQ(line.SourceIndex, std::vector<int>({ 0, 1, 3, 4 }));
  EXPECT_EQ(line.MergedPoints, 1);
  line = cleanPolyline({ a, b, c, d - tiny, d }, false);
  EXPECT_EQ(line.SourceIndex, std::vector<int>({ 0, 1, 2, 4 }));
  line = cleanPolyline({ a, b, c, c + tiny, c + 2.0 * tiny, d }, false);
  EXPECT_EQ(line.Points.size(), 6u);
}

TEST(Parameterization, RepeatedSeamClosesTheLine)
{
  const CleanPolyline line =
    cleanPolyline({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 0, 0) }, false);
  EXPECT_TRUE(line.Closed);
  EXPECT_EQ(line.Points.size(), 3u);
  EXPECT_EQ(line.numberOfSpans(), 3);
  const auto knots = computeKnots(line, Parameterization::ChordLength);
  ASSERT_EQ(knots.size(), 4u);
  EXPECT_NEAR(knots.back(), 2.0 + std::sqrt(2.0), 1e-15);
}

TEST(Parameterization, ForcedClosureAndTooFewPointsToClose)
{
  EXPECT_TRUE(cleanPolyline({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0) }, true).Closed);
  // A B A cannot enclose anything: it stays an open line of three points.
  const CleanPolyline back = cleanPolyline({ Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 0) }, false);
  EXPECT_FALSE(back.Closed);
  EXPECT_EQ(back.Points.size(), 3u);
}

TEST(Parameterization, AllPointsIdentical)
{
  const CleanPolyline line = cleanPolyline({ Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3) }, true);
  EXPECT_EQ(line.Points.size(), 1u);
  EXPECT_FALSE(line.Closed);
  EXPECT_EQ(line.numberOfSpans(), 0);
}

TEST(Parameterization, HugeCoordinatesAreNotMergedAway)
{
  // The diagonal of 1e160-sized data squares past the double range; the merge
  // tolerance must not become infinite and swallow every point.
  const CleanPolyline line =
    cleanPolyline({ Vec3(0, 0, 0), Vec3(1e160, 0, 0), Vec3(1e160, 2e160, 0) }, false);
  EXPECT_EQ(line.Points.size(), 3u);
  EXPECT_NEAR(boundingBoxDiagonal(line.Points), std::sqrt(5.0) * 1e160, 1e146);
}
