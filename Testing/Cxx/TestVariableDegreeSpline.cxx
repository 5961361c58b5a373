// C3 variable degree splines (Costantini & Manni (VDPS)): the pseudo Bernstein basis, the
// corner cutting construction, interpolation, the tension limit, automatic
// shape preservation, accuracy and the approximation schemes.
#include "VariableDegreeSpline.h"
#include "MathTestUtilities.h"
#include "Approximation.h" // leastSquaresPolygon

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>

using namespace shapesplines;
using namespace shapesplines::test;

namespace
{
const std::vector<double> Degrees = { 5, 6, 8, 11, 20, 50, 100, 200 };

/// The basis straight from its definition in long double: B0, B1, B4, B5
/// closed forms, B2 and B3 from the two conditions that define them.
std::array<long double, 6> referenceBasis(long double k, long double m, long double v)
{
  std::array<long double, 6> b;
  b[0] = std::pow(1 - v, k);
  b[1] = k * v * std::pow(1 - v, k - 1);
  b[4] = m * std::pow(v, m - 1) * (1 - v);
  b[5] = std::pow(v, m);
  const long double rest = 1 - b[0] - b[1] - b[4] - b[5];
  const long double linear = v - b[1] / k - (1 - 1 / m) * b[4] - b[5];
  b[3] = (linear - 2 / k * rest) / (1 - 2 / k - 2 / m);
  b[2] = rest - b[3];
  return b;
}

VariableDegreeParameters uniformParameters(size_t knots, double degree, double lambda = 1.0)
{
  return { std::vector<double>(knots, degree), std::vector<double>(knots, lambda) };
}

/// count random points of the unit cube on an open line, with knot spacings
/// spacing + U(0, 1) (per point: its coordinates, then its spacing).
std::pair<std::vector<Vec3>, std::vector<double>> randomOpenData(int count, double spacing, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> points;
  std::vector<double> u = { 0.0 };
  for (int i = 0; i < count; ++i)
  {
    points.emplace_back(unit(random), unit(random), unit(random));
    u.push_back(u.back() + spacing + unit(random));
  }
  u.pop_back();
  return { points, u };
}

/// Largest relative jump of derivative `order` over the interior knots.
double largestJump(const Curve& curve, int order)
{
  double worst = 0.0;
  const int spans = curve.numberOfSpans();
  for (int j = curve.isClosed() ? 0 : 1; j < spans; ++j)
  {
    const int before = (j - 1 + spans) % spans;
    const Derivatives left = curve.evaluateOnSpan(before, curve.knots()[before + 1], order);
    const Derivatives right = curve.evaluateOnSpan(j, curve.knots()[j], order);
    worst = std::max(worst, relativeJump(left[order], right[order]));
  }
  return worst;
}

/// The largest distance of the given spans from their chords between the
/// points, at 31 inner samples a span.
double largestChordDistance(
  const Curve& curve, const std::vector<Vec3>& points, const std::vector<int>& spans)
{
  const std::vector<double>& knots = curve.knots();
  double distance = 0.0;
  for (const int j : spans)
  {
    for (int s = 1; s < 32; ++s)
    {
      const double f = s / 32.0;
      const Vec3 chord = (1 - f) * points[j] + f * points[j + 1];
      const double t = knots[j] + f * (knots[j + 1] - knots[j]);
      distance = std::max(distance, (curve.evaluateOnSpan(j, t, 0)[0] - chord).norm());
    }
  }
  return distance;
}

FittedPolyline Fit(const std::vector<Vec3>& points, const VariableDegreeOptions& options)
{
  return fitPolyline(points, FitOptions{}, variableDegreeBuilder(options));
}

VariableDegreeOptions Options(bool automatic, double degree = 5.0)
{
  VariableDegreeOptions options;
  options.Automatic = automatic;
  options.Degree = degree;
  return options;
}

/// A space curve the quintic overshoots: a helix turn that runs into a straight line.
std::vector<Vec3> helixIntoLine()
{
  std::vector<Vec3> points;
  for (int i = 0; i <= 6; ++i)
  {
    const double t = 2.0 * Pi * i / 8.0;
    points.emplace_back(2.0 * std::cos(t), 2.0 * std::sin(t), 0.5 * t);
  }
  const Vec3 end = points.back();
  for (int i = 1; i <= 4; ++i)
  {
    points.push_back(end + Vec3(1.5 * i, 0.0, 0.0));
  }
  return points;
}
} // namespace

