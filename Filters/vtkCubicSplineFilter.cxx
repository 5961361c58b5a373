#include "vtkCubicSplineFilter.h"

#include "CubicSpline.h"
#include "FitPolyline.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkCubicSplineFilter);

vtkCubicSplineFilter::vtkCubicSplineFilter() = default;
vtkCubicSplineFilter::~vtkCubicSplineFilter() = default;

const char* vtkCubicSplineFilter::GetEndConditionAsString()
{
  switch (this->EndCondition)
  {
    case NATURAL:
      return "Natural";
    case CLAMPED:
      return "Clamped";
    default:
      return "NotAKnot";
  }
}

shapesplines::BuiltCurve vtkCubicSplineFilter::BuildCurve(
  const shapesplines::FitContext& context) const
{
  shapesplines::BuiltCurve built;
  built.Spline = std::make_unique<shapesplines::CubicSpline>(
    shapesplines::CubicSpline::interpolate(context.Data.Points, context.Knots, context.Data.Closed,
      static_cast<shapesplines::CubicEndCondition>(this->EndCondition)));
  return built;
}

void vtkCubicSplineFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EndCondition: " << this->GetEndConditionAsString() << "\n";
}
