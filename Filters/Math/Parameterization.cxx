#include "Parameterization.h"

#include <cmath>

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
