// Shared by the image regression tests: the baseline check, the torsion
// colour map, the scalar bar and the comparison with the baseline.
#ifndef ShapeSplinesImageTestUtilities_h
#define ShapeSplinesImageTestUtilities_h

#include "vtkColorTransferFunction.h"
#include "vtkRenderWindow.h"
#include "vtkScalarBarActor.h"
#include "vtkSmartPointer.h"
#include "vtkTesting.h"
#include "vtkTextProperty.h"

#include <cstdlib>
#include <iostream>

namespace shapesplines_test
{
/// False, with a message, when the test was given no baseline image (-V):
/// it cannot pass without one.
inline bool HasBaseline(vtkTesting* testing)
{
  if (testing->IsValidImageSpecified())
  {
    return true;
  }
  std::cerr << "ERROR: no baseline image given (-V): the test cannot pass without one.\n";
  return false;
}

/// Blue to grey to red on [-range, range], grey at zero: torsion's sign at a glance.
inline vtkSmartPointer<vtkColorTransferFunction> DivergingColors(double range)
{
  auto colors = vtkSmartPointer<vtkColorTransferFunction>::New();
  colors->SetColorSpaceToDiverging();
  colors->AddRGBPoint(-range, 0.23, 0.299, 0.754);
  colors->AddRGBPoint(0.0, 0.865, 0.865, 0.865);
  colors->AddRGBPoint(range, 0.706, 0.016, 0.150);
  return colors;
}

/// A scalar bar of colors with five labels in black, its lower left corner
/// at (x, y) of its renderer, width and height in the renderer's fractions.
inline vtkSmartPointer<vtkScalarBarActor> ScalarBar(vtkScalarsToColors* colors, const char* title,
  double x, double y, double width, double height)
{
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(colors);
  bar->SetTitle(title);
  bar->SetNumberOfLabels(5);
  bar->SetWidth(width);
  bar->SetHeight(height);
  bar->SetPosition(x, y);
  bar->GetTitleTextProperty()->SetColor(0, 0, 0);
  bar->GetLabelTextProperty()->SetColor(0, 0, 0);
  return bar;
}

/// The rendered window against the baseline named in argv, threshold 10
/// (VTK 9.2's image difference metric: rendering noise stays far below):
/// EXIT_SUCCESS or EXIT_FAILURE.
inline int CompareWithBaseline(int argc, char* argv[], vtkRenderWindow* window)
{
  return vtkTesting::Test(argc, argv, window, 10.0) == vtkTesting::PASSED ? EXIT_SUCCESS
                                                                           : EXIT_FAILURE;
}
} // namespace shapesplines_test

#endif
