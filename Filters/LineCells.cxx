#include "LineCells.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkPolyData.h"

#include <algorithm>

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
} // namespace shapesplines
