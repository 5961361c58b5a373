// ShapeSplines math core: cleaning a polyline and choosing its knot parameters.
#ifndef shapesplines_Parameterization_h
#define shapesplines_Parameterization_h

#include "Curve.h"

#include <utility>
#include <vector>

namespace shapesplines
{
enum class Parameterization
{
  Uniform,     ///< t_{i+1} - t_i = 1
  ChordLength, ///< t_{i+1} - t_i = |I_{i+1} - I_i|
  Centripetal  ///< t_{i+1} - t_i = sqrt(|I_{i+1} - I_i|)
};

/**
 * A polyline ready for fitting: consecutive repeated points merged, and for a
 * closed line the seam point stored once (the last span runs from the last
 * point back to the first).
 */
struct CleanPolyline
{
  std::vector<Vec3> Points;
  std::vector<int> SourceIndex; ///< index in the input of each kept point
  bool Closed = false;
  int MergedPoints = 0; ///< input points dropped as repeats of their predecessor

  int numberOfSpans() const
  {
    const int n = static_cast<int>(this->Points.size());
    return this->Closed ? n : n - 1;
  }
  /// I_{i+1} - I_i, with I_n = I_0 on a closed line.
  Vec3 segment(int i) const;
  /// The polyline's length (a closed line's includes the closing segment).
  double length() const;
};

/// Lowest and highest corner of the axis-aligned bounding box (points not empty).
std::pair<Vec3, Vec3> boundingBox(const std::vector<Vec3>& points);

/// Diagonal of the axis-aligned bounding box (0 for no or identical points).
double boundingBoxDiagonal(const std::vector<Vec3>& points);

/**
 * Merges points closer than relativeTolerance * bounding-box diagonal to their
 * predecessor, and points whose segment to their predecessor is under 1e-8 of
 * every neighbouring segment (near repeats, whose direction is noise). A line
 * is closed if forceClosed is set or its last point repeats its first; the
 * repeated seam point is dropped.
 */
CleanPolyline cleanPolyline(
  const std::vector<Vec3>& points, bool forceClosed, double relativeTolerance = 1e-12);

/// Knots t_0 = 0 < ... (one per span end; a closed line has numberOfPoints + 1 knots).
std::vector<double> computeKnots(const CleanPolyline& line, Parameterization kind);
} // namespace shapesplines

#endif
