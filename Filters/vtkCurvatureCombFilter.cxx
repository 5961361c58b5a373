#include "vtkCurvatureCombFilter.h"

#include "ArrayNames.h"
#include "LineCells.h"
#include "OutputArrays.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <utility>
#include <vector>

namespace names = shapesplines::names;

vtkStandardNewMacro(vtkCurvatureCombFilter);

namespace
{
/// The samples of one line that carry a tooth, and whether the line is closed.
struct CombLine
{
  std::vector<vtkIdType> Teeth;
  bool Closed = false;
};

std::vector<CombLine> ToothSamples(const std::vector<shapesplines::LineCell>& cells, int stride)
{
  std::vector<CombLine> result;
  for (const auto& cell : cells)
  {
    const vtkIdType* ids = cell.PointIds.data();
    const auto n = static_cast<vtkIdType>(cell.PointIds.size());
    CombLine line;
    // Closed curves repeat their first point at the end of the cell.
    line.Closed = n > 2 && ids[0] == ids[n - 1];
    const vtkIdType count = line.Closed ? n - 1 : n;
    for (vtkIdType k = 0; k < count; k += stride)
    {
      line.Teeth.push_back(ids[k]);
    }
    if (count > 0 && !line.Closed && (count - 1) % stride != 0)
    {
      line.Teeth.push_back(ids[count - 1]);
    }
    result.push_back(std::move(line));
  }
  return result;
}

/// The automatic scale follows the 95th percentile tooth, not the longest:
/// one spike (a near-corner, the noise at an end) would shrink all others.
double TypicalToothValue(const std::vector<CombLine>& lines, vtkDataArray* values)
{
  std::vector<double> teethValues;
  for (const CombLine& line : lines)
  {
    for (const vtkIdType id : line.Teeth)
    {
      teethValues.push_back(values->GetComponent(id, 0));
    }
  }
  return shapesplines::typicalMagnitude(teethValues);
}

/// The comb's geometry: a two-point cell per tooth (CombPart 0), then an
/// envelope per line (CombPart 1).
struct Comb
{
  vtkNew<vtkPoints> Points;
  vtkNew<vtkDoubleArray> Value;
  vtkNew<vtkCellArray> Cells;
  vtkNew<vtkUnsignedCharArray> Part;
  std::vector<std::vector<vtkIdType>> Tips; ///< of each line's teeth

  Comb()
  {
    this->Points->SetDataTypeToDouble();
    this->Value->SetName(names::CombValue);
    this->Part->SetName(names::CombPart);
  }
};

/// Draws the teeth of every line; a tooth whose length or direction is not
/// finite is drawn with zero length and value. Returns how many were.
vtkIdType DrawTeeth(const std::vector<CombLine>& lines, vtkPolyData* input, vtkDataArray* values,
  vtkDataArray* directions, double scale, bool torsionComb, Comb& comb)
{
  vtkIdType undefined = 0;
  comb.Tips.resize(lines.size());
  for (size_t l = 0; l < lines.size(); ++l)
  {
    for (const vtkIdType id : lines[l].Teeth)
    {
      double base[3], direction[3], tip[3];
      input->GetPoint(id, base);
      directions->GetTuple(id, direction);
      double value = values->GetComponent(id, 0);
      // Curvature points to the centre of curvature; the comb points away from it.
      const double sign = torsionComb ? 1.0 : -1.0;
      const double length = sign * scale * value;
      const bool defined = std::isfinite(length) && std::isfinite(direction[0]) &&
        std::isfinite(direction[1]) && std::isfinite(direction[2]);
      if (!defined)
      {
        ++undefined;
        value = 0.0;
      }
      for (int c = 0; c < 3; ++c)
      {
        tip[c] = defined ? base[c] + length * direction[c] : base[c];
      }
      const vtkIdType tooth[2] = { comb.Points->InsertNextPoint(base),
        comb.Points->InsertNextPoint(tip) };
      comb.Value->InsertNextValue(value);
      comb.Value->InsertNextValue(value);
      comb.Cells->InsertNextCell(2, tooth);
      comb.Part->InsertNextValue(0);
      comb.Tips[l].push_back(tooth[1]);
    }
  }
  return undefined;
}

/// Joins the tips of each line's teeth (closed lines' back to their first).
void DrawEnvelopes(const std::vector<CombLine>& lines, Comb& comb)
{
  for (size_t l = 0; l < lines.size(); ++l)
  {
    std::vector<vtkIdType> envelope = comb.Tips[l];
    if (lines[l].Closed && !envelope.empty())
    {
      envelope.push_back(envelope.front());
    }
    if (envelope.size() >= 2)
    {
      comb.Cells->InsertNextCell(static_cast<vtkIdType>(envelope.size()), envelope.data());
      comb.Part->InsertNextValue(1);
    }
  }
}
} // namespace