TEST(PseudoBernstein, IsTheQuinticBernsteinBasisForDegreeFive)
{
  static const double binomial[6] = { 1, 5, 10, 10, 5, 1 };
  for (int s = 0; s <= 20; ++s)
  {
    const double v = s / 20.0;
    const auto basis = pseudoBernstein(5, 5, v);
    for (int j = 0; j < 6; ++j)
    {
      EXPECT_NEAR(basis[j][0], binomial[j] * std::pow(v, j) * std::pow(1 - v, 5 - j), 4e-15);
    }
  }
}

TEST(PseudoBernstein, PartitionOfUnityLinearPrecisionSymmetryAndStability)
{
  for (const double k : Degrees)
  {
    for (const double m : Degrees)
    {
      const double xi[6] = { 0, 1 / k, 2 / k, 1 - 2 / m, 1 - 1 / m, 1 };
      for (int s = 0; s <= 64; ++s)
      {
        const double v = s / 64.0;
        const auto basis = pseudoBernstein(k, m, v);
        const auto mirrored = pseudoBernstein(m, k, 1 - v);
        const auto reference = referenceBasis(k, m, v);
        for (int n = 0; n < 5; ++n)
        {
          double sum = 0.0, abscissa = 0.0;
          for (int j = 0; j < 6; ++j)
          {
            sum += basis[j][n];
            abscissa += xi[j] * basis[j][n];
            // B_j(k, m; v) = B_5-j(m, k; 1 - v), derivatives with the sign of (-1)^n.
            EXPECT_NEAR(basis[j][n], (n % 2 ? -1 : 1) * mirrored[5 - j][n],
              1e-12 * std::pow(std::max(k, m), n))
              << k << " " << m << " " << v << " j " << j << " n " << n;
          }
          EXPECT_NEAR(sum, n == 0 ? 1.0 : 0.0, 1e-12 * std::pow(std::max(k, m), n));
          EXPECT_NEAR(abscissa, n == 0 ? v : (n == 1 ? 1.0 : 0.0), 1e-12 * std::pow(std::max(k, m), n));
        }
        for (int j = 0; j < 6; ++j)
        {
          EXPECT_NEAR(basis[j][0], static_cast<double>(reference[j]), 1e-14)
            << k << " " << m << " " << v << " j " << j;
        }
      }
    }
  }
}

TEST(PseudoBernstein, DerivativesAgreeWithDifferencesOfTheLowerOrder)
{
  const double step = 1e-6;
  for (const double k : { 5.0, 7.0, 30.0, 200.0 })
  {
    for (const double m : { 5.0, 9.0, 200.0 })
    {
      for (const double v : { 0.1, 0.37, 0.5, 0.8, 0.97 })
      {
        const auto plus = pseudoBernstein(k, m, v + step);
        const auto minus = pseudoBernstein(k, m, v - step);
        const auto at = pseudoBernstein(k, m, v);
        for (int j = 0; j < 6; ++j)
        {
          for (int n = 1; n < 5; ++n)
          {
            const double difference = (plus[j][n - 1] - minus[j][n - 1]) / (2 * step);
            EXPECT_NEAR(at[j][n], difference, 1e-5 * std::pow(std::max(k, m), n))
              << k << " " << m << " " << v << " j " << j << " n " << n;
          }
        }
      }
    }
  }
}

