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
    // Float values, or floats written as text with the 9 significant digits
    // that tell one float from the next (and read back as doubles): each
    // within half that last digit of a float, which a double hits by chance
    // about once in ten.
    constexpr int FloatDigits = std::numeric_limits<float>::max_digits10;
    const auto values = vtk::DataArrayValueRange(points->GetData());
    floats = std::all_of(values.begin(), values.end(), [](double value) {
      const double nearestFloat = static_cast<double>(static_cast<float>(value));
      if (nearestFloat == value)
      {
        return true;
      }
      const double lastDigit =
        std::pow(10.0, std::floor(std::log10(std::abs(value))) - (FloatDigits - 1));
      return std::abs(value - nearestFloat) <=
        0.5 * lastDigit + 2.0 * std::numeric_limits<double>::epsilon() * std::abs(value);
    });
  }
  return floats ? std::numeric_limits<float>::epsilon() : std::numeric_limits<double>::epsilon();
}
} // namespace shapesplines