vtkCurvatureCombFilter::vtkCurvatureCombFilter() = default;
vtkCurvatureCombFilter::~vtkCurvatureCombFilter() = default;

int vtkCurvatureCombFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  int status = 1;
  vtkPolyData* input = shapesplines::polyDataInput(this, inputVector[0], output, status);
  if (!input)
  {
    return status;
  }
  if (std::isnan(this->ScaleFactor) || std::isnan(this->RelativeToothLength))
  {
    vtkErrorMacro("ScaleFactor and RelativeToothLength must not be NaN: no comb made.");
    return 1;
  }
  if (input->GetNumberOfLines() == 0)
  {
    vtkWarningMacro("Input has no lines: the comb is empty.");
    return 1;
  }
  const bool torsionComb = this->CombType == TORSION;
  const char* valueName = torsionComb ? names::Torsion : names::Curvature;
  const char* directionName = torsionComb ? names::Binormal : names::Normal;
  vtkDataArray* values = input->GetPointData()->GetArray(valueName);
  vtkDataArray* directions = input->GetPointData()->GetArray(directionName);
  const vtkIdType points = input->GetNumberOfPoints();
  if (!values || values->GetNumberOfComponents() != 1 || !directions ||
    directions->GetNumberOfComponents() != 3 || values->GetNumberOfTuples() != points ||
    directions->GetNumberOfTuples() != points)
  {
    vtkErrorMacro("Input needs the point arrays "
      << valueName << " (1 component) and " << directionName
      << " (3 components), one tuple per point, as the ShapeSplines curve filters write them.");
    return 1;
  }

  const auto inputLines = shapesplines::lineCells(input);
  for (const auto& cell : inputLines)
  {
    if (!cell.Error.empty())
    {
      vtkErrorMacro("Line (cell " << cell.CellId << ") skipped: " << cell.Error << ".");
    }
  }
  const std::vector<CombLine> lines = ToothSamples(inputLines, this->Stride);
  const double scale = this->ToothScale(TypicalToothValue(lines, values), input->GetLength());

  Comb comb;
  const vtkIdType undefined =
    DrawTeeth(lines, input, values, directions, scale, torsionComb, comb);
  if (this->Envelope)
  {
    DrawEnvelopes(lines, comb);
  }
  if (undefined > 0)
  {
    vtkWarningMacro(<< undefined << " teeth with a non-finite " << valueName << " or "
                    << directionName << " drawn with zero length.");
  }

  output->SetPoints(comb.Points);
  output->SetLines(comb.Cells);
  output->GetPointData()->AddArray(comb.Value);
  output->GetPointData()->SetActiveScalars(names::CombValue);
  output->GetCellData()->AddArray(comb.Part);
  vtkNew<vtkDoubleArray> scaleUsed;
  scaleUsed->SetName(names::CombScale);
  scaleUsed->InsertNextValue(scale);
  output->GetFieldData()->AddArray(scaleUsed);
  return 1;
}

double vtkCurvatureCombFilter::ToothScale(double typicalValue, double diagonal) const
{
  if (this->ScaleMode != AUTOMATIC)
  {
    return this->ScaleFactor;
  }
  return typicalValue > 0.0 && std::isfinite(diagonal)
    ? this->RelativeToothLength * diagonal / typicalValue
    : 0.0;
}

void vtkCurvatureCombFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CombType: " << (this->CombType == TORSION ? "Torsion" : "Curvature") << "\n";
  os << indent << "ScaleMode: " << (this->ScaleMode == FIXED ? "Fixed" : "Automatic") << "\n";
  os << indent << "RelativeToothLength: " << this->RelativeToothLength << "\n";
  os << indent << "ScaleFactor: " << this->ScaleFactor << "\n";
  os << indent << "Stride: " << this->Stride << "\n";
  os << indent << "Envelope: " << (this->Envelope ? "On" : "Off") << "\n";
}