TEST(PseudoBernstein, NonNegativeEvenForVeryUnequalNeighbouringDegrees)
{
  // The shared design notes expected B2 < 0 for k = 50, m = 7; with B2, B3
  // defined by partition of unity and linear precision every B_j stays >= 0,
  // for neighbouring degrees as unequal as 5 and 1000 (checked on a fine grid).
  std::vector<double> degrees = Degrees;
  degrees.push_back(1000.0);
  double smallest = 1.0;
  for (const double k : degrees)
  {
    for (const double m : degrees)
    {
      for (int s = 0; s <= 2000; ++s)
      {
        for (const auto& b : pseudoBernstein(k, m, s / 2000.0))
        {
          smallest = std::min(smallest, b[0]);
        }
      }
    }
  }
  EXPECT_GT(smallest, -1e-15);
  // And strictly positive inside the interval, where the properties of a
  // Bernstein-like basis need it.
  for (const auto& b : pseudoBernstein(50, 7, 0.5))
  {
    EXPECT_GT(b[0], 0.0);
  }
}

TEST(VariableDegreeSpline, C3AtEveryKnotWithRandomDegreesAndTensions)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double choices[4] = { 5, 6, 8, 11 };
  for (const bool closed : { false, true })
  {
    const int knots = 12;
    std::vector<double> u = { 0.0 };
    VariableDegreeParameters p;
    for (int i = 0; i < knots; ++i)
    {
      u.push_back(u.back() + 0.2 + unit(random));
      p.Degree.push_back(choices[random() % 4]);
      p.Lambda.push_back(0.1 + 1.4 * unit(random));
    }
    if (!closed)
    {
      p.Degree.push_back(7);
      p.Lambda.push_back(0.5);
    }
    std::vector<Vec3> deBoor(closed ? knots : knots + 5);
    for (Vec3& d : deBoor)
    {
      d = Vec3(unit(random), unit(random), unit(random));
    }
    const auto spline = VariableDegreeSpline::fromDeBoor(u, closed, p, deBoor);
    for (int order = 0; order <= 3; ++order)
    {
      EXPECT_LE(largestJump(spline, order), 1e-9) << "closed " << closed << " order " << order;
    }
    // The fourth derivative jumps: the test sees a join that is C3 and not more.
    EXPECT_GT(largestJump(spline, 4), 1e-3);
  }
}

TEST(VariableDegreeSpline, DegreeFiveAndTensionOneIsTheC4QuinticWithNaturalEnds)
{
  const auto [points, u] = randomOpenData(10, 0.3, 8);
  const auto spline = VariableDegreeSpline::interpolate(
    points, u, false, uniformParameters(u.size(), 5.0), VariableDegreeEnds::Natural);
  EXPECT_LE(largestJump(spline, 4), 1e-9);
  for (int i = 0; i < 10; ++i)
  {
    EXPECT_LT((spline.evaluate(u[i], 0)[0] - points[i]).norm(), 1e-13);
  }
  const Derivatives start = spline.evaluate(u.front(), 3);
  const Derivatives end = spline.evaluate(u.back(), 3);
  EXPECT_LT(start[2].norm() + start[3].norm() + end[2].norm() + end[3].norm(), 1e-10);
}

TEST(VariableDegreeSpline, InterpolatesOpenClosedAndClampedWithRandomDegrees)
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const bool closed : { false, true })
  {
    for (const VariableDegreeEnds ends : { VariableDegreeEnds::Natural, VariableDegreeEnds::Clamped })
    {
      std::vector<Vec3> points;
      std::vector<double> u = { 0.0 };
      VariableDegreeParameters p;
      for (int i = 0; i < 9; ++i)
      {
        points.emplace_back(unit(random), unit(random), unit(random));
        u.push_back(u.back() + 0.1 + unit(random));
        p.Degree.push_back(5 + std::floor(40 * unit(random)));
        p.Lambda.push_back(5.0 / p.Degree.back());
      }
      if (!closed)
      {
        u.pop_back();
      }
      const auto spline = VariableDegreeSpline::interpolate(points, u, closed, p, ends);
      for (size_t i = 0; i < points.size(); ++i)
      {
        EXPECT_LT((spline.evaluate(u[i], 0)[0] - points[i]).norm(), 1e-12) << closed;
      }
      if (closed)
      {
        EXPECT_LT((spline.evaluate(u.back(), 0)[0] - points[0]).norm(), 1e-12);
      }
      EXPECT_LE(largestJump(spline, 3), 1e-9);
      EXPECT_LT(spline.conditionEstimate(), 1e6);
    }
  }
}

