// The line cells of a vtkPolyData, as the ShapeSplines filters read them:
// every point id checked against the point count first (a damaged file can
// hold any id, and reading through one writes or reads outside the arrays).
#ifndef shapesplines_LineCells_h
#define shapesplines_LineCells_h

#include "vtkType.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace shapesplines
{
/// One line or polyline cell.
struct LineCell
{
  vtkIdType CellId = 0; ///< in the poly data's numbering (vertices come first)
  std::vector<vtkIdType> PointIds;
  std::string Error; ///< why the cell cannot be used; empty when it can
};

/// The line cells of polyData, in order; a cell with an id outside
/// [0, number of points) has no point ids and an Error saying so.
std::vector<LineCell> lineCells(vtkPolyData* polyData);
} // namespace shapesplines

#endif
