// Image regression test: a space curve (a helix turn running into a straight
// line) as the control polygon of qqr B-spline-like curves, alpha = beta = 4
// (left: the classical cubic B-spline) and automatic (right), each with its
// control polygon and coloured by torsion on the same diverging scale.
// Arguments: -V <baseline.png> -T <temp dir>.
#include "ImageTestUtilities.h"
#include "vtkQQRSplineFilter.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkCoordinate.h"
#include "vtkDataArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTesting.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
vtkSmartPointer<vtkPolyData> HelixIntoLine()
{
  vtkNew<vtkPoints> points;
  for (int i = 0; i <= 6; ++i)
  {
    const double t = 2.0 * vtkMath::Pi() * i / 8.0;
    points->InsertNextPoint(2.0 * std::cos(t), 2.0 * std::sin(t), 0.5 * t);
  }
  double end[3];
  points->GetPoint(6, end);
  for (int i = 1; i <= 4; ++i)
  {
    points->InsertNextPoint(end[0] + 1.5 * i, end[1], end[2]);
  }
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    lines->InsertCellPoint(i);
  }
  auto polyline = vtkSmartPointer<vtkPolyData>::New();
  polyline->SetPoints(points);
  polyline->SetLines(lines);
  return polyline;
}

/// One viewport: the control polygon and the curve coloured by torsion, with a title.
void AddPanel(vtkRenderWindow* window, vtkPolyData* polygon, bool automatic, double left,
  double right, vtkColorTransferFunction* colors)
{
  vtkNew<vtkQQRSplineFilter> spline;
  spline->SetInputData(polygon);
  spline->SetModeToApproximate();
  spline->SetAutomatic(automatic);
  spline->SetNumberOfSubdivisions(32);
  spline->Update();
  vtkPolyData* out = spline->GetOutput();
  const int violations = static_cast<int>(out->GetCellData()->GetArray("ShapeViolations")->GetTuple1(0));
  const double straightness = out->GetCellData()->GetArray("MaxStraightness")->GetTuple1(0);

  vtkNew<vtkPolyDataMapper> curveMapper;
  curveMapper->SetInputData(out);
  curveMapper->SetLookupTable(colors);
  curveMapper->SetScalarModeToUsePointFieldData();
  curveMapper->SelectColorArray("Torsion");
  curveMapper->UseLookupTableScalarRangeOn();
  vtkNew<vtkActor> curve;
  curve->SetMapper(curveMapper);
  curve->GetProperty()->SetLineWidth(5);

  vtkNew<vtkPolyDataMapper> polygonMapper;
  polygonMapper->SetInputData(polygon);
  vtkNew<vtkActor> polygonActor;
  polygonActor->SetMapper(polygonMapper);
  polygonActor->GetProperty()->SetColor(0.3, 0.3, 0.3);
  polygonActor->GetProperty()->SetLineWidth(1.5);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.12);
  vtkNew<vtkGlyph3DMapper> pointMapper;
  pointMapper->SetInputData(polygon);
  pointMapper->SetSourceConnection(sphere->GetOutputPort());
  pointMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> points;
  points->SetMapper(pointMapper);
  points->GetProperty()->SetColor(0.1, 0.1, 0.1);

  vtkNew<vtkTextActor> title;
  char straightened[64];
  std::snprintf(straightened, sizeof(straightened), "automatic, max straightness %.2f", straightness);
  title->SetInput(((automatic ? std::string(straightened)
                              : std::string("alpha = beta = 4 (cubic B-spline)")) +
    "\nshape violations: " + std::to_string(violations))
                   .c_str());
  title->GetTextProperty()->SetColor(0, 0, 0);
  title->GetTextProperty()->SetFontSize(16);
  title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  title->SetPosition(0.03, 0.03);

  vtkNew<vtkRenderer> renderer;
  renderer->SetViewport(left, 0.0, right, 1.0);
  renderer->AddActor(polygonActor);
  renderer->AddActor(points);
  renderer->AddActor(curve);
  renderer->AddActor2D(title);
  renderer->SetBackground(1, 1, 1);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Elevation(-35);
  renderer->GetActiveCamera()->OrthogonalizeViewUp();
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Dolly(0.95);
  renderer->ResetCameraClippingRange();
}
} // namespace

int TestQQRSplineImage(int argc, char* argv[])
{
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  if (!shapesplines_test::HasBaseline(testing))
  {
    return EXIT_FAILURE;
  }
  const vtkSmartPointer<vtkPolyData> polygon = HelixIntoLine();
  // The helix's torsion, 0.5 / (4 + 0.25) = 0.118, at the ends of the scale.
  const auto colors = shapesplines_test::DivergingColors(0.2);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(900, 450);
  window->SetMultiSamples(0);
  AddPanel(window, polygon, false, 0.0, 0.42, colors);
  AddPanel(window, polygon, true, 0.42, 0.84, colors);
  vtkNew<vtkRenderer> legend;
  legend->SetViewport(0.84, 0.0, 1.0, 1.0);
  legend->SetBackground(1, 1, 1);
  legend->AddActor2D(shapesplines_test::ScalarBar(colors, "Torsion", 0.25, 0.1, 0.6, 0.8));
  window->AddRenderer(legend);
  window->Render();
  return shapesplines_test::CompareWithBaseline(argc, argv, window);
}

int main(int argc, char* argv[])
{
  return TestQQRSplineImage(argc, argv);
}