TEST(VariableDegreeSpline, PolynomialEndsReproduceAQuinticCurve)
{
  // Degree 5 and tension 1 is the C4 quintic spline: with the end quintic's
  // s'' and s''' (the curve's own for a quintic curve) it is the curve, to
  // rounding, on uneven knots; natural ends are not.
  std::vector<double> u;
  std::vector<Vec3> points;
  for (int i = 0; i <= 11; ++i)
  {
    const double t = -1.0 + 2.0 * i / 11.0 + (i % 3 == 1 ? 0.05 : 0.0);
    u.push_back(t);
    points.emplace_back(t, t * t * t * t * t - t * t, t * t * t);
  }
  const auto p = uniformParameters(u.size(), 5.0);
  const auto polynomial =
    VariableDegreeSpline::interpolate(points, u, false, p, VariableDegreeEnds::Polynomial);
  const auto natural =
    VariableDegreeSpline::interpolate(points, u, false, p, VariableDegreeEnds::Natural);
  expectPolynomialEndsReproduce("quintic curve", polynomial, natural,
    [](double t) { return Vec3(0.0, 20.0 * t * t * t - 2.0, 6.0 * t); }, 1e-8);
}

TEST(VariableDegreeSpline, NaturalEndsNeedTensionAtTheEndKnots)
{
  // All degrees 200, lambda = (5/200)^3: the curve near an end hardly depends
  // on D_-2, D_-1 any more, so s'' = s''' = 0 there pins them badly; clamped
  // ends, or lambda = 1 at the two knots next to each end (the builder's
  // choice for natural ends), keep the system well-conditioned.
  const auto [points, u] = randomOpenData(20, 0.5, 1);
  const auto p = uniformParameters(points.size(), 200.0, std::pow(5.0 / 200.0, 3));
  const auto clamped = VariableDegreeSpline::interpolate(points, u, false, p, VariableDegreeEnds::Clamped);
  const auto natural = VariableDegreeSpline::interpolate(points, u, false, p, VariableDegreeEnds::Natural);
  auto endTension = p;
  for (const size_t i : { size_t(0), size_t(1), points.size() - 2, points.size() - 1 })
  {
    endTension.Lambda[i] = 1.0;
  }
  const auto natural1 =
    VariableDegreeSpline::interpolate(points, u, false, endTension, VariableDegreeEnds::Natural);
  std::printf("degree 200: condition estimate clamped %.3g, natural %.3g, natural with "
              "lambda 1 at the end knots %.3g\n",
    clamped.conditionEstimate(), natural.conditionEstimate(), natural1.conditionEstimate());
  EXPECT_LT(clamped.conditionEstimate(), 100.0);
  EXPECT_GT(natural.conditionEstimate(), 1e6);
  EXPECT_LT(natural1.conditionEstimate(), 100.0);
  // The builder takes the middle road: lambda = 5 / k at the two knots next
  // to each end, (5 / k)^3 elsewhere. The condition grows like k (about 770
  // at degree 200), and the end spans still tend to their chords, which
  // lambda = 1 there stops (a random 3D polyline's automatic degrees kept a
  // convexity violation on span 2 at any degree).
  const FittedPolyline fit = Fit(points, Options(false, 200.0));
  EXPECT_LT(fit.Spline->conditionEstimate(), 2e3);
  auto endDistance = [&](const Curve& curve) {
    const int spans = curve.numberOfSpans();
    return largestChordDistance(curve, fit.Data.Points, { 0, 1, spans - 2, spans - 1 }) /
      boundingBoxDiagonal(fit.Data.Points);
  };
  const double atDegree200 = endDistance(*fit.Spline);
  const double atDegree5 = endDistance(*Fit(points, Options(false, 5.0)).Spline);
  std::printf("end spans' largest distance to their chords: %.3g at degree 5, %.3g at 200\n",
    atDegree5, atDegree200);
  EXPECT_LT(atDegree200, 0.1 * atDegree5);
}

