#include "Approximation.h"

#include "ExtendedIndex.h"
#include "SparseSolve.h"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>

namespace shapesplines
{
std::vector<double> uniformKnots(const std::vector<double>& u, int count)
{
  std::vector<double> knots;
  for (int i = 0; i < count; ++i)
  {
    knots.push_back(u.front() + (u.back() - u.front()) * i / (count - 1));
  }
  knots.back() = u.back();
  return knots;
}

namespace
{
/// Points a knot from which an approximation smooths rather than all but
/// interpolates (planApproximation).
constexpr int SmoothingSpanPoints = 3;

/// count >= 2 knots at the quantiles of the increasing parameters u: as many
/// parameters between any two knots, ending exactly at u's ends.
std::vector<double> quantileKnots(const std::vector<double>& u, int count)
{
  const int parameters = static_cast<int>(u.size());
  std::vector<double> knots(count);
  for (int j = 0; j < count; ++j)
  {
    const double position = static_cast<double>(j) * (parameters - 1) / (count - 1);
    const int below = std::min(static_cast<int>(position), parameters - 2);
    knots[j] = u[below] + (position - below) * (u[below + 1] - u[below]);
  }
  knots.back() = u.back();
  return knots;
}

/// Every count up to 64 (GCV is bumpy there: on a noisy 80-point line 14
/// knots scored 6% above 19, with 15-18 between); beyond, 15% steps.
std::vector<int> candidateCounts(int lowest, int highest)
{
  constexpr int EveryCountUpTo = 64;
  constexpr double GridGrowth = 1.15;
  std::vector<int> grid;
  for (int knots = lowest; knots <= highest;
       knots = knots < EveryCountUpTo ? knots + 1 : static_cast<int>(knots * GridGrowth))
  {
    grid.push_back(knots);
  }
  if (!grid.empty() && grid.back() != highest)
  {
    grid.push_back(highest);
  }
  return grid;
}

/// N RSS / (N - unknowns)^2, or infinity where there are too few points.
double gcvScore(double rss, double points, int knots, bool closed)
{
  const double freedom = points - (closed ? knots : knots + 4); // the de Boor points of the fit
  return freedom > 0 ? points * rss / (freedom * freedom) : std::numeric_limits<double>::infinity();
}

/**
 * The scores of the counts the search needs: the grid, then the counts
 * between the best grid point's neighbours (ternary search: GCV is close to
 * unimodal there). score() is called once per count; it returns infinity
 * for a count that cannot be fitted. The scored counts, in order.
 */
std::map<int, double> scoreCounts(
  int lowest, int highest, const std::function<double(int)>& score)
{
  std::map<int, double> scores;
  auto scored = [&](int knots) {
    const auto known = scores.find(knots);
    return known != scores.end() ? known->second : (scores[knots] = score(knots));
  };
  const std::vector<int> grid = candidateCounts(lowest, highest);
  if (grid.empty())
  {
    return scores;
  }
  size_t best = 0;
  for (size_t i = 0; i < grid.size(); ++i)
  {
    best = scored(grid[i]) < scored(grid[best]) ? i : best;
  }
  int low = grid[best == 0 ? 0 : best - 1];
  int high = grid[std::min(best + 1, grid.size() - 1)];
  while (high - low > 2)
  {
    const int left = low + (high - low) / 3;
    const int right = high - (high - low) / 3;
    if (scored(left) <= scored(right))
    {
      high = right;
    }
    else
    {
      low = left;
    }
  }
  for (int knots = low; knots <= high; ++knots)
  {
    scored(knots);
  }
  return scores;
}
} // namespace

QuinticFit::QuinticFit(const std::vector<double>& knots, bool closed)
  : Spans(static_cast<int>(knots.size()) - 1)
  , Closed(closed)
  , First(knots.front())
  , Last(knots.back())
{
  // The full knot vector: five more beyond each end, repeated (open: a
  // clamped quintic) or continued by the period (closed).
  for (int j = -Degree; j <= this->Spans + Degree; ++j)
  {
    this->T.push_back(closed ? periodicKnot(knots, j) : knots[std::clamp(j, 0, this->Spans)]);
  }
}

int QuinticFit::unknown(int j) const
{
  return this->Closed ? wrapIndex(j, this->Spans) : j;
}

int QuinticFit::locate(double u) const
{
  const auto begin = this->T.begin() + Degree;
  const auto it = std::upper_bound(begin, begin + this->Spans + 1, u);
  return std::clamp(static_cast<int>(it - begin) - 1, 0, this->Spans - 1);
}

std::array<std::array<double, QuinticFit::Degree + 1>, 3> QuinticFit::basis(int span, double u) const
{
  // Piegl and Tiller's algorithm A2.3: the six quintic B-splines nonzero on
  // the span (coefficients span..span + 5) and their first two derivatives.
  constexpr int p = Degree;
  const int i = span + p; // the span's start in T
  std::array<std::array<double, p + 1>, p + 1> ndu{};
  std::array<double, p + 1> left{}, right{};
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j)
  {
    left[j] = u - this->T[i + 1 - j];
    right[j] = this->T[i + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r)
    {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  std::array<std::array<double, p + 1>, 3> ders{};
  for (int j = 0; j <= p; ++j)
  {
    ders[0][j] = ndu[j][p];
  }
  std::array<std::array<double, p + 1>, 2> a{};
  for (int r = 0; r <= p; ++r)
  {
    int s1 = 0, s2 = 1;
    a[0].fill(0.0);
    a[1].fill(0.0);
    a[0][0] = 1.0;
    for (int k = 1; k <= 2; ++k)
    {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k)
      {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = r - 1 <= pk ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j)
      {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk)
      {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k][r] = d;
      std::swap(s1, s2);
    }
  }
  for (int j = 0; j <= p; ++j)
  {
    ders[1][j] *= p;
    ders[2][j] *= p * (p - 1);
  }
  return ders;
}

std::optional<QuinticFit> QuinticFit::solve(const std::vector<Vec3>& points,
  const std::vector<double>& u, const std::vector<double>& knots, bool closed)
{
  QuinticFit fit(knots, closed);
  const int spans = fit.Spans;
  // B-spline span + a (a = 0..5) is nonzero on span; a closed curve's wrap around.
  const int unknowns = closed ? spans : spans + 5;
  // Upper band of the normal matrix by unwrapped index: band(i, d) = (B^T B)(i, i + d).
  Eigen::Matrix<double, Eigen::Dynamic, 6> band = Eigen::Matrix<double, Eigen::Dynamic, 6>::Zero(spans + 5, 6);
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(unknowns, 3);
  std::vector<char> spanHasPoints(spans, 0);
  for (size_t j = 0; j < points.size(); ++j)
  {
    const int span = fit.locate(u[j]);
    const auto b = fit.basis(span, std::clamp(u[j], fit.T[span + Degree], fit.T[span + Degree + 1]))[0];
    spanHasPoints[span] = 1;
    for (int a = 0; a < 6; ++a)
    {
      for (int c = a; c < 6; ++c)
      {
        band(span + a, c - a) += b[a] * b[c];
      }
      rhs.row(fit.unknown(span + a)) += b[a] * points[j].transpose();
    }
  }
  // A span without points is decided by its neighbours' alone: on the aorta
  // centerline (chords up to 8 times their median) such least squares went
  // singular, or nearly (a curve 2000 times too long).
  if (std::find(spanHasPoints.begin(), spanHasPoints.end(), 0) != spanHasPoints.end())
  {
    return std::nullopt;
  }
  Triplets entries; // the lower triangle, as SimplicialLDLT reads it; wrapped entries add up
  for (int i = 0; i < spans + 5; ++i)
  {
    for (int d = 0; d < 6 && i + d < spans + 5; ++d)
    {
      const int row = fit.unknown(i + d), column = fit.unknown(i);
      if (d > 0 && row == column)
      {
        entries.emplace_back(row, row, 2.0 * band(i, d)); // both (i, i + d) and (i + d, i)
      }
      else
      {
        entries.emplace_back(std::max(row, column), std::min(row, column), band(i, d));
      }
    }
  }
  Eigen::SparseMatrix<double> normal(unknowns, unknowns);
  normal.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>
    solver(normal);
  const Eigen::VectorXd pivots = solver.vectorD();
  // Pivots at rounding level of the largest: as good as a span without points.
  if (solver.info() != Eigen::Success || pivots.minCoeff() <= 1e-12 * pivots.maxCoeff())
  {
    return std::nullopt;
  }
  fit.Coefficients = solver.solve(rhs);
  return fit;
}

std::array<Vec3, 3> QuinticFit::evaluate(double u) const
{
  const int span = this->locate(u);
  u = std::clamp(u, this->T[span + Degree], this->T[span + Degree + 1]);
  const auto b = this->basis(span, u);
  std::array<Vec3, 3> out;
  out.fill(Vec3::Zero());
  for (int a = 0; a < 6; ++a)
  {
    const Vec3 c = this->Coefficients.row(this->unknown(span + a)).transpose();
    for (int r = 0; r < 3; ++r)
    {
      out[r] += b[r][a] * c;
    }
  }
  return out;
}

double QuinticFit::nearest(const Vec3& p, double u) const
{
  // Newton on (s(u) - p) . s'(u) = 0; three steps from a nearby start.
  for (int step = 0; step < 3; ++step)
  {
    const std::array<Vec3, 3> d = this->evaluate(u);
    const Vec3 r = d[0] - p;
    const double slope = d[1].squaredNorm() + r.dot(d[2]);
    if (!(slope > 0.0))
    {
      break;
    }
    u = std::clamp(u - r.dot(d[1]) / slope, this->First, this->Last);
  }
  return u;
}

double QuinticFit::residual(const std::vector<Vec3>& points, const std::vector<double>& u) const
{
  double rss = 0.0;
  for (size_t j = 0; j < points.size(); ++j)
  {
    rss += (this->evaluate(u[j])[0] - points[j]).squaredNorm();
  }
  return rss;
}

ExtendedData extendForApproximation(
  const std::vector<Vec3>& points, const std::vector<double>& u, int knotCount, bool closed)
{
  ExtendedData data;
  const int n = static_cast<int>(points.size());
  if (closed || n < 3)
  {
    data.Points = points;
    data.Parameters = u;
    data.Knots = uniformKnots(u, closed ? knotCount + 1 : knotCount);
    return data;
  }
  // The points within two mean spacings of an end (at least two), at most a
  // quarter of them; and as many more as it takes to reach one mean spacing
  // beyond the end with two points beyond it. Points at the end's parameter
  // (within a tenth of a mean spacing) are not mirrored: repeated points give
  // no leverage, and the corrected parameters of noisy points gather at an
  // end, where a mirrored point off the end at the end's parameter made a
  // kink (the shipped aorta's line 0, 34 knots: curvature 1.13 at its end
  // for 0.45 without it), or a span beyond of no length and a fit of none
  // (0 / 0), losing cross-validation the few knots torsion needs.
  const double a = u.front(), b = u[n - 1];
  const double reach = 2.0 * (b - a) / (n - 1);
  auto mirrored = [&](auto distance) {
    std::vector<int> taken;
    for (int k = 1; k < n; ++k)
    {
      const double d = distance(k);
      if (d <= 0.05 * reach)
      {
        continue; // at the end's parameter: its mirror there would demand a kink
      }
      const int count = static_cast<int>(taken.size());
      if (count >= 2 && !(count < n / 4 && d <= reach) && distance(taken.back()) >= 0.5 * reach)
      {
        break;
      }
      taken.push_back(k);
    }
    return taken;
  };
  const std::vector<int> head = mirrored([&](int k) { return u[k] - a; });
  const std::vector<int> tail = mirrored([&](int k) { return b - u[n - 1 - k]; });
  for (auto k = head.rbegin(); k != head.rend(); ++k)
  {
    data.Points.push_back(2.0 * points.front() - points[*k]);
    data.Parameters.push_back(2.0 * a - u[*k]);
  }
  data.Points.insert(data.Points.end(), points.begin(), points.end());
  data.Parameters.insert(data.Parameters.end(), u.begin(), u.begin() + n);
  for (const int k : tail)
  {
    data.Points.push_back(2.0 * points.back() - points[n - 1 - k]);
    data.Parameters.push_back(2.0 * b - u[n - 1 - k]);
  }
  // One span beyond each end, as long as the mirrored points reach.
  const std::vector<double> inside = uniformKnots(u, knotCount);
  data.Knots.push_back(data.Parameters.front());
  data.Knots.insert(data.Knots.end(), inside.begin(), inside.end());
  data.Knots.push_back(data.Parameters.back());
  data.Extra = 1;
  return data;
}

std::vector<int> extendedLevels(const std::vector<int>& levels, int extra)
{
  std::vector<int> all(extra, levels.front());
  all.insert(all.end(), levels.begin(), levels.end());
  all.insert(all.end(), extra, levels.back());
  return all;
}

namespace
{
/// A knot count's fit with the parameters corrected towards it (three
/// rounds of projecting every point onto the fit from where it was), and
/// the squared distances left. Nothing when a fit is singular.
struct CorrectedFit
{
  std::vector<double> Parameters;
  double Residual = std::numeric_limits<double>::infinity();
};

/// The fewest parameters u[0..count) that a span of the knots holds.
int fewestHeld(const std::vector<double>& knots, const std::vector<double>& u, size_t count)
{
  std::vector<int> held(knots.size() - 1, 0);
  for (size_t j = 0; j < count; ++j)
  {
    const auto after = std::upper_bound(knots.begin(), knots.end(), u[j]);
    ++held[std::clamp<long>(after - knots.begin() - 1, 0, static_cast<long>(held.size()) - 1)];
  }
  return *std::min_element(held.begin(), held.end());
}

/// Whether every span of the extended knots holds at least two points: a
/// span with one is decided by that point and its neighbours, and the
/// corrected parameters of a wandering line (a random walk) can gather so
/// that a dozen such spans in a row loop far from the points.
bool everySpanHoldsTwoPoints(const ExtendedData& data)
{
  return fewestHeld(data.Knots, data.Parameters, data.Parameters.size()) >= 2;
}

/// The nondecreasing sequence closest to values in least squares (pool
/// adjacent violators): each run out of order becomes its mean.
std::vector<double> nondecreasing(const std::vector<double>& values)
{
  std::vector<std::pair<double, size_t>> blocks; // (mean, count)
  for (const double value : values)
  {
    blocks.emplace_back(value, 1);
    while (blocks.size() > 1 && blocks[blocks.size() - 2].first > blocks.back().first)
    {
      const auto [mean, count] = blocks.back();
      blocks.pop_back();
      auto& previous = blocks.back();
      previous.first = (previous.first * previous.second + mean * count) / (previous.second + count);
      previous.second += count;
    }
  }
  std::vector<double> result;
  result.reserve(values.size());
  for (const auto& [mean, count] : blocks)
  {
    result.insert(result.end(), count, mean);
  }
  return result;
}

CorrectedFit correctedFit(const std::vector<Vec3>& points, std::vector<double> u, int knots,
  bool closed, bool correct, const std::function<void()>& checkpoint)
{
  auto fitTo = [&](const std::vector<double>& parameters) {
    const ExtendedData data = extendForApproximation(points, parameters, knots, closed);
    return QuinticFit::solve(data.Points, data.Parameters, data.Knots, closed);
  };
  constexpr int Rounds = 3;
  for (int round = 0; correct && round < Rounds; ++round)
  {
    checkpoint(); // a round on a million points takes seconds
    const auto fit = fitTo(u);
    if (!fit)
    {
      return {};
    }
    // An open line's points, its ends too, go where they project, in their
    // order (the nearest order in least squares): with the end points kept
    // and each point held after the one before, a first point projecting
    // inwards pushed the next ones along round after round, and the fit ran
    // on past the line's start (400 noisy points of a Viviani curve: by up
    // to 5 times the noise, length 1.6% long). A closed line's first point
    // keeps its parameter: it fixes the seam.
    std::vector<double> corrected = u;
    if (closed)
    {
      for (size_t j = 1; j < points.size(); ++j)
      {
        corrected[j] = std::clamp(fit->nearest(points[j], u[j]), corrected[j - 1], u.back());
      }
    }
    else
    {
      for (size_t j = 0; j < points.size(); ++j)
      {
        corrected[j] = fit->nearest(points[j], u[j]);
      }
      corrected = nondecreasing(corrected);
    }
    if (!everySpanHoldsTwoPoints(extendForApproximation(points, corrected, knots, closed)))
    {
      break; // keep the last parameters that held every span
    }
    u = std::move(corrected);
  }
  checkpoint();
  const auto fit = fitTo(u);
  if (!fit)
  {
    return {};
  }
  return { u, fit->residual(points, u) };
}
/// A plan, its generalized cross-validation score (infinity where its fit
/// failed) and the best score of the counts it chose among.
struct ScoredPlan
{
  ApproximationPlan Plan;
  double Score = std::numeric_limits<double>::infinity();
  double Best = std::numeric_limits<double>::infinity();
};

/// The scores a count may have to be taken for fewer knots than the best
/// score's: within half a standard error of it (the score's relative error
/// is about sqrt(2 / N) on N points).
double acceptableScore(double best, double points)
{
  return best * (1.0 + 0.5 * std::sqrt(2.0 / points));
}

ScoredPlan planFrom(const std::vector<Vec3>& points, const std::vector<double>& u,
  int highest, bool closed, int requestedKnots, bool correctParameters,
  const ProgressCallback& progress)
{
  const double count = static_cast<double>(points.size());
  const int lowest = lowestKnotCount(closed);
  // About the counts scoreCounts tries: every one up to 64, a grid beyond.
  const double expectedFits = static_cast<double>(candidateCounts(lowest, highest).size()) + 8.0;
  std::map<int, CorrectedFit> fits;
  auto fitted = [&](int knots) -> const CorrectedFit& {
    const auto known = fits.find(knots);
    if (known != fits.end())
    {
      return known->second;
    }
    const double fraction = std::min(0.99, static_cast<double>(fits.size()) / expectedFits);
    return fits[knots] = correctedFit(points, u, knots, closed, correctParameters,
             [&] { reportProgress(progress, 0, 1, fraction); });
  };
  int chosen = std::clamp(requestedKnots, lowest, std::max(lowest, highest));
  double best = std::numeric_limits<double>::infinity();
  if (requestedKnots == CrossValidatedKnots)
  {
    std::map<int, double> scores = scoreCounts(lowest, highest,
      [&](int knots) { return gcvScore(fitted(knots).Residual, count, knots, closed); });
    auto bestScore = [&] {
      std::pair<int, double> best(lowest, std::numeric_limits<double>::infinity());
      for (const auto& [knots, score] : scores)
      {
        if (score < best.second)
        {
          best = { knots, score };
        }
      }
      return best;
    };
    // No count with a span of a single point: a span holding one point is
    // free to bulge wherever the points leave a gap (60 noisy points of a
    // trefoil with gaps of 5 mean spacings: 24 knots, the fit 125 times the
    // noise off the curve in a gap, torsion error 117%), and a score of the
    // points' positions cannot see it. Smoothing (the best count takes
    // three points or more a knot): none with a span of fewer than three.
    // Points at random places leave a few spans with one or two, where the
    // third derivative, the torsion, follows their noise. Counts that all
    // but interpolate keep spans of two: a clean helix at 8 points a turn
    // needs them.
    const int fewest = count >= SmoothingSpanPoints * bestScore().first ? SmoothingSpanPoints : 2;
    for (auto& [knots, score] : scores)
    {
      const CorrectedFit& fit = fitted(knots);
      if (std::isfinite(score) &&
        fewestHeld(uniformKnots(fit.Parameters, closed ? knots + 1 : knots), fit.Parameters,
          points.size()) < fewest)
      {
        score = std::numeric_limits<double>::infinity();
      }
    }
    best = bestScore().second;
    // The fewest knots within half a standard error of the best score.
    const double acceptable = acceptableScore(best, count);
    chosen = lowest;
    for (const auto& [knots, score] : scores)
    {
      if (score <= acceptable)
      {
        chosen = knots;
        break;
      }
    }
  }
  ScoredPlan scored;
  const CorrectedFit& fit = fitted(chosen);
  scored.Plan.Knots = chosen;
  scored.Plan.Parameters = std::isfinite(fit.Residual) ? fit.Parameters : u;
  scored.Plan.NoiseLevel = std::isfinite(fit.Residual) ? std::sqrt(fit.Residual / count) : 0.0;
  scored.Plan.StarvedSpan = !std::isfinite(fit.Residual);
  scored.Score = gcvScore(fit.Residual, count, chosen, closed);
  scored.Best = std::min(best, scored.Score);
  return scored;
}

/**
 * The parameters u warped so that equal steps cover equal amounts of arc
 * length times sqrt(1 + curvature / mean curvature), both of the classical
 * quintic least squares on `knots` uniform knots (closed: distinct ones);
 * uniform knots in the warped parameters are then denser where the curve
 * bends. An open fit's first and last spans take the curvature at their
 * inner knot: an end hook of the fit would draw knots to itself and feed
 * the hook. Nothing where the fit fails or does not bend, or has fewer than
 * 3 spans.
 */
std::optional<std::vector<double>> curvatureWeighted(
  const std::vector<Vec3>& points, const std::vector<double>& u, int knots, bool closed)
{
  if (knots < 4)
  {
    return std::nullopt;
  }
  const ExtendedData data = extendForApproximation(points, u, knots, closed);
  const auto fit = QuinticFit::solve(data.Points, data.Parameters, data.Knots, closed);
  if (!fit)
  {
    return std::nullopt;
  }
  constexpr int PerSpan = 40;
  const int samples = PerSpan * (closed ? knots : knots - 1);
  const double a = u.front(), b = u.back();
  std::vector<double> speed(samples + 1), curvature(samples + 1);
  for (int k = 0; k <= samples; ++k)
  {
    const auto d = fit->evaluate(a + (b - a) * k / samples);
    speed[k] = d[1].norm();
    curvature[k] = shapesplines::curvature(d[1], d[2]);
  }
  for (int k = 0; k < PerSpan && !closed; ++k)
  {
    curvature[k] = curvature[PerSpan];
    curvature[samples - k] = curvature[samples - PerSpan];
  }
  // Trapezoids on the uniform grid: its step cancels out of the ratios.
  double length = 0.0, turning = 0.0;
  for (int k = 0; k < samples; ++k)
  {
    length += speed[k] + speed[k + 1];
    turning += curvature[k] * speed[k] + curvature[k + 1] * speed[k + 1];
  }
  if (!(turning > 0.0 && length > 0.0))
  {
    return std::nullopt;
  }
  const double mean = turning / length;
  std::vector<double> measure(samples + 1, 0.0);
  auto weight = [&](int k) { return speed[k] * std::sqrt(1.0 + curvature[k] / mean); };
  for (int k = 0; k < samples; ++k)
  {
    measure[k + 1] = measure[k] + weight(k) + weight(k + 1);
  }
  std::vector<double> warped(u.size());
  for (size_t j = 0; j < u.size(); ++j)
  {
    const double x = std::clamp((u[j] - a) / (b - a) * samples, 0.0, static_cast<double>(samples));
    const int k = std::min(static_cast<int>(x), samples - 1);
    warped[j] = a + (b - a) * (measure[k] + (x - k) * (measure[k + 1] - measure[k])) / measure[samples];
  }
  warped.back() = b;
  return warped;
}
} // namespace

ApproximationPlan planApproximation(const std::vector<Vec3>& points, const std::vector<double>& u,
  int highest, bool closed, int requestedKnots, bool correctParameters,
  const ProgressCallback& progress)
{
  // Two searches at most: each reports half the progress.
  auto half = [&](double start) { return progressWithin(progress, start, start + 0.5); };
  const ScoredPlan uniform = planFrom(points, u, highest, closed, requestedKnots, correctParameters, half(0.0));
  const bool smoothing = points.size() >= SmoothingSpanPoints * static_cast<size_t>(uniform.Plan.Knots);
  const auto warped =
    smoothing ? curvatureWeighted(points, uniform.Plan.Parameters, uniform.Plan.Knots, closed) : std::nullopt;
  if (!warped)
  {
    return uniform.Plan;
  }
  // Knots uniform in the parameter spread evenly along the curve, while a
  // curve's bends need them more than its straighter stretches: a spiral
  // whose radius grows took knots for its tight turns that then let noise
  // into the torsion of its wide ones. So, again from parameters warped by
  // the first plan's curvature, kept where they score better. The warp
  // moves the count little: up to twice the first one's is searched (on
  // 360 noisy cases the same choices as searching all, at 0.7x the cost).
  const ScoredPlan adapted = planFrom(points, *warped, std::min(highest, 2 * uniform.Plan.Knots), closed,
    requestedKnots, correctParameters, half(0.5));
  // Between the plans, the same rule as between counts: where both score
  // within half a standard error of the better one's best, the fewer knots.
  // Comparing their scores alone took a trefoil's 15 uniform knots (60%
  // torsion error) over 10 warped ones (7%) for a score 1.5% lower.
  const double acceptable =
    acceptableScore(std::min(uniform.Best, adapted.Best), static_cast<double>(points.size()));
  if (uniform.Score <= acceptable && adapted.Score <= acceptable &&
    uniform.Plan.Knots != adapted.Plan.Knots)
  {
    return adapted.Plan.Knots < uniform.Plan.Knots ? adapted.Plan : uniform.Plan;
  }
  return adapted.Score < uniform.Score ? adapted.Plan : uniform.Plan;
}

bool looksNoisy(const std::vector<Vec3>& points, const std::vector<double>& u, bool closed)
{
  const int count = static_cast<int>(points.size());
  constexpr int FewestPoints = 20;
  if (count < FewestPoints)
  {
    return false;
  }
  // Knots at the points' quantiles, 3 and 2 points a span: knots uniform in
  // u leave the spans of widely spaced points with one point or none (a clean
  // spiral from a tight centre), whose fit fails and made the points look noisy.
  auto score = [&](int knots) -> std::optional<double> {
    const auto fit = QuinticFit::solve(points, u, quantileKnots(u, closed ? knots + 1 : knots), closed);
    if (!fit)
    {
      return std::nullopt;
    }
    return gcvScore(fit->residual(points, u), count, knots, closed);
  };
  const auto fewer = score(count / 3);
  const auto more = score(count / 2);
  return fewer && more && *fewer < *more; // no verdict where a fit fails
}

namespace
{
/// The span of each of the first `count` parameters u and the two hat
/// functions of L*'s vertices on it, passed to visit(vertex, vertex, hat, hat).
template <class Visit>
void forEachHatPair(const std::vector<double>& u, size_t count, const std::vector<double>& knots,
  bool closed, const Visit& visit)
{
  const int spans = static_cast<int>(knots.size()) - 1;
  const int vertices = closed ? spans : spans + 1; // a closed polygon's last vertex is its first
  for (size_t j = 0; j < count; ++j)
  {
    const double t = u[j];
    const int span = std::clamp(
      static_cast<int>(std::upper_bound(knots.begin(), knots.end(), t) - knots.begin()) - 1, 0,
      spans - 1);
    const double w = (t - knots[span]) / (knots[span + 1] - knots[span]);
    visit(span, (span + 1) % vertices, 1.0 - w, w);
  }
}

/// A symmetric positive definite tridiagonal matrix (diagonal d, off-diagonal
/// e) as L D L^T, L unit lower bidiagonal with subdiagonal l.
struct TridiagonalLDL
{
  std::vector<double> D, L;

