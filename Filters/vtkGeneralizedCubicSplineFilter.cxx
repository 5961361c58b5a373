#include "vtkGeneralizedCubicSplineFilter.h"

#include "GeneralizedCubicSpline.h"

#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkGeneralizedCubicSplineFilter);

vtkGeneralizedCubicSplineFilter::vtkGeneralizedCubicSplineFilter() = default;
vtkGeneralizedCubicSplineFilter::~vtkGeneralizedCubicSplineFilter()
{
  this->SetTensionArrayName(nullptr);
}

const char* vtkGeneralizedCubicSplineFilter::GetSpaceKindAsString()
{
  switch (this->SpaceKind)
  {
    case POLYNOMIAL:
      return "Polynomial";
    case TRIGONOMETRIC:
      return "Trigonometric";
    case VARIABLE_DEGREE:
      return "VariableDegree";
    default:
      return "Exponential";
  }
}

int vtkGeneralizedCubicSplineFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Settings the kinds cannot take are adapted, and the user told so, once per run.
  const auto kind = static_cast<shapesplines::SpaceKind>(this->SpaceKind);
  if (kind == shapesplines::SpaceKind::Trigonometric &&
    (this->Tension > shapesplines::largestTension(kind, this->Tension) ||
      (this->Automatic &&
        this->MaxTension > shapesplines::largestTension(kind, this->MaxTension))))
  {
    vtkWarningMacro("Trigonometric tension is limited to 0.99 pi (3.11).");
  }
  if (kind == shapesplines::SpaceKind::VariableDegree && this->Tension < 3.0)
  {
    vtkWarningMacro("VariableDegree: Tension is the degree, at least 3; using 3.");
  }
  if (this->Automatic && this->MaxTension < this->Tension)
  {
    vtkWarningMacro("MaxTension " << this->MaxTension << " is below Tension " << this->Tension
                                  << ": the automatic mode cannot raise the tension.");
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

const char* vtkGeneralizedCubicSplineFilter::GetPointValuesArrayName()
{
  return this->TensionArrayName;
}

shapesplines::BuiltCurve vtkGeneralizedCubicSplineFilter::BuildCurve(
  const shapesplines::FitContext& context) const
{
  shapesplines::GeneralizedCubicOptions options;
  options.Kind = static_cast<shapesplines::SpaceKind>(this->SpaceKind);
  options.Automatic = this->Automatic;
  options.Tension = this->Tension;
  options.MaxTension = std::max(this->MaxTension, this->Tension);
  options.Ends = static_cast<shapesplines::GeneralizedCubicEnds>(this->EndCondition);
  return shapesplines::generalizedCubicBuilder(options)(context);
}

void vtkGeneralizedCubicSplineFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SpaceKind: " << this->GetSpaceKindAsString() << "\n";
  os << indent << "Automatic: " << (this->Automatic ? "On" : "Off") << "\n";
  os << indent << "Tension: " << this->Tension << "\n";
  os << indent << "MaxTension: " << this->MaxTension << "\n";
  os << indent << "EndCondition: "
     << (this->EndCondition == NATURAL_ENDS ? "Natural" : "Polynomial") << "\n";
  os << indent << "TensionArrayName: "
     << (this->TensionArrayName ? this->TensionArrayName : "(none)") << "\n";
}