TEST(VariableDegreeSpline, GrowingDegreesTendToThePolygon)
{
  const std::vector<Vec3> points = akima();
  CleanPolyline data = cleanPolyline(points, false);
  const auto knots = computeKnots(data, Parameterization::ChordLength);
  const double diameter = boundingBoxDiagonal(data.Points);
  // Measured: 5.5% at degree 5, 0.87% at 10, a hump to 1.35% at 21 (the
  // tension lambda has collapsed, the degrees not yet), then decreasing.
  double previous = 1e300;
  for (const double k : { 5.0, 10.0, 21.0, 25.0, 50.0, 100.0, 200.0 })
  {
    // The builder's default tension law, lambda = (5 / k)^3.
    VariableDegreeParameters p = uniformParameters(points.size(), k, std::pow(5.0 / k, 3));
    const auto spline = VariableDegreeSpline::interpolate(points, knots, false, p);
    std::vector<int> spans(spline.numberOfSpans());
    std::iota(spans.begin(), spans.end(), 0);
    const double distance = largestChordDistance(spline, points, spans);
    std::printf("degree %g: largest distance to the polygon %.3g of the diameter\n", k,
      distance / diameter);
    if (k == 10.0 || k > 21.0)
    {
      EXPECT_LT(distance, previous) << k;
    }
    previous = distance;
  }
  EXPECT_LT(previous, 3e-3 * diameter);
}

TEST(VariableDegreeSpline, AutomaticDegreesRemoveEveryViolationTheQuinticHas)
{
  const std::vector<std::pair<const char*, std::vector<Vec3>>> sets = { { "Akima", akima() },
    { "RPN 15A", rpn15a() }, { "titanium", titanium() }, { "helix into a line", helixIntoLine() } };
  for (const auto& [name, points] : sets)
  {
    const FittedPolyline quintic = Fit(points, Options(false));
    const FittedPolyline automatic = Fit(points, Options(true));
    const auto& degree = static_cast<const VariableDegreeSpline&>(*automatic.Spline).parameters().Degree;
    const long raised =
      std::count_if(degree.begin(), degree.end(), [](double k) { return k > 5.0; });
    std::printf("%s: quintic %d violations, automatic %d; largest degree %g, knots raised %ld of %zu\n",
      name, quintic.Audit.violations(), automatic.Audit.violations(),
      *std::max_element(degree.begin(), degree.end()), raised, degree.size());
    EXPECT_GT(quintic.Audit.violations(), 0) << name;
    EXPECT_EQ(automatic.Audit.violations(), 0) << name;
    // Only where needed: some knots keep degree 5.
    EXPECT_LT(raised, static_cast<long>(degree.size())) << name;
  }
}

TEST(VariableDegreeSpline, HelixCurvatureAndTorsionConverge)
{
  double previousCurvature = 1.0, previousTorsion = 1.0;
  for (const int perTurn : { 8, 16, 32 })
  {
    const FittedPolyline fit = Fit(helix(perTurn, 6), Options(true));
    const RelativeErrors errors = interiorErrors(fit, 0.4, 0.2, perTurn);
    const double curvatureOrder = std::log2(previousCurvature / errors.Curvature);
    const double torsionOrder = std::log2(previousTorsion / errors.Torsion);
    std::printf("helix, %d points per turn: curvature %.3g, torsion %.3g (orders %.2f, %.2f)\n",
      perTurn, errors.Curvature, errors.Torsion, curvatureOrder, torsionOrder);
    if (perTurn == 8)
    {
      EXPECT_LT(errors.Curvature, 1e-2);
      EXPECT_LT(errors.Torsion, 1e-2);
    }
    else
    {
      EXPECT_GT(curvatureOrder, 3.5);
      EXPECT_GT(torsionOrder, 3.5);
    }
    previousCurvature = errors.Curvature;
    previousTorsion = errors.Torsion;
  }
}

