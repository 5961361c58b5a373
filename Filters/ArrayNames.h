// The names of the arrays the ShapeSplines filters write, spelled once for the
// filters and the command line. Python reads the same strings from
// shapesplines.names, which Filters/Python/ArrayNames.cmake generates from this
// file: declare each name in one of the two forms used below.
#ifndef shapesplines_ArrayNames_h
#define shapesplines_ArrayNames_h

#include <array>

namespace shapesplines::names
{
// Point arrays of every curve.
constexpr const char* Curvature = "Curvature";
constexpr const char* Torsion = "Torsion";
constexpr const char* Tangent = "Tangent";
constexpr const char* Normal = "Normal";
constexpr const char* Binormal = "Binormal";
constexpr const char* Parameter = "Parameter";
constexpr const char* ArcLength = "ArcLength";
constexpr const char* SpanIndex = "SpanIndex";

// Cell arrays of every curve (one value per line).
constexpr const char* ShapePreserving = "ShapePreserving";
constexpr const char* ShapeViolations = "ShapeViolations";
constexpr const char* Length = "Length";
constexpr const char* Tortuosity = "Tortuosity";
constexpr const char* ConditionEstimate = "ConditionEstimate";
constexpr const char* NumberOfKnots = "NumberOfKnots";
constexpr const char* NoiseLevel = "NoiseLevel";
constexpr const char* PolygonDeviation = "PolygonDeviation";
constexpr const char* MergedPoints = "MergedPoints";
constexpr const char* LineId = "LineId";

// Field data of every curve.
constexpr const char* TorsionColorRange = "TorsionColorRange";

// Polyline Shape Analysis.
constexpr const char* DiscreteCurvature = "DiscreteCurvature";
constexpr const char* DiscreteTorsion = "DiscreteTorsion";
constexpr const char* DiscreteBinormal = "DiscreteBinormal";
constexpr const char* Collinear = "Collinear";
constexpr const char* Convex = "Convex";
constexpr const char* Coplanar = "Coplanar";
constexpr const char* ViolationMask = "ViolationMask";
/// Violations per criterion, in the order of shapesplines::ShapeCriterion.
constexpr std::array<const char*, 6> CriterionViolations = { "CollinearityViolations",
  "ConvexityAtKnotViolations", "ConvexityOnSpanViolations", "CoplanarityViolations",
  "TorsionSignAtKnotViolations", "TorsionSignOnSpanViolations" };

// Curvature Comb.
constexpr const char* CombValue = "CombValue";
constexpr const char* CombPart = "CombPart";
constexpr const char* CombScale = "CombScale";
} // namespace shapesplines::names

#endif
