#include "vtkTensionQuinticSplineFilter.h"

#include "TensionQuinticFit.h"

#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkTensionQuinticSplineFilter);

vtkTensionQuinticSplineFilter::vtkTensionQuinticSplineFilter() = default;
vtkTensionQuinticSplineFilter::~vtkTensionQuinticSplineFilter() = default;

const char* vtkTensionQuinticSplineFilter::GetContinuityAsString()
{
  return this->Continuity == C3 ? "C3" : "C4";
}

const char* vtkTensionQuinticSplineFilter::GetModeAsString()
{
  return this->Mode == APPROXIMATE ? "Approximate" : "Interpolate";
}

int vtkTensionQuinticSplineFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* output)
{
  if (!this->Automatic && this->Continuity == C4 && this->Gamma > 1.0)
  {
    vtkWarningMacro("Gamma " << this->Gamma << " is beyond the C4 range (0,1]: using 1.");
  }
  return this->Superclass::RequestData(request, inputs, output);
}

shapesplines::BuiltCurve vtkTensionQuinticSplineFilter::BuildCurve(
  const shapesplines::FitContext& context) const
{
  shapesplines::QuinticFitOptions quintic;
  quintic.Continuity =
    this->Continuity == C3 ? shapesplines::QuinticContinuity::C3 : shapesplines::QuinticContinuity::C4;
  quintic.Automatic = this->Automatic;
  quintic.Gamma = this->Continuity == C3 ? this->Gamma : std::min(this->Gamma, 1.0);
  quintic.Lambda = this->Lambda;
  quintic.ApproximationKnots = this->Mode == APPROXIMATE ? ApproximationKnotCount(this->NumberOfKnots) : 0;
  quintic.CorrectParameters = this->CorrectParameters;
  return shapesplines::tensionQuinticBuilder(quintic)(context);
}

void vtkTensionQuinticSplineFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Continuity: " << this->GetContinuityAsString() << "\n";
  os << indent << "Mode: " << this->GetModeAsString() << "\n";
  os << indent << "NumberOfKnots: " << this->NumberOfKnots << "\n";
  os << indent << "Automatic: " << (this->Automatic ? "On" : "Off") << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "Lambda: " << this->Lambda << "\n";
}