TEST(VariableDegreeSpline, PolynomialEndsConvergeUpToTheEndsAndFadeAsTheEndDegreeGrows)
{
  // The whole open line, ends included: natural ends (s'' = s''' = 0) leave
  // an error of the size of the curvature and torsion there at any density;
  // the end quintic's s'' and s''' converge at fourth order, like the inside.
  VariableDegreeOptions natural = Options(false);
  natural.Ends = VariableDegreeEnds::Natural;
  double previousCurvature = 1.0, previousTorsion = 1.0;
  for (const int perTurn : { 8, 16, 32 })
  {
    const std::vector<Vec3> points = helix(perTurn, 2);
    const RelativeErrors errors = interiorErrors(Fit(points, Options(false)), 0.4, 0.2, 0);
    const RelativeErrors naturalErrors = interiorErrors(Fit(points, natural), 0.4, 0.2, 0);
    const double curvatureOrder = std::log2(previousCurvature / errors.Curvature);
    const double torsionOrder = std::log2(previousTorsion / errors.Torsion);
    std::printf("open helix, %d points per turn, whole line: polynomial ends curvature %.3g, "
                "torsion %.3g (orders %.2f, %.2f); natural ends %.3g, %.3g\n",
      perTurn, errors.Curvature, errors.Torsion, curvatureOrder, torsionOrder,
      naturalErrors.Curvature, naturalErrors.Torsion);
    EXPECT_GT(naturalErrors.Curvature, 0.5) << perTurn;
    EXPECT_GT(naturalErrors.Torsion, 0.5) << perTurn;
    if (perTurn > 8)
    {
      EXPECT_GT(curvatureOrder, 3.0) << perTurn;
      EXPECT_GT(torsionOrder, 3.0) << perTurn;
    }
    previousCurvature = errors.Curvature;
    previousTorsion = errors.Torsion;
  }
  EXPECT_LT(previousCurvature, 1e-3);
  EXPECT_LT(previousTorsion, 1e-2);

  // At degree 200 the end derivatives fade by (5 / 200)^3: the same system
  // and condition as natural ends, nearly the same curve, whose end spans
  // still tend to their chords.
  const auto [points, u] = randomOpenData(20, 0.5, 1);
  natural.Degree = 200.0;
  const FittedPolyline fit = Fit(points, Options(false, 200.0));
  const FittedPolyline naturalFit = Fit(points, natural);
  const double diagonal = boundingBoxDiagonal(fit.Data.Points);
  double apart = 0.0;
  for (int k = 0; k <= 2000; ++k)
  {
    const double t = fit.Knots.front() + (fit.Knots.back() - fit.Knots.front()) * k / 2000.0;
    const Vec3 difference = fit.Spline->evaluate(t, 0)[0] - naturalFit.Spline->evaluate(t, 0)[0];
    apart = std::max(apart, difference.norm());
  }
  std::printf("degree 200: polynomial and natural ends %.3g of the diagonal apart; condition "
              "estimates %.3g and %.3g\n",
    apart / diagonal, fit.Spline->conditionEstimate(), naturalFit.Spline->conditionEstimate());
  EXPECT_LT(apart, 1e-3 * diagonal);
  EXPECT_LT(fit.Spline->conditionEstimate(), 2e3);
}

