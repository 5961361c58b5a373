#include "vtkQQRSplineFilter.h"

#include "QQRSpline.h"

#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkQQRSplineFilter);

vtkQQRSplineFilter::vtkQQRSplineFilter() = default;
vtkQQRSplineFilter::~vtkQQRSplineFilter()
{
  this->SetZArrayName(nullptr);
}

const char* vtkQQRSplineFilter::GetPointValuesArrayName()
{
  return this->ZArrayName;
}

const char* vtkQQRSplineFilter::GetModeAsString()
{
  switch (this->Mode)
  {
    case APPROXIMATE:
      return "Approximate";
    case LOCAL_INTERPOLATION:
      return "LocalInterpolation";
    default:
      return "Interpolate";
  }
}

int vtkQQRSplineFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* output)
{
  if (this->Continuity == C2_FC && this->Mode != APPROXIMATE)
  {
    vtkWarningMacro("Continuity C2_FC needs x = y = 0 on the control polygon (Mode Approximate): "
                    "using C2.");
  }
  if (std::min(this->Alpha, this->Beta) <= 3.0)
  {
    vtkWarningMacro("Alpha and Beta at or below 3: the qqr basis is not positive there and the "
                    "joins are not C2 (the paper's Theorems 1 and 8 need more than 3).");
  }
  else if (std::min(this->Alpha, this->Beta) < 4.0)
  {
    vtkWarningMacro("Alpha or Beta below 4: the third derivative, and so the torsion, is "
                    "unbounded at the knots.");
  }
  if (this->Automatic && this->MaxAlpha < std::max(this->Alpha, this->Beta))
  {
    vtkWarningMacro("MaxAlpha " << this->MaxAlpha << " is below Alpha/Beta: the automatic mode "
                                << "cannot raise the exponents.");
  }
  return this->Superclass::RequestData(request, inputs, output);
}

shapesplines::BuiltCurve vtkQQRSplineFilter::BuildCurve(
  const shapesplines::FitContext& context) const
{
  shapesplines::QQROptions options;
  options.Construction = this->Mode == APPROXIMATE ? shapesplines::QQRConstruction::ControlPolygon
    : this->Mode == LOCAL_INTERPOLATION           ? shapesplines::QQRConstruction::LocalInterpolation
                                                  : shapesplines::QQRConstruction::Interpolation;
  options.Automatic = this->Automatic;
  options.Alpha = this->Alpha;
  options.Beta = this->Beta;
  options.MaxAlpha = std::max({ this->MaxAlpha, this->Alpha, this->Beta });
  if (this->LocalParameters == CUSTOM)
  {
    // X and Y shape the control polygon's curve; an interpolation keeps its
    // own (applied to it, X = 1 swung a 20-point helix out to 6e6 times its size).
    if (this->Mode == APPROXIMATE)
    {
      options.X = this->X;
      options.Y = this->Y;
    }
    options.Z = this->Z;
  }
  if (this->Continuity == C2_FC && this->Mode == APPROXIMATE)
  {
    // Theorem 13: x = y = 0 and alpha = beta >= l + 3.
    options.X = 0.0;
    options.Y = 0.0;
    const double exponent = std::max({ this->Alpha, this->Beta, this->FrenetOrder + 3.0 });
    options.Alpha = exponent;
    options.Beta = exponent;
    options.MaxAlpha = std::max(options.MaxAlpha, exponent);
  }
  return shapesplines::qqrBuilder(options)(context);
}

void vtkQQRSplineFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->GetModeAsString() << "\n";
  os << indent << "Automatic: " << (this->Automatic ? "On" : "Off") << "\n";
  os << indent << "Alpha: " << this->Alpha << "\n";
  os << indent << "Beta: " << this->Beta << "\n";
  os << indent << "MaxAlpha: " << this->MaxAlpha << "\n";
  os << indent << "LocalParameters: " << (this->LocalParameters == CUSTOM ? "Custom" : "Paper")
     << "\n";
  os << indent << "X: " << this->X << "\n";
  os << indent << "Y: " << this->Y << "\n";
  os << indent << "Z: " << this->Z << "\n";
  os << indent << "Continuity: " << (this->Continuity == C2_FC ? "C2_FC" : "C2") << "\n";
  os << indent << "FrenetOrder: " << this->FrenetOrder << "\n";
  os << indent << "ZArrayName: " << (this->ZArrayName ? this->ZArrayName : "(none)") << "\n";
}
