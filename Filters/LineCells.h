// The line cells of a vtkPolyData, as the ShapeSplines filters read them:
// every point id checked against the point count first (a damaged file can
// hold any id, and reading through one writes or reads outside the arrays).
#ifndef shapesplines_LineCells_h
#define shapesplines_LineCells_h

#include "vtkType.h"

#include <cstddef>

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataArray;
class vtkFieldData;
class vtkInformationVector;
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

/// A RequestData's poly data input (port 0), or null once it has said why: a
/// block of a composite input that is not poly data is left out with a
/// warning, status 1 (the other blocks go through); a missing input or output
/// is an error, status 0.
vtkPolyData* polyDataInput(
  vtkAlgorithm* self, vtkInformationVector* input, vtkPolyData* output, int& status);

/// Whether a column or point array of this name holds line ids: line_id,
/// line, lineid, id, cell, cell_id, track or streamline, in any case.
bool isLineIdName(const std::string& name);

/// Points without line cells (a table's rows, vertices) made into lines in
/// point order: one line per value of lineIds, in the order of their first
/// points, or one line of every point when lineIds is null. Points whose id
/// is NaN or infinite belong to no line. CellId is the line's index.
std::vector<LineCell> connectedPoints(vtkIdType numberOfPoints, vtkDataArray* lineIds);

/// Removes from data (the attributes of a copy, never of the input) the arrays
/// without `tuples` tuples: a damaged file's, which no filter may read tuple by
/// tuple. Returns them for a warning, "X (23 tuples), Y (0 tuples)", or "".
std::string removeMisfitArrays(vtkFieldData* data, vtkIdType tuples);

/// Relative precision of polyData's point coordinates: FLT_EPSILON for float
/// points (rounded to 6e-8 relative: curvature or a turn within that is
/// noise) and for double points that are float values (converted from
/// float, as a float file read into numpy and back), or floats written as
/// text with their 9 significant digits (within half the last digit of a
/// float: the same rounding), DBL_EPSILON otherwise.
double coordinatePrecision(vtkPolyData* polyData);
} // namespace shapesplines

#endif