TEST(VariableDegreeSpline, ApproximationReproducesACurveOfItsSpace)
{
  // Points sampled from a spline with clamped ends on the approximation's own
  // knots and degrees: least squares gives that spline back.
  std::mt19937 random(21);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::vector<double> knots = { 0.0, 1.0, 1.7, 3.0, 3.5, 5.0 };
  VariableDegreeParameters p{ { 5, 9, 14, 6, 20, 5 }, { 1, 0.5, 0.3, 0.9, 0.25, 1 } };
  std::vector<Vec3> free(knots.size());
  for (Vec3& d : free)
  {
    d = Vec3(unit(random), unit(random), unit(random));
  }
  std::vector<Vec3> deBoor = { free[0], free[0] };
  deBoor.insert(deBoor.end(), free.begin(), free.end());
  deBoor.insert(deBoor.end(), { free.back(), free.back() });
  const auto truth = VariableDegreeSpline::fromDeBoor(knots, false, p, deBoor);
  std::vector<Vec3> points;
  std::vector<double> u;
  for (int j = 0; j <= 60; ++j)
  {
    u.push_back(5.0 * j / 60.0);
    points.push_back(truth.evaluate(u.back(), 0)[0]);
  }
  const auto fit = VariableDegreeSpline::approximate(
    points, u, knots, false, p, std::vector<double>(knots.size(), 0.0), std::vector<Vec3>(knots.size()));
  for (size_t j = 0; j < deBoor.size(); ++j)
  {
    EXPECT_LT((fit.deBoorPoints()[j] - deBoor[j]).norm(), 1e-10) << j;
  }
}

TEST(VariableDegreeSpline, ClosedApproximationReproducesAClosedCurveOfItsSpace)
{
  // A closed curve of degrees 5 to 12 through 7 space points: least squares
  // on its own knots and degrees from 90 of its points give it back.
  std::vector<Vec3> vertices;
  std::vector<double> knots{ 0.0 };
  std::vector<double> degrees;
  for (int i = 0; i < 7; ++i)
  {
    const double a = 2.0 * test::Pi * i / 7;
    vertices.emplace_back(std::cos(a), 1.2 * std::sin(a), 0.3 * std::sin(2 * a));
    knots.push_back(knots.back() + 1.0 + 0.2 * std::sin(3.0 * i));
    degrees.push_back(5.0 + i);
  }
  VariableDegreeParameters p = uniformParameters(7, 5.0);
  p.Degree = degrees;
  const auto truth = VariableDegreeSpline::interpolate(vertices, knots, true, p);
  std::vector<double> u;
  std::vector<Vec3> points;
  for (int j = 0; j < 90; ++j)
  {
    u.push_back(knots.front() + (knots.back() - knots.front()) * (j + 0.5) / 90);
    points.push_back(truth.evaluate(u.back(), 0)[0]);
  }
  const auto fit = VariableDegreeSpline::approximate(
    points, u, knots, true, p, std::vector<double>(7, 0.0), std::vector<Vec3>(7));
  ASSERT_TRUE(fit.isClosed());
  ASSERT_EQ(fit.deBoorPoints().size(), truth.deBoorPoints().size());
  for (size_t j = 0; j < truth.deBoorPoints().size(); ++j)
  {
    EXPECT_LT((fit.deBoorPoints()[j] - truth.deBoorPoints()[j]).norm(), 1e-10) << j;
  }
}

