#include "Parameterization.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shapesplines
{
Vec3 CleanPolyline::segment(int i) const
{
  const int n = static_cast<int>(this->Points.size());
  return this->Points[(i + 1) % n] - this->Points[i];
}

double CleanPolyline::length() const
{
  double total = 0.0;
  for (int i = 0; i < this->numberOfSpans(); ++i)
  {
    total += this->segment(i).norm();
  }
  return total;
}

std::pair<Vec3, Vec3> boundingBox(const std::vector<Vec3>& points)
{
  Vec3 lo = points.front();
  Vec3 hi = points.front();
  for (const Vec3& p : points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return { lo, hi };
}

double boundingBoxDiagonal(const std::vector<Vec3>& points)
{
  if (points.empty())
  {
    return 0.0;
  }
  const auto [lo, hi] = boundingBox(points);
  return (hi - lo).stableNorm(); // no overflow for coordinates of 1e160
}

namespace
{
/**
 * Drops a point whose segment to its predecessor is under NearRepeatRatio of
 * every neighbouring segment (the line's last point stays; its predecessor
 * goes): a streamline stalling, a coordinate round trip. Such a segment's
 * direction is noise, and a smooth curve through it turns within it: on a
 * helix, a point 1e-10 of a segment from its neighbour made the quintic's,
 * qqr's and the variable degree spline's curvature 1e5 times the helix's
 * (1e-8: 80-300 times, still within the automatic modes' bounds).
 */
void mergeNearRepeats(CleanPolyline& line)
{
  constexpr double NearRepeatRatio = 1e-8;
  const int n = static_cast<int>(line.Points.size());
  if (n < 3)
  {
    return;
  }
  auto length = [&](int k) { return (line.Points[k + 1] - line.Points[k]).stableNorm(); };
  std::vector<char> drop(n, 0);
  for (int k = 0; k + 1 < n; ++k)
  {
    double neighbours = std::numeric_limits<double>::infinity();
    for (const int other : { k - 1, k + 1 })
    {
      if (other >= 0 && other + 1 < n)
      {
        neighbours = std::min(neighbours, length(other));
      }
    }
    if (length(k) <= NearRepeatRatio * neighbours)
    {
      drop[k + 1 < n - 1 ? k + 1 : k] = 1;
    }
  }
  std::vector<Vec3> points;
  std::vector<int> sources;
  for (int k = 0; k < n; ++k)
  {
    if (drop[k])
    {
      ++line.MergedPoints;
      continue;
    }
    points.push_back(line.Points[k]);
    sources.push_back(line.SourceIndex[k]);
  }
  line.Points = std::move(points);
  line.SourceIndex = std::move(sources);
}
} // namespace

CleanPolyline cleanPolyline(
  const std::vector<Vec3>& points, bool forceClosed, double relativeTolerance)
{
  CleanPolyline line;
  const double tolerance = relativeTolerance * boundingBoxDiagonal(points);
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
  {
    if (!line.Points.empty() && (points[i] - line.Points.back()).stableNorm() <= tolerance)
    {
      ++line.MergedPoints;
      continue;
    }
    line.Points.push_back(points[i]);
    line.SourceIndex.push_back(i);
  }
  mergeNearRepeats(line);
  const bool seamRepeated =
    line.Points.size() > 1 && (line.Points.back() - line.Points.front()).stableNorm() <= tolerance;
  if (seamRepeated)
  {
    line.Points.pop_back();
    line.SourceIndex.pop_back();
  }
  // A closed curve needs at least three distinct points to enclose anything.
  line.Closed = (forceClosed || seamRepeated) && line.Points.size() >= 3;
  if (seamRepeated && !line.Closed)
  {
    // Too few points to close: keep the seam point so the line is unchanged.
    line.Points.push_back(points.back());
    line.SourceIndex.push_back(static_cast<int>(points.size()) - 1);
  }
  return line;
}

std::vector<double> computeKnots(const CleanPolyline& line, Parameterization kind)
{
  const int spans = line.numberOfSpans();
  std::vector<double> knots(spans + 1, 0.0);
  for (int i = 0; i < spans; ++i)
  {
    const double chord = line.segment(i).stableNorm();
    double step = 1.0;
    if (kind == Parameterization::ChordLength)
    {
      step = chord;
    }
    else if (kind == Parameterization::Centripetal)
    {
      step = std::sqrt(chord);
    }
    knots[i + 1] = knots[i] + step;
  }
  return knots;
}
} // namespace shapesplines