  TridiagonalLDL(const std::vector<double>& d, const std::vector<double>& e)
    : D(d)
    , L(e.size())
  {
    for (size_t i = 0; i < e.size(); ++i)
    {
      this->L[i] = e[i] / this->D[i];
      this->D[i + 1] -= this->L[i] * e[i];
    }
    if (!std::all_of(this->D.begin(), this->D.end(), [](double pivot) { return pivot > 0.0; }))
    {
      throw std::runtime_error("a vertex of the least-squares polygon rests on no point");
    }
  }

  /// The diagonal of the inverse (Takahashi's recurrence: Z_ii = 1 / D_i + l_i^2 Z_{i+1,i+1}).
  std::vector<double> inverseDiagonal() const
  {
    std::vector<double> z(this->D.size());
    z.back() = 1.0 / this->D.back();
    for (size_t i = this->L.size(); i-- > 0;)
    {
      z[i] = 1.0 / this->D[i] + this->L[i] * this->L[i] * z[i + 1];
    }
    return z;
  }

  /// The inverse's column `column`.
  std::vector<double> solveUnit(size_t column) const
  {
    std::vector<double> x(this->D.size(), 0.0);
    x[column] = 1.0;
    for (size_t i = 0; i < this->L.size(); ++i)
    {
      x[i + 1] -= this->L[i] * x[i];
    }
    for (size_t i = 0; i < x.size(); ++i)
    {
      x[i] /= this->D[i];
    }
    for (size_t i = this->L.size(); i-- > 0;)
    {
      x[i] -= this->L[i] * x[i + 1];
    }
    return x;
  }
};
} // namespace

std::vector<Vec3> leastSquaresPolygon(const std::vector<Vec3>& points,
  const std::vector<double>& u, const std::vector<double>& knots, bool closed)
{
  const int spans = static_cast<int>(knots.size()) - 1;
  const int k = closed ? spans : spans + 1; // a closed polygon's last vertex is its first
  NormalEquations normal(k);
  size_t j = 0;
  forEachHatPair(u, points.size(), knots, closed, [&](int a, int b, double hatA, double hatB) {
    const int vertex[2] = { a, b };
    const double hat[2] = { hatA, hatB };
    normal.add(vertex, hat, 2, points[j++]);
  });
  const Eigen::MatrixX3d solution = normal.solve();
  std::vector<Vec3> vertices(k);
  for (int i = 0; i < k; ++i)
  {
    vertices[i] = solution.row(i).transpose();
  }
  return vertices;
}

std::vector<double> leastSquaresPolygonNoise(const std::vector<Vec3>& points,
  const std::vector<double>& u, const std::vector<double>& knots, bool closed)
{
  const int spans = static_cast<int>(knots.size()) - 1;
  const int k = closed ? spans : spans + 1;
  // The normal matrix H = A^T A of the hat functions: tridiagonal, and for a
  // closed polygon one more entry, `corner`, joining its last vertex to its first.
  std::vector<double> diagonal(k, 0.0), off(k - 1, 0.0);
  double corner = 0.0;
  forEachHatPair(u, points.size(), knots, closed, [&](int a, int b, double hatA, double hatB) {
    diagonal[a] += hatA * hatA;
    diagonal[b] += hatB * hatB;
    (b == a + 1 ? off[a] : corner) += hatA * hatB;
  });
  const TridiagonalLDL open(diagonal, off);
  std::vector<double> variance = open.inverseDiagonal();
  if (corner != 0.0)
  {
    // H = T + U C U^T, U = [e_0, e_last], C = [0 c; c 0] (Woodbury):
    // diag(H^-1) = diag(T^-1) - y_i^T (I + C W)^-1 C y_i, y_i row i of T^-1 U, W = U^T T^-1 U.
    const std::vector<double> first = open.solveUnit(0), last = open.solveUnit(k - 1);
    Eigen::Matrix2d c;
    c << 0.0, corner, corner, 0.0;
    Eigen::Matrix2d w;
    w << first[0], first[k - 1], last[0], last[k - 1];
    const Eigen::Matrix2d s = (Eigen::Matrix2d::Identity() + c * w).inverse() * c;
    for (int i = 0; i < k; ++i)
    {
      const Eigen::Vector2d y(first[i], last[i]);
      variance[i] -= y.dot(s * y);
    }
  }
  std::vector<double> noise(k);
  std::transform(variance.begin(), variance.end(), noise.begin(),
    [](double v) { return std::sqrt(std::max(v, 0.0)); });
  return noise;
}

ReferencePolygon referencePolygon(const ExtendedData& data, bool closed, double pointNoise)
{
  ReferencePolygon reference;
  reference.Whole = leastSquaresPolygon(data.Points, data.Parameters, data.Knots, closed);
  const std::vector<double> noise = leastSquaresPolygonNoise(data.Points, data.Parameters, data.Knots, closed);
  const int spans = static_cast<int>(data.Knots.size()) - 1 - 2 * data.Extra;
  const int vertices = closed ? spans : spans + 1;
  reference.Polygon.Points.assign(
    reference.Whole.begin() + data.Extra, reference.Whole.begin() + data.Extra + vertices);
  reference.Polygon.Closed = closed;
  for (int i = 0; i < vertices; ++i)
  {
    reference.VertexNoise.push_back(pointNoise * noise[data.Extra + i]);
  }
  return reference;
}
} // namespace shapesplines
