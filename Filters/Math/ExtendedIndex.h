// ShapeSplines math core: reading knots, spans and per-knot values beyond a
// curve's ends, written once for every family (a closed curve wraps around,
// an open one repeats or mirrors its end values).
#ifndef shapesplines_ExtendedIndex_h
#define shapesplines_ExtendedIndex_h

#include <algorithm>
#include <vector>

namespace shapesplines
{
/// a / n rounded towards minus infinity (n > 0).
constexpr int floorDiv(int a, int n)
{
  return a >= 0 ? a / n : -((-a + n - 1) / n);
}

/// a modulo n, in [0, n) (n > 0): an index on a closed curve.
constexpr int wrapIndex(int a, int n)
{
  return a - floorDiv(a, n) * n;
}

/// How an open curve reads an index beyond its ends.
enum class Beyond
{
  Clamp,          ///< the end entry again
  MirrorEntries,  ///< reflected about the end entry: -1 reads 1 (values at knots)
  MirrorIntervals ///< reflected about the end: -1 reads 0 (values on spans)
};

/**
 * Which of n entries index i reads: wrapped around a closed curve; beyond an
 * open curve's ends as `beyond` says, clamped to [0, n - 1] where a short
 * sequence cannot be mirrored far enough.
 */
constexpr int extendedIndex(int i, int n, bool closed, Beyond beyond = Beyond::Clamp)
{
  if (closed)
  {
    return wrapIndex(i, n);
  }
  const int last = n - 1;
  if (beyond == Beyond::MirrorEntries)
  {
    i = i < 0 ? -i : (i > last ? 2 * last - i : i);
  }
  else if (beyond == Beyond::MirrorIntervals)
  {
    i = i < 0 ? -1 - i : (i > last ? 2 * last + 1 - i : i);
  }
  return std::clamp(i, 0, last);
}

/**
 * Knot j of a closed curve whose knots t_0..t_n (t_n the seam again) are
 * continued by the period: t_(j + n) = t_j + (t_n - t_0). Knots 0..n are read
 * as they are, so the seam's value does not move by a rounding.
 */
inline double periodicKnot(const std::vector<double>& knots, int j)
{
  const int n = static_cast<int>(knots.size()) - 1;
  if (j >= 0 && j <= n)
  {
    return knots[j];
  }
  return knots[wrapIndex(j, n)] + floorDiv(j, n) * (knots[n] - knots[0]);
}
} // namespace shapesplines

#endif
