// The tensioned quintic B-splines with all shape parameters 1, and the
// variable degree splines with all degrees 5 and tensions 1, against SciPy's
// classical quintic splines (values written at test time by
// scipy_quintic_reference.py, whose output file is the first argument).
#include "TensionQuinticSpline.h"
#include "VariableDegreeSpline.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <string>

using namespace shapesplines;

namespace
{
std::string ReferenceFile;

struct ReferenceCase
{
  bool Closed = false;
  std::vector<double> Knots;
  std::vector<Vec3> Points;
  std::vector<double> Parameters;
  std::vector<Derivatives> Values;
};

std::map<std::string, ReferenceCase> readReference()
{
  std::map<std::string, ReferenceCase> cases;
  std::ifstream in(ReferenceFile);
  std::string word, name;
  int closed, knots, points, evaluations;
  while (in >> word >> name >> closed >> knots >> points >> evaluations)
  {
    ReferenceCase& c = cases[name];
    c.Closed = closed != 0;
    c.Knots.resize(knots);
    for (double& t : c.Knots)
    {
      in >> t;
    }
    c.Points.resize(points);
    for (Vec3& p : c.Points)
    {
      in >> p.x() >> p.y() >> p.z();
    }
    for (int i = 0; i < evaluations; ++i)
    {
      double t;
      Derivatives d;
      in >> t;
      for (Vec3& v : d)
      {
        in >> v.x() >> v.y() >> v.z();
      }
      c.Parameters.push_back(t);
      c.Values.push_back(d);
    }
  }
  return cases;
}

const ReferenceCase& referenceCase(const std::string& name)
{
  static const auto cases = readReference();
  if (cases.count(name) != 1)
  {
    throw std::runtime_error("no case " + name + " in '" + ReferenceFile + "'");
  }
  return cases.at(name);
}

/// Largest differences of derivatives 0..4, relative to the largest reference value of each order.
void compare(const std::string& name, const Curve& curve, double tolerance)
{
  const ReferenceCase& c = referenceCase(name);
  double scale[5] = { 0, 0, 0, 0, 0 };
  for (const Derivatives& d : c.Values)
  {
    for (int order = 0; order < 5; ++order)
    {
      scale[order] = std::max(scale[order], d[order].norm());
    }
  }
  double worst[5] = { 0, 0, 0, 0, 0 };
  for (size_t i = 0; i < c.Parameters.size(); ++i)
  {
    const Derivatives ours = curve.evaluate(c.Parameters[i], 4);
    for (int order = 0; order < 5; ++order)
    {
      worst[order] =
        std::max(worst[order], (ours[order] - c.Values[i][order]).norm() / scale[order]);
    }
  }
  for (int order = 0; order < 5; ++order)
  {
    EXPECT_LT(worst[order], tolerance) << name << ", derivative " << order;
  }
  std::printf("%s: largest relative differences to SciPy %.1e %.1e %.1e %.1e %.1e\n",
    name.c_str(), worst[0], worst[1], worst[2], worst[3], worst[4]);
}

class QuinticAgainstSciPy : public ::testing::TestWithParam<QuinticContinuity>
{
};
} // namespace

TEST_P(QuinticAgainstSciPy, BasisIsTheQuinticBSpline)
{
  const ReferenceCase& c = referenceCase("basis");
  const int knots = static_cast<int>(c.Knots.size());
  const auto spline = TensionQuinticSpline::fromControlPoints(c.Knots,
    TensionQuinticSpline::grevilleAbscissae(c.Knots, false), c.Points,
    QuinticParameters::uniform(GetParam(), knots), false);
  // X(t) = t with the Greville abscissae (21): the knots stay where they are.
  for (int i = 0; i < knots; ++i)
  {
    EXPECT_NEAR(spline.knots()[i], c.Knots[i], 1e-13 * c.Knots.back());
  }
  compare("basis", spline, 1e-10);
}

TEST_P(QuinticAgainstSciPy, OpenInterpolation)
{
  const ReferenceCase& c = referenceCase("open");
  const auto spline = TensionQuinticSpline::interpolate(c.Points, c.Knots,
    QuinticParameters::uniform(GetParam(), static_cast<int>(c.Knots.size())), false);
  EXPECT_EQ(spline.knotRecoveries(), 0);
  compare("open", spline, 1e-8);
}

TEST_P(QuinticAgainstSciPy, PeriodicInterpolation)
{
  const ReferenceCase& c = referenceCase("closed");
  const auto spline = TensionQuinticSpline::interpolate(c.Points, c.Knots,
    QuinticParameters::uniform(GetParam(), static_cast<int>(c.Points.size())), true);
  compare("closed", spline, 1e-8);
}

TEST(VariableDegreeAgainstSciPy, AllDegreesFiveIsTheQuinticInterpolant)
{
  for (const char* name : { "natural", "closed" })
  {
    const ReferenceCase& c = referenceCase(name);
    const size_t knots = c.Points.size();
    const VariableDegreeParameters quintic{ std::vector<double>(knots, 5.0),
      std::vector<double>(knots, 1.0) };
    const auto spline = VariableDegreeSpline::interpolate(
      c.Points, c.Knots, c.Closed, quintic, VariableDegreeEnds::Natural);
    compare(name, spline, 1e-8);
  }
}

INSTANTIATE_TEST_SUITE_P(Continuity, QuinticAgainstSciPy,
  ::testing::Values(QuinticContinuity::C3, QuinticContinuity::C4),
  [](const auto& info) { return info.param == QuinticContinuity::C3 ? "C3" : "C4"; });

int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  // Without the file (as when CTest lists the tests) every comparison fails.
  ReferenceFile = argc > 1 ? argv[1] : "";
  return RUN_ALL_TESTS();
}
