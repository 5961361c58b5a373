// Quartic Bernstein-like (qqr) basis and cubic B-spline-like curves (paper 003).
#include "QQRSpline.h"
#include "MathTestUtilities.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace shapesplines;
using namespace shapesplines::test;

TEST(QQRBasis, PartitionOfUnity)
{
  for (const double alpha : { 2.0, 4.0, 200.0 })
  {
    for (int k = 0; k <= 20; ++k)
    {
      const auto a = qqrBasis(k / 20.0, alpha, alpha);
      double sum = 0.0;
      for (const Jet& j : a)
      {
        sum += j[0];
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
    }
  }
}
