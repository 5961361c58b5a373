#include "OutputArrays.h"

#include "vtkAbstractArray.h"
#include "vtkFieldData.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace shapesplines
{
void addArrays(vtkFieldData* data, std::initializer_list<vtkAbstractArray*> arrays)
{
  for (vtkAbstractArray* array : arrays)
  {
    data->AddArray(array);
  }
}

double typicalMagnitude(std::vector<double> values)
{
  const auto notFinite = [](double v) { return !std::isfinite(v); };
  values.erase(std::remove_if(values.begin(), values.end(), notFinite), values.end());
  if (values.empty())
  {
    return 0.0;
  }
  std::transform(values.begin(), values.end(), values.begin(), [](double v) { return std::abs(v); });
  const auto rank = values.begin() + static_cast<std::ptrdiff_t>(0.95 * (values.size() - 1));
  std::nth_element(values.begin(), rank, values.end());
  return *rank;
}
} // namespace shapesplines