TEST(VariableDegreeSpline, ApproximationTendsToPsiAsDegreesOrWeightsGrow)
{
  std::mt19937 random(4);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::vector<Vec3> points = helix(16, 2);
  std::vector<double> u;
  for (size_t j = 0; j < points.size(); ++j)
  {
    points[j] += Vec3(noise(random), noise(random), noise(random));
    u.push_back(static_cast<double>(j));
  }
  std::vector<double> knots;
  for (int i = 0; i <= 8; ++i)
  {
    knots.push_back(u.back() * i / 8.0);
  }
  const std::vector<Vec3> psi = leastSquaresPolygon(points, u, knots);
  auto distanceToPsi = [&](const VariableDegreeSpline& s) {
    double worst = 0.0;
    for (size_t i = 0; i < knots.size(); ++i)
    {
      worst = std::max(worst, (s.evaluate(knots[i], 0)[0] - psi[i]).norm());
    }
    return worst;
  };
  const std::vector<double> none(knots.size(), 0.0);
  double previous = 1e300;
  for (const double k : { 5.0, 20.0, 100.0, 1000.0 })
  {
    const auto s = VariableDegreeSpline::approximate(
      points, u, knots, false, uniformParameters(knots.size(), k, std::pow(5.0 / k, 3)), none, psi);
    const double d = distanceToPsi(s);
    std::printf("global scheme, degree %g: distance to psi at the knots %.3g\n", k, d);
    EXPECT_LT(d, previous);
    previous = d;
  }
  EXPECT_LT(previous, 0.02);
  // The local scheme: a large weight at one knot pulls the curve onto psi there only.
  std::vector<double> weights = none;
  weights[4] = 1e8;
  const auto s = VariableDegreeSpline::approximate(
    points, u, knots, false, uniformParameters(knots.size(), 5.0), weights, psi);
  EXPECT_LT((s.evaluate(knots[4], 0)[0] - psi[4]).norm(), 1e-5);
  EXPECT_GT((s.evaluate(knots[2], 0)[0] - psi[2]).norm(), 1e-4);
}

TEST(VariableDegreeSpline, AutomaticApproximationKeepsTheShapeOfPsi)
{
  std::mt19937 random(9);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<Vec3> points = helixIntoLine();
  std::vector<Vec3> dense;
  for (size_t i = 0; i + 1 < points.size(); ++i)
  {
    for (int s = 0; s < 6; ++s)
    {
      const double f = s / 6.0;
      dense.push_back((1 - f) * points[i] + f * points[i + 1] +
        Vec3(noise(random), noise(random), noise(random)));
    }
  }
  dense.push_back(points.back());
  for (const VariableDegreeMode mode :
    { VariableDegreeMode::ApproximateGlobal, VariableDegreeMode::ApproximateLocal })
  {
    VariableDegreeOptions options = Options(true);
    options.Mode = mode;
    options.ApproximationKnots = 12;
    const FittedPolyline fit = Fit(dense, options);
    options.Automatic = false;
    const FittedPolyline plain = Fit(dense, options);
    ASSERT_TRUE(fit.ShapeReference);
    EXPECT_EQ(fit.ShapeReference->Points.size(), 12u);
    const auto degree = fit.Spline->spanParameters().at(0).Values;
    std::printf("mode %d: fixed degree 5 %d violations of psi's shape, automatic %d "
                "(largest degree %g)\n",
      int(mode), plain.Audit.violations(), fit.Audit.violations(),
      *std::max_element(degree.begin(), degree.end()));
    EXPECT_EQ(fit.Audit.violations(), 0) << int(mode);
  }
}

TEST(VariableDegreeSpline, RejectsWhatIsNotASpline)
{
  const std::vector<double> knots = { 0, 1, 2, 3 };
  const std::vector<Vec3> points(4, Vec3::Zero());
  EXPECT_THROW(VariableDegreeSpline::interpolate(points, knots, false, uniformParameters(4, 4.0)),
    std::invalid_argument);
  EXPECT_THROW(
    VariableDegreeSpline::interpolate(points, knots, false, uniformParameters(4, 5.0, 0.0)),
    std::invalid_argument);
  EXPECT_THROW(VariableDegreeSpline::interpolate(
                 points, { 0, 1, 1, 3 }, false, uniformParameters(4, 5.0)),
    std::invalid_argument);
  EXPECT_THROW(VariableDegreeSpline::interpolate(points, knots, false, uniformParameters(3, 5.0)),
    std::invalid_argument);
  EXPECT_EQ(raisedDegree(5, 100), 7); // 6.3 rounded up
  EXPECT_EQ(raisedDegree(7, 100), 9);
  EXPECT_EQ(raisedDegree(90, 100), 100);
  EXPECT_EQ(raisedDegree(100, 100), 100);
}
