// The C2 cubic spline against SciPy's CubicSpline (values written at test time
// by scipy_cubic_reference.py, whose output file is the first argument).
#include "CubicSpline.h"

#include <gtest/gtest.h>

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
  int closed, points, evaluations;
  while (in >> word >> name >> closed >> points >> evaluations)
  {
    ReferenceCase& c = cases[name];
    c.Closed = closed != 0;
    for (int i = 0; i < points; ++i)
    {
      double t;
      Vec3 p;
      in >> t >> p.x() >> p.y() >> p.z();
      c.Knots.push_back(t);
      c.Points.push_back(p);
    }
    for (int i = 0; i < evaluations; ++i)
    {
      double t;
      Derivatives d;
      d.fill(Vec3::Zero());
      in >> t;
      for (int order = 0; order < 4; ++order)
      {
        in >> d[order].x() >> d[order].y() >> d[order].z();
      }
      c.Parameters.push_back(t);
      c.Values.push_back(d);
    }
  }
  return cases;
}

void compare(const std::string& name, CubicEndCondition ends)
{
  const auto cases = readReference();
  ASSERT_EQ(cases.count(name), 1u) << "no case " << name << " in " << ReferenceFile;
  const ReferenceCase& c = cases.at(name);
  std::vector<Vec3> points = c.Points;
  if (c.Closed)
  {
    points.pop_back(); // SciPy repeats the seam point
  }
  const CubicSpline s = CubicSpline::interpolate(points, c.Knots, c.Closed, ends);
  double worst[4] = { 0, 0, 0, 0 };
  for (size_t i = 0; i < c.Parameters.size(); ++i)
  {
    const Derivatives ours = s.evaluate(c.Parameters[i], 3);
    for (int order = 0; order < 4; ++order)
    {
      worst[order] = std::max(worst[order],
        (ours[order] - c.Values[i][order]).norm() / (1.0 + c.Values[i][order].norm()));
    }
  }
  for (int order = 0; order < 4; ++order)
  {
    EXPECT_LT(worst[order], 1e-10) << name << ", derivative " << order;
  }
  std::printf("%s: largest relative differences to SciPy %.1e %.1e %.1e %.1e over %zu parameters\n",
    name.c_str(), worst[0], worst[1], worst[2], worst[3], c.Parameters.size());
}
} // namespace

TEST(CubicAgainstSciPy, NotAKnot)
{
  compare("not-a-knot", CubicEndCondition::NotAKnot);
}

TEST(CubicAgainstSciPy, Natural)
{
  compare("natural", CubicEndCondition::Natural);
}

TEST(CubicAgainstSciPy, ClampedWithParabolaEnds)
{
  compare("clamped", CubicEndCondition::Clamped);
}

TEST(CubicAgainstSciPy, Periodic)
{
  compare("periodic", CubicEndCondition::NotAKnot);
}

int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  // Without the file (as when CTest lists the tests) every comparison fails.
  ReferenceFile = argc > 1 ? argv[1] : "";
  return RUN_ALL_TESTS();
}
