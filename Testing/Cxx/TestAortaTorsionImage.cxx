// Image regression test: the aorta centerline's spline from one family at
// its filter's defaults (automatic tension or degrees) coloured by torsion
// (diverging map centred on zero) with the data points, as a user would look
// at it. Arguments: cubic|quintic|vdps -D <Data dir> -V <baseline.png> -T <temp dir>.
#include "ImageTestUtilities.h"
#include "vtkCubicSplineFilter.h"
#include "vtkTensionQuinticSplineFilter.h"
#include "vtkVariableDegreeSplineFilter.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkIdList.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTesting.h"
#include "vtkTubeFilter.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <array>
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
using Point = std::array<double, 3>;

/// Where the centerline's first two lines part: the first point of line 0
/// farther than 1 from every point of line 1.
Point Bifurcation(vtkPolyData* data)
{
  vtkNew<vtkIdList> trunk, branch;
  data->GetCellPoints(0, trunk);
  data->GetCellPoints(1, branch);
  Point p{};
  for (vtkIdType i = 0; i < trunk->GetNumberOfIds(); ++i)
  {
    data->GetPoint(trunk->GetId(i), p.data());
    double nearest = 1e300;
    for (vtkIdType j = 0; j < branch->GetNumberOfIds(); ++j)
    {
      Point q;
      data->GetPoint(branch->GetId(j), q.data());
      nearest = std::min(nearest, std::sqrt(vtkMath::Distance2BetweenPoints(p.data(), q.data())));
    }
    if (nearest > 1.0)
    {
      break;
    }
  }
  return p;
}
} // namespace

int TestAortaTorsionImage(int argc, char* argv[])
{
  const std::string family = argc > 1 ? argv[1] : "";
  vtkSmartPointer<vtkShapeSplineFilter> spline;
  if (family == "cubic")
  {
    spline = vtkSmartPointer<vtkCubicSplineFilter>::New();
  }
  else if (family == "quintic")
  {
    spline = vtkSmartPointer<vtkTensionQuinticSplineFilter>::New();
  }
  else if (family == "vdps")
  {
    spline = vtkSmartPointer<vtkVariableDegreeSplineFilter>::New();
  }
  else
  {
    std::cerr << "ERROR: the first argument must be cubic, quintic or vdps.\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc - 1, argv + 1);
  const std::string file = std::string(testing->GetDataRoot()) + "/aorta-centerline.vtp";
  if (!shapesplines_test::HasBaseline(testing))
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
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

  const auto colors = shapesplines_test::DivergingColors(range);

  // Left: the whole centerline as a tube. Right: a close-up of the
  // bifurcation, where a thin tube leaves the data points (0.26 apart) visible.
  auto curveActor = [&](double radius) {
    vtkNew<vtkTubeFilter> tube;
    tube->SetInputConnection(spline->GetOutputPort());
    tube->SetRadius(radius);
    tube->SetNumberOfSides(12);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(tube->GetOutputPort());
    mapper->SetLookupTable(colors);
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray("Torsion");
    mapper->UseLookupTableScalarRangeOn();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    return vtkSmartPointer<vtkActor>(actor);
  };

  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.1);
  vtkNew<vtkGlyph3DMapper> pointMapper;
  pointMapper->SetInputConnection(reader->GetOutputPort());
  pointMapper->SetSourceConnection(sphere->GetOutputPort());
  pointMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> points;
  points->SetMapper(pointMapper);
  points->GetProperty()->SetColor(0.1, 0.1, 0.1);

  vtkNew<vtkRenderer> whole;
  whole->SetViewport(0.0, 0.0, 0.5, 1.0);
  whole->AddActor(curveActor(0.6));
  whole->SetBackground(1, 1, 1);
  vtkNew<vtkRenderer> closeUp;
  closeUp->SetViewport(0.5, 0.0, 1.0, 1.0);
  closeUp->AddActor(curveActor(0.06));
  closeUp->AddActor(points);
  closeUp->AddActor2D(shapesplines_test::ScalarBar(colors, "Torsion", 0.78, 0.2, 0.2, 0.7));
  closeUp->SetBackground(0.96, 0.96, 0.96);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 600);
  window->SetMultiSamples(0);
  window->AddRenderer(whole);
  window->AddRenderer(closeUp);
  whole->ResetCamera();
  whole->GetActiveCamera()->Azimuth(20);
  whole->GetActiveCamera()->Dolly(1.15);
  whole->ResetCameraClippingRange();
  closeUp->GetActiveCamera()->DeepCopy(whole->GetActiveCamera());
  const Point fork = Bifurcation(reader->GetOutput());
  closeUp->GetActiveCamera()->SetFocalPoint(fork.data());
  closeUp->GetActiveCamera()->Dolly(6.0);
  closeUp->ResetCameraClippingRange();
  window->Render();
  return shapesplines_test::CompareWithBaseline(argc, argv, window);
}

int main(int argc, char* argv[])
{
  return TestAortaTorsionImage(argc, argv);
}
