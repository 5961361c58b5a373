// Fits the installed vtkCubicSplineFilter to a polyline file and prints a summary.
#include "vtkCubicSplineFilter.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataReader.h"

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: " << argv[0] << " polylines.vtp\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(argv[1]);
  vtkNew<vtkCubicSplineFilter> spline;
  spline->SetInputConnection(reader->GetOutputPort());
  spline->Update();
  vtkPolyData* curve = spline->GetOutput();
  vtkDataArray* curvature = curve->GetPointData()->GetArray("Curvature");
  if (!curvature || curve->GetNumberOfPoints() == 0)
  {
    std::cerr << "no curvature in the output\n";
    return EXIT_FAILURE;
  }
  const std::string name = argv[1];
  std::cout << name.substr(name.find_last_of('/') + 1) << ": " << curve->GetNumberOfLines()
            << " line(s), " << curve->GetNumberOfPoints() << " points, curvature "
            << curvature->GetTuple1(curve->GetNumberOfPoints() / 2) << "\n";
  return EXIT_SUCCESS;
}
