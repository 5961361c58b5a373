// Image regression test: Akima's data, the classical cubic (top) and the
// generalized cubic with automatic exponential tension (bottom), each coloured
// by curvature on the same scale and with its curvature comb: the cubic's
// comb flips side on the flat run (wiggles), the automatic curve's does not.
// Arguments: -D <Data dir> -V <baseline.png> -T <temp dir>.
#include "ImageTestUtilities.h"
#include "vtkCurvatureCombFilter.h"
#include "vtkGeneralizedCubicSplineFilter.h"

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
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTesting.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkXMLPolyDataReader.h"

#include <string>

namespace
{
/// One viewport: data points, the curve coloured by curvature, its comb, a title.
void AddPanel(vtkRenderWindow* window, vtkAlgorithmOutput* data, int kind, double bottom,
  double top, vtkColorTransferFunction* colors, const std::string& title)
{
  vtkNew<vtkGeneralizedCubicSplineFilter> spline;
  spline->SetInputConnection(data);
  spline->SetSpaceKind(kind);
  spline->SetNumberOfSubdivisions(24);
  spline->Update();
  const int violations =
    static_cast<int>(spline->GetOutput()->GetCellData()->GetArray("ShapeViolations")->GetTuple1(0));

  vtkNew<vtkPolyDataMapper> curveMapper;
  curveMapper->SetInputConnection(spline->GetOutputPort());
  curveMapper->SetLookupTable(colors);
  curveMapper->SetScalarModeToUsePointFieldData();
  curveMapper->SelectColorArray("Curvature");
  curveMapper->UseLookupTableScalarRangeOn();
  vtkNew<vtkActor> curve;
  curve->SetMapper(curveMapper);
  curve->GetProperty()->SetLineWidth(4);

  vtkNew<vtkCurvatureCombFilter> comb;
  comb->SetInputConnection(spline->GetOutputPort());
  comb->SetScaleModeToFixed();
  comb->SetScaleFactor(1.5);
  vtkNew<vtkPolyDataMapper> combMapper;
  combMapper->SetInputConnection(comb->GetOutputPort());
  combMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> teeth;
  teeth->SetMapper(combMapper);
  teeth->GetProperty()->SetColor(0.55, 0.55, 0.6);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.12);
  vtkNew<vtkGlyph3DMapper> pointMapper;
  pointMapper->SetInputConnection(data);
  pointMapper->SetSourceConnection(sphere->GetOutputPort());
  pointMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> points;
  points->SetMapper(pointMapper);
  points->GetProperty()->SetColor(0.1, 0.1, 0.1);

  vtkNew<vtkTextActor> label;
  label->SetInput((title + ": " + std::to_string(violations) + " shape violations").c_str());
  label->GetTextProperty()->SetColor(0, 0, 0);
  label->GetTextProperty()->SetFontSize(16);
  label->SetPosition(10, 330); // top left of the panel, away from the curve

  vtkNew<vtkRenderer> renderer;
  renderer->SetViewport(0.0, bottom, 0.85, top);
  renderer->SetBackground(1, 1, 1);
  renderer->AddActor(teeth);
  renderer->AddActor(curve);
  renderer->AddActor(points);
  renderer->AddActor2D(label);
  // The flat run and the knee, where the cubic wiggles.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(8.5, 11.6, 0.0);
  camera->SetPosition(8.5, 11.6, 50.0);
  camera->SetParallelScale(3.4);
  renderer->ResetCameraClippingRange();
  window->AddRenderer(renderer);
}
} // namespace

int TestGeneralizedCubicImage(int argc, char* argv[])
{
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  if (!shapesplines_test::HasBaseline(testing))
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName((std::string(testing->GetDataRoot()) + "/akima.vtp").c_str());

  vtkNew<vtkColorTransferFunction> colors;
  colors->AddRGBPoint(0.0, 0.27, 0.0, 0.33);
  colors->AddRGBPoint(0.25, 0.23, 0.32, 0.55);
  colors->AddRGBPoint(0.5, 0.13, 0.57, 0.55);
  colors->AddRGBPoint(0.75, 0.37, 0.79, 0.38);
  colors->AddRGBPoint(1.0, 0.99, 0.91, 0.14);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(640, 720);
  window->SetMultiSamples(0);
  AddPanel(window, reader->GetOutputPort(), vtkGeneralizedCubicSplineFilter::POLYNOMIAL, 0.5, 1.0,
    colors, "cubic spline");
  AddPanel(window, reader->GetOutputPort(), vtkGeneralizedCubicSplineFilter::EXPONENTIAL, 0.0,
    0.5, colors, "automatic exponential tension");

  vtkNew<vtkRenderer> legend;
  legend->SetViewport(0.85, 0.0, 1.0, 1.0);
  legend->SetBackground(1, 1, 1);
  legend->AddActor2D(shapesplines_test::ScalarBar(colors, "Curvature", 0.1, 0.2, 0.8, 0.6));
  window->AddRenderer(legend);
  window->Render();
  return shapesplines_test::CompareWithBaseline(argc, argv, window);
}

int main(int argc, char* argv[])
{
  return TestGeneralizedCubicImage(argc, argv);
}
