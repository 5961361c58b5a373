// ShapeSplines math core: curvature, torsion and the Frenet frame, written once.
#ifndef shapesplines_FrenetFrame_h
#define shapesplines_FrenetFrame_h

#include "Curve.h"

#include <vector>

namespace shapesplines
{
struct FrenetFrame
{
  Vec3 Tangent = Vec3::UnitX();
  Vec3 Normal = Vec3::UnitY();
  Vec3 Binormal = Vec3::UnitZ();
  double Curvature = 0.0; ///< |s' x s''| / |s'|^3
  double Torsion = 0.0;   ///< det(s', s'', s''') / |s' x s''|^2, signed
};

/**
 * What a run of samples framed on its own needs of the rest of its curve to
 * get the frames of the whole curve framed at once: the last tangent and
 * normal of the samples just before it; or, when the curve's first samples
 * have no normal (see frenetFrames) and the run is among them, the first
 * normal after it, which the run's normals are transported back from.
 */
struct FrameNeighbours
{
  const Vec3* PreviousTangent = nullptr;
  const Vec3* PreviousNormal = nullptr;
  const Vec3* NextNormal = nullptr;
};

/**
 * Frenet frames along a sequence of samples (derivatives 1..3 used). The
 * curvature is always the curve's own; where it is at or below flatCurvature[k]
 * (within rounding of zero) the Frenet normal is undefined: the torsion is 0
 * and the normal is carried by parallel transport from the nearest sample
 * where it is defined, so frames stay continuous and finite. previousNormal,
 * the last normal of the samples just before these, continues a curve's frames
 * piece by piece.
 */
std::vector<FrenetFrame> frenetFrames(const std::vector<Derivatives>& samples,
  const std::vector<double>& flatCurvature, const Vec3* previousNormal = nullptr);

/// The same into frames, reusing its storage (a caller framing many short
/// runs), with the run's neighbours on its curve.
void frenetFrames(const std::vector<Derivatives>& samples, const std::vector<double>& flatCurvature,
  std::vector<FrenetFrame>& frames, const FrameNeighbours& neighbours = {});

/// The same with one threshold for every sample.
std::vector<FrenetFrame> frenetFrames(const std::vector<Derivatives>& samples, double flatCurvature);

/// |s' x s''| / |s'|^3; 0 where s' = 0 or the value is not finite.
double curvature(const Vec3& first, const Vec3& second);
} // namespace shapesplines

#endif
