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
#include <utility>
#include <vector>

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

namespace
{
/// The digits a value needs, to within its type's rounding: after the decimal
/// point, and significant ones; -1 where more than were tried.
struct Digits
{
  int Decimals = -1;
  int Significant = -1;
  int Exponent = 0; ///< of its leading digit
};

/// True when value * scale is an integer but for the type's rounding.
bool wholeSteps(double value, double scale, double precision)
{
  const double steps = value * scale;
  return std::abs(steps - std::round(steps)) <= 2.0 * precision * (std::abs(steps) + 1.0);
}

Digits digitsOf(double value, int mostDecimals, int mostSignificant, double precision)
{
  Digits digits;
  if (value == 0.0)
  {
    digits.Decimals = digits.Significant = 0;
    return digits;
  }
  for (int d = 0; d <= mostDecimals && digits.Decimals < 0; ++d)
  {
    if (wholeSteps(value, std::pow(10.0, d), precision))
    {
      digits.Decimals = d;
    }
  }
  int exponent = static_cast<int>(std::floor(std::log10(std::abs(value))));
  exponent += std::abs(value) >= std::pow(10.0, exponent + 1) ? 1 : 0;
  exponent -= std::abs(value) < std::pow(10.0, exponent) ? 1 : 0;
  digits.Exponent = exponent;
  for (int s = 1; s <= mostSignificant && digits.Significant < 0; ++s)
  {
    if (wholeSteps(value, std::pow(10.0, s - 1 - exponent), precision))
    {
      digits.Significant = s;
    }
  }
  return digits;
}

/// The step one coordinate's values were written with (see coordinateSteps).
double columnStep(const std::vector<double>& values, double precision)
{
  double largest = 0.0;
  for (const double value : values)
  {
    largest = std::max(largest, std::abs(value));
  }
  // A step is tested only well above the type's rounding, so that a value
  // off the step by that rounding is told from one off by chance (at most an
  // eighth of the step either way: a quarter of random values pass each).
  constexpr double StepOverRounding = 16.0;
  int decimalsTried = static_cast<int>(std::floor(-std::log10(StepOverRounding * precision *
    std::max(largest, std::numeric_limits<double>::min()))));
  int significantTried = static_cast<int>(std::floor(-std::log10(StepOverRounding * precision)));
  std::vector<Digits> digits;
  digits.reserve(values.size());
  for (const double value : values)
  {
    digits.push_back(digitsOf(value, decimalsTried, significantTried, precision));
    // A way one value does not fit is out: not tried on the others.
    decimalsTried = digits.back().Decimals < 0 ? -1 : decimalsTried;
    significantTried = digits.back().Significant < 0 ? 0 : significantTried;
    if (decimalsTried < 0 && significantTried == 0)
    {
      return 0.0;
    }
  }
  // Two ways to write numbers: a fixed number of decimals ("%.3f": the step
  // is the same everywhere) or of significant digits ("%.5e", ParaView's CSV
  // default: the step grows with the value). Either fits the other's
  // numbers with more digits than they show, which few values use: random
  // last digits leave a tenth of the values short of a way's digits, and a
  // way is plausible where at least a quarter use them all.
  struct Way
  {
    int Digits = -1; ///< the fewest that fit every value, -1: none
    int Full = 0;    ///< nonzero values that use them all
  };
  int nonzero = 0;
  for (const Digits& d : digits)
  {
    nonzero += d.Significant != 0;
  }
  auto fewest = [&](int Digits::*count) {
    Way way;
    for (const Digits& d : digits)
    {
      if (d.*count < 0)
      {
        return Way{};
      }
      way.Digits = std::max(way.Digits, d.*count);
    }
    for (const Digits& d : digits)
    {
      way.Full += d.Significant != 0 && d.*count == way.Digits;
    }
    return way;
  };
  const Way decimals = fewest(&Digits::Decimals);
  const Way significant = fewest(&Digits::Significant);
  constexpr int FewestDecimals = 2, FewestSignificant = 3;
  if (decimals.Digits >= 0 && decimals.Digits < FewestDecimals)
  {
    return 0.0; // integers, tenths: designed values
  }
  const double decimalStep = decimals.Digits >= 0 ? std::pow(10.0, -decimals.Digits) : 0.0;
  if (significant.Digits < FewestSignificant || 4 * significant.Full < nonzero ||
    (decimalStep > 0 && significant.Full < decimals.Full))
  {
    return decimalStep;
  }
  int exponent = std::numeric_limits<int>::min();
  for (const Digits& d : digits)
  {
    exponent = d.Significant != 0 ? std::max(exponent, d.Exponent) : exponent;
  }
  // The largest values' step bounds every value's.
  const double significantStep = std::pow(10.0, exponent - significant.Digits + 1);
  // Equally plausible (all values within one decade): the finer step.
  return decimalStep > 0 && significant.Full == decimals.Full
    ? std::min(decimalStep, significantStep)
    : significantStep;
}
} // namespace

std::array<double, 3> coordinateSteps(vtkPolyData* polyData, double precision)
{
  std::array<double, 3> steps{ 0.0, 0.0, 0.0 };
  vtkPoints* points = polyData->GetPoints();
  if (!points || points->GetNumberOfPoints() == 0)
  {
    return steps;
  }
  const auto tuples = vtk::DataArrayTupleRange<3>(points->GetData());
  std::vector<double> column(tuples.size());
  for (int axis = 0; axis < 3; ++axis)
  {
    for (vtkIdType i = 0; i < tuples.size(); ++i)
    {
      column[i] = tuples[i][axis];
      if (!std::isfinite(column[i]))
      {
        return { 0.0, 0.0, 0.0 };
      }
    }
    steps[axis] = columnStep(column, precision);
  }
  return steps;
}

double roundingReach(const std::array<double, 3>& steps)
{
  // Each coordinate rounded by up to half its step.
  return 0.5 * std::hypot(steps[0], steps[1], steps[2]);
}
} // namespace shapesplines
