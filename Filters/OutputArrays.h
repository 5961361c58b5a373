// What the ShapeSplines filters share to make their output arrays.
#ifndef shapesplines_OutputArrays_h
#define shapesplines_OutputArrays_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <initializer_list>
#include <vector>

class vtkAbstractArray;
class vtkFieldData;

namespace shapesplines
{
/// A new array of this name with tuples tuples of components each (values unset).
template <typename Array>
vtkSmartPointer<Array> newArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

/// Adds the arrays to data in order; a later one replaces an array of the same name.
void addArrays(vtkFieldData* data, std::initializer_list<vtkAbstractArray*> arrays);

/// The 95th percentile of |v| over the finite values v (0 when there is none):
/// a typical size that a few spikes do not set.
double typicalMagnitude(const double* first, const double* last);
double typicalMagnitude(const std::vector<double>& values);
} // namespace shapesplines

#endif
