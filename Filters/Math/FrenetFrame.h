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
 * Frenet frames along a sequence of samples (derivatives 1..3 used). The
 * curvature is always the curve's own; where it is at or below flatCurvature[k]
 * (within rounding of zero) the Frenet normal is undefined: the torsion is 0
 * and the normal is carried by parallel transport from the nearest sample
 * where it is defined, so frames stay continuous and finite. previousNormal,
 * the last normal of the samples just before these, continues a curve's frames
 * piece by piece exactly as if they were computed in one go.
 */
std::vector<FrenetFrame> frenetFrames(const std::vector<Derivatives>& samples,
  const std::vector<double>& flatCurvature, const Vec3* previousNormal = nullptr);

/// The same into frames, reusing its storage (a caller framing many short runs).
void frenetFrames(const std::vector<Derivatives>& samples, const std::vector<double>& flatCurvature,
  std::vector<FrenetFrame>& frames, const Vec3* previousNormal = nullptr);

/// The same with one threshold for every sample.
std::vector<FrenetFrame> frenetFrames(const std::vector<Derivatives>& samples, double flatCurvature);
} // namespace shapesplines

#endif
