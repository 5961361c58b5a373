// Image regression test: the aorta centerline's C4 tensioned quintic spline
// (automatic tension, the filter's defaults) coloured by torsion (diverging map
// centred on zero) with the data points, as a user would look at it. Arguments: -D <Data dir> -V <baseline.png> -T <temp dir>.
#include "vtkTensionQuinticSplineFilter.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkSphereSource.h"
#include "vtkTesting.h"
#include "vtkTextProperty.h"
#include "vtkTubeFilter.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
/// Symmetric colour range: the 75th percentile of |torsion|. Torsion on this
/// centerline spikes by orders of magnitude where points are nearly repeated;
/// a wider range would paint everything grey.
double TorsionRange(vtkDataArray* torsion)
{
  std::vector<double> magnitudes(torsion->GetNumberOfTuples());
  for (vtkIdType i = 0; i < torsion->GetNumberOfTuples(); ++i)
  {
    magnitudes[i] = std::abs(torsion->GetTuple1(i));
  }
  const size_t k = magnitudes.size() * 75 / 100;
  std::nth_element(magnitudes.begin(), magnitudes.begin() + k, magnitudes.end());
  return std::max(magnitudes[k], 1e-12);
}
} // namespace

int TestTensionQuinticSplineImage(int argc, char* argv[])
{
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  const std::string file = std::string(testing->GetDataRoot()) + "/aorta-centerline.vtp";
  if (!testing->IsValidImageSpecified())
  {
    std::cerr << "ERROR: no baseline image given (-V): the test cannot pass without one.\n";
    return EXIT_FAILURE;
  }

  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  vtkNew<vtkTensionQuinticSplineFilter> spline;
  spline->SetInputConnection(reader->GetOutputPort());
  spline->SetNumberOfSubdivisions(8);
  spline->Update();
  vtkDataArray* violations = spline->GetOutput()->GetCellData()->GetArray("ShapeViolations");
  for (vtkIdType i = 0; i < violations->GetNumberOfTuples(); ++i)
  {
    std::cout << "line " << i << ": " << violations->GetTuple1(i) << " shape violations\n";
  }
  vtkDataArray* torsion = spline->GetOutput()->GetPointData()->GetArray("Torsion");
  const double range = TorsionRange(torsion);

  vtkNew<vtkColorTransferFunction> colors;
  colors->SetColorSpaceToDiverging();
  colors->AddRGBPoint(-range, 0.23, 0.299, 0.754);
  colors->AddRGBPoint(0.0, 0.865, 0.865, 0.865);
  colors->AddRGBPoint(range, 0.706, 0.016, 0.150);

  vtkNew<vtkTubeFilter> tube;
  tube->SetInputConnection(spline->GetOutputPort());
  tube->SetRadius(0.6);
  tube->SetNumberOfSides(12);
  vtkNew<vtkPolyDataMapper> curveMapper;
  curveMapper->SetInputConnection(tube->GetOutputPort());
  curveMapper->SetLookupTable(colors);
  curveMapper->SetScalarModeToUsePointFieldData();
  curveMapper->SelectColorArray("Torsion");
  curveMapper->UseLookupTableScalarRangeOn();
  vtkNew<vtkActor> curve;
  curve->SetMapper(curveMapper);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.5);
  vtkNew<vtkGlyph3DMapper> pointMapper;
  pointMapper->SetInputConnection(reader->GetOutputPort());
  pointMapper->SetSourceConnection(sphere->GetOutputPort());
  pointMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> points;
  points->SetMapper(pointMapper);
  points->GetProperty()->SetColor(0.1, 0.1, 0.1);

  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(colors);
  bar->SetTitle("Torsion");
  bar->SetNumberOfLabels(5);
  bar->SetWidth(0.12);
  bar->SetHeight(0.7);
  bar->SetPosition(0.84, 0.2);
  bar->GetTitleTextProperty()->SetColor(0, 0, 0);
  bar->GetLabelTextProperty()->SetColor(0, 0, 0);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(curve);
  renderer->AddActor(points);
  renderer->AddActor2D(bar);
  renderer->SetBackground(1, 1, 1);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(450, 600);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(20);
  renderer->GetActiveCamera()->Dolly(1.15);
  renderer->ResetCameraClippingRange();
  window->Render();

  // Threshold 10 (VTK 9.2's image difference metric): rendering noise stays far below.
  const int result = vtkRegressionTestImageThreshold(window, 10.0);
  return result == vtkTesting::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}

int main(int argc, char* argv[])
{
  return TestTensionQuinticSplineImage(argc, argv);
}
