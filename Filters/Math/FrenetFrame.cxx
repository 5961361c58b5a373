#include "FrenetFrame.h"

#include <cmath>

namespace shapesplines
{
namespace
{
/// Whether a norm taken by squaring is exact: its squares neither under- nor overflowed.
bool squaredExactly(double norm)
{
  return norm > 1e-140 && norm < 1e140;
}

/// |v|, also where squaring under- or overflows (derivatives at a hairpin of a
/// line 1e-100 wide): the fast norm where it is exact, stableNorm elsewhere.
double robustNorm(const Vec3& v)
{
  const double fast = v.norm();
  return squaredExactly(fast) ? fast : v.stableNorm();
}

/// v / |v| of unit length even for subnormal v: scaled by its largest component first.
Vec3 unitVector(const Vec3& v)
{
  const Vec3 scaled = v / v.cwiseAbs().maxCoeff();
  return scaled / scaled.norm();
}

/// v / |v| given robustNorm(v): the division alone where squaring was exact.
Vec3 unitVector(const Vec3& v, double norm)
{
  return squaredExactly(norm) ? Vec3(v / norm) : unitVector(v);
}

/// A unit vector orthogonal to unit t, from the coordinate axis least aligned with it.
Vec3 anyNormal(const Vec3& t)
{
  int axis = 0;
  t.cwiseAbs().minCoeff(&axis);
  Vec3 n = Vec3::Unit(axis) - t[axis] * t;
  return n.normalized();
}

/// Transports a normal to a new tangent: remove its tangential part.
Vec3 transport(const Vec3& normal, const Vec3& tangent)
{
  const Vec3 n = normal - normal.dot(tangent) * tangent;
  const double length = n.norm();
  return length > 1e-8 ? Vec3(n / length) : anyNormal(tangent);
}
} // namespace

double curvature(const Vec3& first, const Vec3& second)
{
  const double speed = robustNorm(first);
  const double value = speed > 0 ? robustNorm(first.cross(second)) / (speed * speed * speed) : 0.0;
  return std::isfinite(value) ? value : 0.0;
}

std::vector<FrenetFrame> frenetFrames(const std::vector<Derivatives>& samples, double flatCurvature)
{
  return frenetFrames(samples, std::vector<double>(samples.size(), flatCurvature));
}

std::vector<FrenetFrame> frenetFrames(const std::vector<Derivatives>& samples,
  const std::vector<double>& flatCurvature, const Vec3* previousNormal)
{
  std::vector<FrenetFrame> frames;
  frenetFrames(samples, flatCurvature, frames, FrameNeighbours{ nullptr, previousNormal });
  return frames;
}

void frenetFrames(const std::vector<Derivatives>& samples, const std::vector<double>& flatCurvature,
  std::vector<FrenetFrame>& frames, const FrameNeighbours& neighbours)
{
  const int n = static_cast<int>(samples.size());
  // Every field of every frame is written below: a block's frames are not
  // filled with defaults first (a pass over ~0.7 MB per block).
  frames.resize(n);
  // A sample's normal is defined where its curvature exceeds the flat one.
  auto defined = [&](int k) { return frames[k].Curvature > flatCurvature[k]; };

  Vec3 lastTangent = neighbours.PreviousTangent ? *neighbours.PreviousTangent : Vec3::UnitX();
  for (int k = 0; k < n; ++k)
  {
    const Vec3& d1 = samples[k][1];
    const Vec3& d2 = samples[k][2];
    const Vec3& d3 = samples[k][3];
    FrenetFrame& f = frames[k];
    const double speed = robustNorm(d1);
    // A stationary point (s' = 0) keeps the direction of s'', or the last tangent.
    if (speed > 0)
    {
      f.Tangent = unitVector(d1, speed);
    }
    else if (robustNorm(d2) > 0)
    {
      f.Tangent = unitVector(d2);
    }
    else
    {
      f.Tangent = lastTangent;
    }
    lastTangent = f.Tangent;
    const Vec3 cross = d1.cross(d2);
    const double crossNorm = robustNorm(cross);
    const double curvature = speed > 0 ? crossNorm / (speed * speed * speed) : 0.0;
    f.Curvature = std::isfinite(curvature) ? curvature : 0.0;
    f.Torsion = 0.0; // a flat sample's; its normal and binormal are transported below
    if (f.Curvature > flatCurvature[k])
    {
      // Orthonormalise against the tangent: near-parallel s', s'' round badly.
      const Vec3 normal = unitVector(cross, crossNorm).cross(f.Tangent);
      f.Normal = unitVector(normal, normal.norm());
      f.Binormal = f.Tangent.cross(f.Normal);
      f.Torsion = d1.dot(d2.cross(d3)) / (crossNorm * crossNorm);
    }
  }

  // Fill flat samples by transporting the nearest defined normal along the curve:
  // forwards from the previous normal (or the first defined sample), then
  // backwards before the first defined sample (or from the next normal) if
  // nothing came before.
  int first = 0;
  while (first < n && !defined(first))
  {
    ++first;
  }
  const bool continues = neighbours.PreviousNormal != nullptr;
  const bool fromNext = !continues && first == n && neighbours.NextNormal != nullptr;
  Vec3 normal = continues ? *neighbours.PreviousNormal
    : fromNext            ? *neighbours.NextNormal
                          : (first < n ? frames[first].Normal
                                       : anyNormal(n > 0 ? frames[0].Tangent : Vec3::UnitX()));
  auto fill = [&](int k) {
    if (defined(k))
    {
      normal = frames[k].Normal;
      return;
    }
    FrenetFrame& f = frames[k];
    f.Normal = transport(normal, f.Tangent);
    f.Binormal = f.Tangent.cross(f.Normal);
    normal = f.Normal;
  };
  const int forwardFrom = fromNext ? n : (continues || first == n ? 0 : first);
  for (int k = forwardFrom; k < n; ++k)
  {
    fill(k);
  }
  normal = forwardFrom > 0 && !fromNext ? frames[first].Normal : normal;
  for (int k = forwardFrom - 1; k >= 0; --k)
  {
    fill(k);
  }
}
} // namespace shapesplines
