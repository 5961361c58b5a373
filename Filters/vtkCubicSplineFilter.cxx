#include "vtkCubicSplineFilter.h"

#include "CubicSpline.h"
#include "Parameterization.h"

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

std::unique_ptr<shapesplines::Curve> vtkCubicSplineFilter::BuildCurve(
  const shapesplines::CleanPolyline& data, const std::vector<double>& knots) const
{
  return std::make_unique<shapesplines::CubicSpline>(shapesplines::CubicSpline::interpolate(
    data.Points, knots, data.Closed, static_cast<shapesplines::CubicEndCondition>(this->EndCondition)));
}

void vtkCubicSplineFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EndCondition: " << this->GetEndConditionAsString() << "\n";
}
