#include "vtkVariableDegreeSplineFilter.h"

#include "VariableDegreeSpline.h"

#include "vtkObjectFactory.h"


vtkStandardNewMacro(vtkVariableDegreeSplineFilter);

vtkVariableDegreeSplineFilter::vtkVariableDegreeSplineFilter() = default;
vtkVariableDegreeSplineFilter::~vtkVariableDegreeSplineFilter()
{
  this->SetDegreeArrayName(nullptr);
}

const char* vtkVariableDegreeSplineFilter::GetModeAsString()
{
  switch (this->Mode)
  {
    case APPROXIMATE_GLOBAL:
      return "ApproximateGlobal";
    case APPROXIMATE_LOCAL:
      return "ApproximateLocal";
    default:
      return "Interpolate";
  }
}

int vtkVariableDegreeSplineFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* output)
{
  if (this->Automatic && this->MaxDegree < this->Degree)
  {
    vtkWarningMacro("MaxDegree " << this->MaxDegree << " is below Degree " << this->Degree
                                 << ": the automatic mode cannot raise the degrees.");
  }
  if (this->Mode != INTERPOLATE && this->GetPointValuesArrayInUse())
  {
    vtkWarningMacro("DegreeArrayName is used by interpolation only; the approximation starts "
                    "every knot from Degree.");
  }
  return this->Superclass::RequestData(request, inputs, output);
}

const char* vtkVariableDegreeSplineFilter::GetPointValuesArrayName()
{
  return this->DegreeArrayName;
}

shapesplines::BuiltCurve vtkVariableDegreeSplineFilter::BuildCurve(
  const shapesplines::FitContext& context) const
{
  shapesplines::VariableDegreeOptions options;
  options.Mode = static_cast<shapesplines::VariableDegreeMode>(this->Mode);
  options.Ends = static_cast<shapesplines::VariableDegreeEnds>(this->EndCondition);
  options.Automatic = this->Automatic;
  options.Degree = this->Degree;
  options.MaxDegree = this->MaxDegree;
  options.Lambda = this->Lambda;
  options.ScaleLambdaWithDegree = this->ScaleLambdaWithDegree;
  options.ApproximationKnots = this->Mode == INTERPOLATE ? 0 : ApproximationKnotCount(this->NumberOfKnots);
  options.CorrectParameters = this->CorrectParameters;
  return shapesplines::variableDegreeBuilder(options)(context);
}

void vtkVariableDegreeSplineFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->GetModeAsString() << "\n";
  os << indent << "NumberOfKnots: " << this->NumberOfKnots << "\n";
  os << indent << "Automatic: " << (this->Automatic ? "On" : "Off") << "\n";
  os << indent << "Degree: " << this->Degree << "\n";
  os << indent << "MaxDegree: " << this->MaxDegree << "\n";
  os << indent << "Lambda: " << this->Lambda << "\n";
  os << indent << "ScaleLambdaWithDegree: " << (this->ScaleLambdaWithDegree ? "On" : "Off")
     << "\n";
  const char* ends[] = { "Natural", "Clamped", "Polynomial" };
  os << indent << "EndCondition: " << ends[this->EndCondition] << "\n";
  os << indent << "DegreeArrayName: "
     << (this->DegreeArrayName ? this->DegreeArrayName : "(none)") << "\n";
}
