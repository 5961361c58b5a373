#include "vtkCurvatureCombFilter.h"

#include "LineCells.h"


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

#include <algorithm>
#include <cmath>
#include <vector>

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
} // namespace

vtkCurvatureCombFilter::vtkCurvatureCombFilter() = default;
vtkCurvatureCombFilter::~vtkCurvatureCombFilter() = default;

int vtkCurvatureCombFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkDataObject* inputObject = vtkDataObject::GetData(inputVector[0], 0);
  if (!input && inputObject && output)
  {
    // A composite input's other blocks still go through.
    vtkWarningMacro("A " << inputObject->GetClassName() << " (a block of a composite input?) is "
                         << "not poly data: left out. Extract Surface makes poly data of it.");
    return 1;
  }
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output poly data.");
    return 0;
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
  const char* valueName = torsionComb ? "Torsion" : "Curvature";
  const char* directionName = torsionComb ? "Binormal" : "Normal";
  vtkDataArray* values = input->GetPointData()->GetArray(valueName);
  vtkDataArray* directions = input->GetPointData()->GetArray(directionName);
  if (!values || values->GetNumberOfComponents() != 1 || !directions ||
    directions->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("Input needs the point arrays "
      << valueName << " (1 component) and " << directionName
      << " (3 components), as the ShapeSplines curve filters write them.");
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
  // The automatic scale follows the 95th percentile tooth, not the longest:
  // one spike (a near-corner, the noise at an end) would shrink all others.
  std::vector<double> magnitudes;
  for (const CombLine& line : lines)
  {
    for (const vtkIdType id : line.Teeth)
    {
      const double v = values->GetComponent(id, 0);
      if (std::isfinite(v))
      {
        magnitudes.push_back(std::abs(v));
      }
    }
  }
  double typical = 0.0;
  if (!magnitudes.empty())
  {
    const auto rank = magnitudes.begin() + static_cast<std::ptrdiff_t>(0.95 * (magnitudes.size() - 1));
    std::nth_element(magnitudes.begin(), rank, magnitudes.end());
    typical = *rank;
  }
  const double diagonal = input->GetLength();
  double scale = this->ScaleFactor;
  if (this->ScaleMode == AUTOMATIC)
  {
    scale = typical > 0.0 && std::isfinite(diagonal) ? this->RelativeToothLength * diagonal / typical
                                                     : 0.0;
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> combValue;
  combValue->SetName("CombValue");
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkUnsignedCharArray> part;
  part->SetName("CombPart");
  std::vector<std::vector<vtkIdType>> tips(lines.size());
  vtkIdType undefined = 0;
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
      const vtkIdType tooth[2] = { points->InsertNextPoint(base), points->InsertNextPoint(tip) };
      combValue->InsertNextValue(value);
      combValue->InsertNextValue(value);
      cells->InsertNextCell(2, tooth);
      part->InsertNextValue(0);
      tips[l].push_back(tooth[1]);
    }
  }
  if (this->Envelope)
  {
    for (size_t l = 0; l < lines.size(); ++l)
    {
      std::vector<vtkIdType> envelope = tips[l];
      if (lines[l].Closed && !envelope.empty())
      {
        envelope.push_back(envelope.front());
      }
      if (envelope.size() >= 2)
      {
        cells->InsertNextCell(static_cast<vtkIdType>(envelope.size()), envelope.data());
        part->InsertNextValue(1);
      }
    }
  }
  if (undefined > 0)
  {
    vtkWarningMacro(<< undefined << " teeth with a non-finite " << valueName << " or "
                    << directionName << " drawn with zero length.");
  }

  output->SetPoints(points);
  output->SetLines(cells);
  output->GetPointData()->AddArray(combValue);
  output->GetPointData()->SetActiveScalars("CombValue");
  output->GetCellData()->AddArray(part);
  vtkNew<vtkDoubleArray> scaleUsed;
  scaleUsed->SetName("CombScale");
  scaleUsed->InsertNextValue(scale);
  output->GetFieldData()->AddArray(scaleUsed);
  return 1;
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
