#include "LineCells.h"

#include "vtkCellArray.h"
#include "vtkAbstractArray.h"
#include "vtkAlgorithm.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkFieldData.h"
#include "vtkInformationVector.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>

namespace shapesplines
{
std::vector<LineCell> lineCells(vtkPolyData* polyData)
{
  std::vector<LineCell> lines;
  const vtkIdType points = polyData->GetNumberOfPoints();
  const vtkIdType firstLineId = polyData->GetNumberOfVerts();
  auto it = vtk::TakeSmartPointer(polyData->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* ids;
    it->GetCurrentCell(count, ids);
    LineCell line;
    line.CellId = firstLineId + static_cast<vtkIdType>(lines.size());
    const auto outside =
      std::find_if(ids, ids + count, [&](vtkIdType id) { return id < 0 || id >= points; });
    if (outside != ids + count)
    {
      line.Error = "point id " + std::to_string(*outside) + " out of range (the data have " +
        std::to_string(points) + " points)";
    }
    else
    {
      line.PointIds.assign(ids, ids + count);
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

bool isLineIdName(const std::string& name)
{
  static const std::array<std::string, 8> names = { "line_id", "line", "lineid", "id", "cell",
    "cell_id", "track", "streamline" };
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return std::find(names.begin(), names.end(), lower) != names.end();
}

std::vector<LineCell> connectedPoints(vtkIdType numberOfPoints, vtkDataArray* lineIds)
{
  std::vector<LineCell> lines;
  std::map<double, size_t> lineOfId;
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    const double id = lineIds ? lineIds->GetComponent(p, 0) : 0.0;
    if (!std::isfinite(id))
    {
      continue;
    }
    const auto [where, isNew] = lineOfId.emplace(id, lines.size());
    if (isNew)
    {
      lines.emplace_back();
      lines.back().CellId = static_cast<vtkIdType>(where->second);
    }
    lines[where->second].PointIds.push_back(p);
  }
  return lines;
}
vtkPolyData* polyDataInput(
  vtkAlgorithm* self, vtkInformationVector* input, vtkPolyData* output, int& status)
{
  vtkPolyData* polyData = vtkPolyData::GetData(input, 0);
  vtkDataObject* given = vtkDataObject::GetData(input, 0);
  status = 1;
  if (!polyData && given && output)
  {
    // A composite input's other blocks still go through.
    vtkWarningWithObjectMacro(self, "A " << given->GetClassName() << " (a block of a composite "
                                         << "input?) is not poly data: left out. Extract Surface "
                                         << "makes poly data of it.");
    return nullptr;
  }
  if (!polyData || !output)
  {
    vtkErrorWithObjectMacro(self, "Missing input or output poly data.");
    status = 0;
    return nullptr;
  }
  return polyData;
}
std::string removeMisfitArrays(vtkFieldData* data, vtkIdType tuples)
{
  std::string removed;
  for (int a = data->GetNumberOfArrays() - 1; a >= 0; --a)
  {
    const vtkIdType count = data->GetAbstractArray(a)->GetNumberOfTuples();
    if (count != tuples)
    {
      const char* name = data->GetArrayName(a);
      removed = (name ? std::string(name) : "#" + std::to_string(a)) + " (" +
        std::to_string(count) + " tuples)" + (removed.empty() ? "" : ", ") + removed;
      data->RemoveArray(a);
    }
  }
  return removed;
}
double coordinatePrecision(vtkPolyData* polyData)
{
  vtkPoints* points = polyData->GetPoints();
  bool floats = points && points->GetDataType() == VTK_FLOAT;
  if (points && points->GetDataType() == VTK_DOUBLE && points->GetNumberOfPoints() > 0)
  {
    const auto values = vtk::DataArrayValueRange(points->GetData());
    floats = std::all_of(values.begin(), values.end(),
      [](double value) { return static_cast<double>(static_cast<float>(value)) == value; });
  }
  return floats ? std::numeric_limits<float>::epsilon() : std::numeric_limits<double>::epsilon();
}
double coordinateStep(vtkPolyData* polyData, double precision)
{
  vtkPoints* points = polyData->GetPoints();
  if (!points || points->GetNumberOfPoints() == 0)
  {
    return 0.0;
  }
  const auto values = vtk::DataArrayValueRange(points->GetData());
  double largest = 0.0;
  for (const double value : values)
  {
    if (!std::isfinite(value))
    {
      return 0.0;
    }
    largest = std::max(largest, std::abs(value));
  }
  // A step is tested only well above the type's rounding, so that a value
  // off the step by that rounding is told from one off by chance (at most an
  // eighth of the step either way: a quarter of random values pass each).
  constexpr double StepOverRounding = 16.0;
  constexpr int FewestDigits = 2;
  for (int digits = 0; digits <= std::numeric_limits<double>::digits10; ++digits)
  {
    const double scale = std::pow(10.0, digits); // exact up to 1e15
    const double step = 1.0 / scale;
    if (step < StepOverRounding * precision * largest)
    {
      break;
    }
    const bool multiples = std::all_of(values.begin(), values.end(), [&](double value) {
      const double steps = value * scale;
      return std::abs(steps - std::round(steps)) <= 2.0 * precision * (std::abs(steps) + 1.0);
    });
    if (multiples)
    {
      return digits < FewestDigits ? 0.0 : step;
    }
  }
  return 0.0;
}
} // namespace shapesplines
