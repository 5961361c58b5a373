// GoogleTest tests of the ShapeSplines VTK filters (vtkCubicSplineFilter through
// vtkShapeSplineFilter, and vtkPolylineShapeAnalysis), driven through VTK
// pipelines. Inputs are built in code unless a file of SHAPESPLINES_DATA_DIR
// is named.
#include "FitPolyline.h"
#include "OutputArrays.h"

#include "vtkCubicSplineFilter.h"
#include "vtkCurvatureCombFilter.h"
#include "vtkPolylineShapeAnalysis.h"
#include "vtkVariableDegreeSplineFilter.h"
#include "vtkTensionQuinticSplineFilter.h"
#include "vtkQQRSplineFilter.h"
#include "vtkGeneralizedCubicSplineFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTree.h"
#include "vtkPartitionedDataSet.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <thread>
#include <functional>
#include <initializer_list>
#include <random>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "FilterTestUtilities.h"

using namespace shapesplines::filtertest;

namespace
{
// Helix of Data/helix.vtp: (a cos t, a sin t, b t), t = 0, pi/4, ..., 8 pi.
constexpr double HelixA = 2.0;
constexpr double HelixB = 1.0;
constexpr double HelixStep = Pi / 4;
constexpr double HelixEnd = 8 * Pi;
const double HelixCurvature = HelixA / (HelixA * HelixA + HelixB * HelixB); // 0.4
const double HelixTorsion = HelixB / (HelixA * HelixA + HelixB * HelixB);   // 0.2

Point HelixPoint(double t)
{
  return { HelixA * std::cos(t), HelixA * std::sin(t), HelixB * t };
}

// ===========================================================================
// Contract of the output on the helix.

TEST(CubicSplineFilter, HelixOutputContract)
{
  const auto helix = ReadData("helix.vtp");
  ASSERT_EQ(helix->GetNumberOfPoints(), 33);
  const FilterRun run = RunCubic(helix);
  ExpectNoMessages(run);
  vtkPolyData* curve = run.Output;

  const auto lines = LinesOf(curve);
  ASSERT_EQ(lines.size(), LinesOf(helix).size());
  ASSERT_EQ(curve->GetNumberOfCells(), 1);
  const IdList& line = lines[0];
  const vtkIdType n = curve->GetNumberOfPoints();
  ASSERT_EQ(static_cast<vtkIdType>(line.size()), n);

  for (const auto& [name, components] : CurvePointArrays)
  {
    vtkDataArray* array = PointArray(curve, name);
    ASSERT_NE(array, nullptr);
    EXPECT_EQ(array->GetNumberOfComponents(), components) << name;
    EXPECT_EQ(array->GetNumberOfTuples(), n) << name;
  }
  for (const char* name : CurveCellArrays)
  {
    vtkDataArray* array = CellArray(curve, name);
    ASSERT_NE(array, nullptr);
    EXPECT_EQ(array->GetNumberOfComponents(), 1) << name;
    EXPECT_EQ(array->GetNumberOfTuples(), 1) << name;
  }

  // The data points (the helix at t = k pi / 4) are the samples 0, N, 2N, ...
  // (default N = 10).
  const Polyline data = PointsOfLine(helix, LinesOf(helix)[0]);
  for (size_t k = 0; k < data.size(); ++k)
  {
    ASSERT_NEAR(Norm(data[k] - HelixPoint(k * HelixStep)), 0.0, 1e-12) << "helix.vtp point " << k;
  }
  ExpectDataPointsAmongSamples(data, curve, line, 10);
  vtkDataArray* span = PointArray(curve, "SpanIndex");
  for (size_t k = 0; k + 1 < line.size(); ++k)
  {
    EXPECT_EQ(span->GetTuple1(line[k]), static_cast<double>(k / 10)) << "sample " << k;
  }

  ExpectOrthonormalFrames(curve, line);

  // ArcLength and Parameter increase; ArcLength ends at the Length.
  vtkDataArray* arcLength = PointArray(curve, "ArcLength");
  vtkDataArray* parameter = PointArray(curve, "Parameter");
  EXPECT_EQ(arcLength->GetTuple1(line.front()), 0.0);
  for (size_t k = 1; k < line.size(); ++k)
  {
    EXPECT_GT(arcLength->GetTuple1(line[k]), arcLength->GetTuple1(line[k - 1])) << "sample " << k;
    EXPECT_GT(parameter->GetTuple1(line[k]), parameter->GetTuple1(line[k - 1])) << "sample " << k;
  }
  const double length = CellArray(curve, "Length")->GetTuple1(0);
  const double lastArcLength = arcLength->GetTuple1(line.back());
  Measure("helix_length_minus_last_arclength", length - lastArcLength);
  EXPECT_NEAR(lastArcLength, length, 1e-9 * length);

  // The true length of the helix over t in [0, 8 pi] is sqrt(a^2 + b^2) 8 pi.
  const double trueLength = std::sqrt(HelixA * HelixA + HelixB * HelixB) * HelixEnd;
  Measure("helix_length_relative_error", (length - trueLength) / trueLength);
  EXPECT_NEAR(length, trueLength, 1e-3 * trueLength);

  // Tortuosity of an open line: length / end-to-end distance.
  const double chord = Norm(data.back() - data.front());
  EXPECT_NEAR(CellArray(curve, "Tortuosity")->GetTuple1(0), length / chord, 1e-12 * length / chord);

  // The input's Radius (2 everywhere) is interpolated.
  vtkDataArray* radius = PointArray(curve, "Radius");
  ASSERT_NE(radius, nullptr);
  ASSERT_EQ(radius->GetNumberOfTuples(), n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    EXPECT_NEAR(radius->GetTuple1(i), 2.0, 1e-12) << "sample " << i;
  }

  // Away from the not-a-knot ends the spline's curvature and torsion are close
  // to the helix's (0.4, 0.2), measured on the spans 4 .. 27. With 8 points per
  // turn (h = pi/4) the spline's second derivative at the knots is that of the
  // helix times 12 (1 - cos h) / (h^2 (4 + 2 cos h)) = 1.0524 (the periodic
  // moment equations for cos and sin), so curvature is off by about 5%;
  // torsion also uses the third derivative, piecewise constant, off by O(h).
  IdList interior(line.begin() + 4 * 10, line.end() - 4 * 10);
  double curvatureError = 0;
  double torsionError = 0;
  for (const vtkIdType id : interior)
  {
    curvatureError = std::max(curvatureError,
      std::abs(PointArray(curve, "Curvature")->GetTuple1(id) - HelixCurvature) / HelixCurvature);
    torsionError = std::max(torsionError,
      std::abs(PointArray(curve, "Torsion")->GetTuple1(id) - HelixTorsion) / HelixTorsion);
  }
  Measure("helix_interior_curvature_max_relative_error", curvatureError);
  Measure("helix_interior_torsion_max_relative_error", torsionError);
  EXPECT_LT(curvatureError, 0.08);
  EXPECT_LT(torsionError, 0.15);
}

TEST(CubicSplineFilter, DataPointsAmongSamplesForAnySubdivisions)
{
  const auto helix = ReadData("helix.vtp");
  const Polyline data = PointsOfLine(helix, LinesOf(helix)[0]);
  for (const int subdivisions : { 1, 3, 7 })
  {
    SCOPED_TRACE("NumberOfSubdivisions " + std::to_string(subdivisions));
    const FilterRun run =
      RunCubic(helix, [&](vtkCubicSplineFilter* f) { f->SetNumberOfSubdivisions(subdivisions); });
    ExpectNoMessages(run);
    ExpectDataPointsAmongSamples(data, run.Output, LinesOf(run.Output)[0], subdivisions);
  }
}

TEST(CubicSplineFilter, IntegerArraysTakeTheNearerDataPointFloatArraysInterpolate)
{
  const Polyline points = { { 0, 0, 0 }, { 1, 0.5, 0 }, { 2, 0, 0.5 }, { 3, 1, 0 } };
  const auto input = PolyDataBuilder().Line(points).Build();
  vtkNew<vtkIntArray> labels; // an id-like integer array: 10 * point id
  labels->SetName("Label");
  for (int i = 0; i < 4; ++i)
  {
    labels->InsertNextValue(10 * i);
  }
  input->GetPointData()->AddArray(labels);
  const FilterRun run = RunCubic(input, [](vtkCubicSplineFilter* f) {
    f->SetParameterizationToUniform(); // parameter fraction = sample index / 4
    f->SetNumberOfSubdivisions(4);
  });
  ExpectNoMessages(run);
  vtkDataArray* label = PointArray(run.Output, "Label");
  vtkDataArray* value = PointArray(run.Output, "Value");
  ASSERT_TRUE(label && value);
  EXPECT_EQ(label->GetDataType(), VTK_INT);
  const IdList line = LinesOf(run.Output)[0];
  for (size_t k = 0; k < line.size(); ++k)
  {
    const size_t span = std::min<size_t>(k / 4, 2);
    const double fraction = (static_cast<double>(k) - 4.0 * span) / 4.0;
    const double nearer = 10.0 * (fraction < 0.5 ? span : span + 1);
    EXPECT_EQ(label->GetTuple1(line[k]), nearer) << "sample " << k;
    const Point a = points[span], b = points[span + 1];
    const double linear = (1 - fraction) * (a[0] + 2 * a[1] + 3 * a[2]) +
      fraction * (b[0] + 2 * b[1] + 3 * b[2]);
    EXPECT_NEAR(value->GetTuple1(line[k]), linear, 1e-12) << "sample " << k;
  }
}

// ===========================================================================
// Closed lines.

constexpr double CircleRadius = 3.0;
constexpr int CirclePoints = 16;
const Point CircleCenter = { 1.0, -2.0, 0.5 };

/// The circle's points with the first id repeated at the end (closed by data).
vtkSmartPointer<vtkPolyData> ClosedCircleData()
{
  PolyDataBuilder builder;
  IdList ids = builder.AddPoints(Circle(CircleRadius, CirclePoints, CircleCenter));
  ids.push_back(ids.front());
  return builder.LineIds(ids).Build();
}

TEST(CubicSplineFilter, ClosedLineIsPeriodicWithoutSeamDuplicate)
{
  const FilterRun run = RunCubic(ClosedCircleData());
  ExpectNoMessages(run);
  vtkPolyData* curve = run.Output;
  const auto lines = LinesOf(curve);
  ASSERT_EQ(lines.size(), 1u);
  const IdList& line = lines[0];
  const int subdivisions = 10;

  // The cell is closed by repeating its first id; the seam point is stored once.
  ASSERT_EQ(line.size(), static_cast<size_t>(CirclePoints * subdivisions + 1));
  EXPECT_EQ(line.front(), line.back());
  EXPECT_EQ(curve->GetNumberOfPoints(), CirclePoints * subdivisions);
  IdList distinct = DistinctIds(line);
  std::sort(distinct.begin(), distinct.end());
  EXPECT_EQ(std::adjacent_find(distinct.begin(), distinct.end()), distinct.end());
  const Point seam = PointOf(curve, line.front());
  for (size_t k = 1; k + 1 < line.size(); ++k)
  {
    EXPECT_GT(Norm(PointOf(curve, line[k]) - seam), 1e-6) << "sample " << k << " repeats the seam";
  }

  // Curvature of the periodic spline through 16 points of a circle of radius R.
  // With h = 2 pi / 16 (equal chords make chord-length knots uniform, and
  // curvature ignores a uniform rescaling of the parameter) the spline's
  // second derivative at a knot is the circle's times
  // lambda = 12 (1 - cos h) / (h^2 (4 + 2 cos h)) and its first derivative the
  // circle's times mu = sin h (1 / h + h lambda / 6); they stay orthogonal, so
  // kappa R = lambda / mu^2 = 1.01319 at every knot: a C2 cubic through 16
  // points cannot be within 1% of the circle's curvature there.
  const double h = 2 * Pi / CirclePoints;
  const double lambda = 12 * (1 - std::cos(h)) / (h * h * (4 + 2 * std::cos(h)));
  const double mu = std::sin(h) * (1 / h + h * lambda / 6);
  const double atKnots = lambda / (mu * mu);
  Measure("circle16_predicted_knot_curvature_relative_error", atKnots - 1);
  vtkDataArray* curvature = PointArray(curve, "Curvature");
  double worst = 0;
  for (size_t k = 0; k + 1 < line.size(); ++k)
  {
    const double relative = curvature->GetTuple1(line[k]) * CircleRadius;
    worst = std::max(worst, std::abs(relative - 1.0));
    if (k % subdivisions == 0)
    {
      EXPECT_NEAR(relative, atKnots, 1e-9) << "knot " << k / subdivisions;
    }
  }
  Measure("circle16_curvature_max_relative_error", worst);
  EXPECT_LT(worst, 0.015);
  EXPECT_LE(MaxAbs(PointArray(curve, "Torsion"), line), 1e-12);
  ExpectOrthonormalFrames(curve, line);

  EXPECT_EQ(CellArray(curve, "Tortuosity")->GetTuple1(0), 0.0);
  const double length = CellArray(curve, "Length")->GetTuple1(0);
  Measure("circle16_length_relative_error", length / (2 * Pi * CircleRadius) - 1);
  EXPECT_NEAR(length, 2 * Pi * CircleRadius, 1e-3 * 2 * Pi * CircleRadius);
}

TEST(CubicSplineFilter, ClosedOptionEqualsRepeatedSeam)
{
  const FilterRun byData = RunCubic(ClosedCircleData());
  const FilterRun byOption =
    RunCubic(PolylinesData({ Circle(CircleRadius, CirclePoints, CircleCenter) }),
      [](vtkCubicSplineFilter* f) { f->ClosedOn(); });
  ExpectNoMessages(byOption);
  ExpectPolyDataNear(byData.Output, byOption.Output, 1e-12, "Closed option vs repeated seam");
}

// ===========================================================================
// Bad input.

TEST(CubicSplineFilter, EmptyInput)
{
  vtkNew<vtkPolyData> empty;
  const FilterRun run = RunCubic(empty);
  EXPECT_TRUE(run.Errors.empty()) << Joined(run.Errors);
  EXPECT_EQ(CountMessages(run.Warnings, { "no lines" }), 1) << Joined(run.Warnings);
  EXPECT_EQ(run.Output->GetNumberOfPoints(), 0);
  EXPECT_EQ(run.Output->GetNumberOfCells(), 0);
}

TEST(CubicSplineFilter, OnePointLinePassedThrough)
{
  const Point lone = { 1.5, -2.5, 3.25 };
  const auto input = PolylinesData({ AkimaPoints(), { lone } });
  const FilterRun run = RunCubic(input);
  EXPECT_TRUE(run.Errors.empty()) << Joined(run.Errors);
  EXPECT_EQ(CountMessages(run.Warnings, { "cell 1", "fewer than two distinct points" }), 1)
    << Joined(run.Warnings);

  const auto lines = LinesOf(run.Output);
  ASSERT_EQ(lines.size(), 2u);
  ASSERT_EQ(lines[1].size(), 1u);
  EXPECT_EQ(PointOf(run.Output, lines[1][0]), lone);
  EXPECT_EQ(
    PointArray(run.Output, "Value")->GetTuple1(lines[1][0]), lone[0] + 2 * lone[1] + 3 * lone[2]);
  EXPECT_EQ(CellArray(run.Output, "InputCellId")->GetTuple1(1), 1.0);
  EXPECT_EQ(CellArray(run.Output, "Length")->GetTuple1(1), 0.0);
  ExpectAllFinite(run.Output);
}

TEST(CubicSplineFilter, TwoPointLineIsStraightSegment)
{
  const Point a = { 1, 2, 3 };
  const Point b = { 4, -2, 15 };
  const FilterRun run = RunCubic(PolylinesData({ { a, b } }));
  EXPECT_TRUE(run.Errors.empty()) << Joined(run.Errors);
  EXPECT_EQ(CountMessages(run.Warnings, { "cell 0", "two distinct points" }), 1)
    << Joined(run.Warnings);

  vtkPolyData* curve = run.Output;
  ExpectAllFinite(curve);
  const IdList line = LinesOf(curve).at(0);
  ASSERT_EQ(line.size(), 11u);
  const Point direction = (1.0 / Norm(b - a)) * (b - a);
  for (size_t k = 0; k < line.size(); ++k)
  {
    const Point p = PointOf(curve, line[k]);
    EXPECT_NEAR(Norm(Cross(p - a, direction)), 0.0, 1e-12) << "sample " << k << " off the segment";
    EXPECT_NEAR(Norm(Vector(PointArray(curve, "Tangent"), line[k]) - direction), 0.0, 1e-12);
  }
  EXPECT_EQ(MaxAbs(PointArray(curve, "Curvature"), line), 0.0);
  EXPECT_EQ(MaxAbs(PointArray(curve, "Torsion"), line), 0.0);
  ExpectOrthonormalFrames(curve, line);
  // On a straight span the input's Value = x + 2y + 3z, interpolated linearly,
  // is the same function of the sample's position.
  vtkDataArray* value = PointArray(curve, "Value");
  for (const vtkIdType id : line)
  {
    const Point p = PointOf(curve, id);
    EXPECT_NEAR(value->GetTuple1(id), p[0] + 2 * p[1] + 3 * p[2], 1e-12) << "sample " << id;
  }
  EXPECT_NEAR(CellArray(curve, "Length")->GetTuple1(0), Norm(b - a), 1e-12 * Norm(b - a));
  EXPECT_NEAR(CellArray(curve, "Tortuosity")->GetTuple1(0), 1.0, 1e-12);
}

/// Three points give the interpolating parabola (not-a-knot, the default): a
/// planar curve whose third derivative vanishes, so torsion is exactly 0.
void ExpectThreePointParabola(const Polyline& points, const std::string& name)
{
  SCOPED_TRACE(name);
  const FilterRun run = RunCubic(PolylinesData({ points }));
  ExpectNoMessages(run);
  vtkPolyData* curve = run.Output;
  ExpectAllFinite(curve);
  const IdList line = LinesOf(curve).at(0);
  ExpectDataPointsAmongSamples(points, curve, line, 10);
  vtkDataArray* curvature = PointArray(curve, "Curvature");
  for (const vtkIdType id : line)
  {
    EXPECT_GT(curvature->GetTuple1(id), 0.0) << "sample " << id;
  }
  // Every sample lies in the plane of the three points.
  const Point planeNormal = Cross(points[1] - points[0], points[2] - points[0]);
  for (const vtkIdType id : line)
  {
    EXPECT_NEAR(Dot(PointOf(curve, id) - points[0], planeNormal) / Norm(planeNormal), 0.0, 1e-12);
  }
  const double torsion = MaxAbs(PointArray(curve, "Torsion"), line);
  Measure(name + "_max_abs_torsion", torsion);
  EXPECT_EQ(torsion, 0.0);
  ExpectOrthonormalFrames(curve, line);
}

TEST(CubicSplineFilter, ThreePointLineIsPlanarCurve)
{
  ExpectThreePointParabola({ { 0, 0, 0 }, { 1, 2, 0 }, { 3, 1, 0 } }, "three_points_z0");
  ExpectThreePointParabola({ { 0, 0, 0 }, { 1, 2, 0.5 }, { 3, 1, 2 } }, "three_points_3d");
}

TEST(CubicSplineFilter, RepeatedPointsMerged)
{
  const Polyline clean = { { 0, 0, 0 }, { 1, 1, 0.2 }, { 2, 0.5, 0.7 }, { 3, 1.5, 0.4 },
    { 4, 0.2, 1.0 } };
  // Duplicates at the start, in the middle and at the end: 3 + 1 + 2 = 6 repeats.
  const Polyline repeated = { clean[0], clean[0], clean[0], clean[0], clean[1], clean[2], clean[2],
    clean[3], clean[4], clean[4], clean[4] };
  const FilterRun withRepeats = RunCubic(PolylinesData({ clean, repeated }));
  EXPECT_TRUE(withRepeats.Errors.empty()) << Joined(withRepeats.Errors);
  // A routine merge is counted, not warned about.
  EXPECT_TRUE(withRepeats.Warnings.empty()) << Joined(withRepeats.Warnings);
  EXPECT_EQ(CellArray(withRepeats.Output, "MergedPoints")->GetTuple1(0), 0);
  EXPECT_EQ(CellArray(withRepeats.Output, "MergedPoints")->GetTuple1(1), 6);
  ExpectAllFinite(withRepeats.Output);

  // Both cells are the same curve (Value interpolated along it alike).
  vtkPolyData* curve = withRepeats.Output;
  const auto lines = LinesOf(curve);
  ASSERT_EQ(lines.size(), 2u);
  ASSERT_EQ(lines[0].size(), lines[1].size());
  for (size_t k = 0; k < lines[0].size(); ++k)
  {
    EXPECT_NEAR(Norm(PointOf(curve, lines[0][k]) - PointOf(curve, lines[1][k])), 0.0, 1e-12);
    for (const auto& [name, components] : CurvePointArrays)
    {
      for (int c = 0; c < components; ++c)
      {
        EXPECT_NEAR(PointArray(curve, name)->GetComponent(lines[0][k], c),
          PointArray(curve, name)->GetComponent(lines[1][k], c), 1e-12)
          << name << " sample " << k;
      }
    }
    EXPECT_NEAR(PointArray(curve, "Value")->GetTuple1(lines[0][k]),
      PointArray(curve, "Value")->GetTuple1(lines[1][k]), 1e-12);
  }
  for (const char* name : CurveCellArrays)
  {
    EXPECT_NEAR(CellArray(curve, name)->GetTuple1(0), CellArray(curve, name)->GetTuple1(1), 1e-12)
      << name;
  }
}

TEST(CubicSplineFilter, NonLineCellsIgnored)
{
  PolyDataBuilder builder;
  builder.Vertex({ 9, 9, 9 })
    .Line(AkimaPoints())
    .Polygon({ { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 } })
    .Strip({ { 0, 0, 2 }, { 1, 0, 2 }, { 0, 1, 2 }, { 1, 1, 2 } });
  const auto input = builder.Build();
  ASSERT_EQ(input->GetNumberOfCells(), 4);
  const FilterRun run = RunCubic(input);
  EXPECT_TRUE(run.Errors.empty()) << Joined(run.Errors);
  EXPECT_EQ(CountMessages(run.Warnings, { "3 non-line cells" }), 1) << Joined(run.Warnings);

  vtkPolyData* curve = run.Output;
  EXPECT_EQ(curve->GetNumberOfCells(), 1);
  EXPECT_EQ(curve->GetNumberOfLines(), 1);
  // The line is input cell 1 (verts come first): its cell data follows it.
  EXPECT_EQ(CellArray(curve, "InputCellId")->GetTuple1(0), 1.0);
  const FilterRun alone = RunCubic(PolylinesData({ AkimaPoints() }));
  EXPECT_EQ(curve->GetNumberOfPoints(), alone.Output->GetNumberOfPoints());
  ExpectDataPointsAmongSamples(AkimaPoints(), curve, LinesOf(curve).at(0), 10);
}

/// A line with a NaN and an Inf coordinate next to a good line; the parameter
/// is the cell id of the bad line (0 or 1).
class NonFiniteLine : public ::testing::TestWithParam<int>
{
};

TEST_P(NonFiniteLine, SkippedWithErrorNamingCell)
{
  const int badCell = GetParam();
  const Polyline good = AkimaPoints();
  const Polyline bad = { { 0, 0, 0 }, { 1, NaN, 0 }, { 2, 1, 0 }, { Inf, 2, 1 }, { 4, 2, 0 } };
  const auto input = PolylinesData(
    badCell == 0 ? std::vector<Polyline>{ bad, good } : std::vector<Polyline>{ good, bad });
  const FilterRun run = RunCubic(input);
  EXPECT_EQ(run.Errors.size(), 1u) << Joined(run.Errors);
  EXPECT_EQ(CountMessages(run.Errors, { "cell " + std::to_string(badCell), "not finite" }), 1)
    << Joined(run.Errors);
  EXPECT_TRUE(run.Warnings.empty()) << Joined(run.Warnings);

  // The good line comes out as if it were alone, with its own cell data.
  const FilterRun alone = RunCubic(PolylinesData({ good }));
  vtkPolyData* curve = run.Output;
  ExpectAllFinite(curve);
  ASSERT_EQ(curve->GetNumberOfCells(), 1);
  EXPECT_EQ(CellArray(curve, "InputCellId")->GetTuple1(0), static_cast<double>(1 - badCell));
  // The rest is as if alone: Value = x + 2y + 3z interpolates alike whatever the point ids.
  curve->GetCellData()->RemoveArray("InputCellId");
  alone.Output->GetCellData()->RemoveArray("InputCellId");
  ExpectPolyDataNear(alone.Output, curve, 1e-12, "good line next to a bad one");
}

INSTANTIATE_TEST_SUITE_P(CubicSplineFilter, NonFiniteLine, ::testing::Values(0, 1));

// ===========================================================================
// Planar and straight input.

TEST(CubicSplineFilter, AkimaTorsionZero)
{
  const auto akima = ReadData("akima.vtp");
  const FilterRun run = RunCubic(akima);
  ExpectNoMessages(run);
  const IdList line = LinesOf(run.Output).at(0);
  const double torsion = MaxAbs(PointArray(run.Output, "Torsion"), line);
  Measure("akima_max_abs_torsion", torsion);
  EXPECT_LE(torsion, 1e-12);
  ExpectOrthonormalFrames(run.Output, line);
  // The frames of a z = 0 curve: binormal along +-z, where the curve bends.
  vtkDataArray* curvature = PointArray(run.Output, "Curvature");
  for (const vtkIdType id : line)
  {
    if (curvature->GetTuple1(id) > 0)
    {
      EXPECT_NEAR(std::abs(Vector(PointArray(run.Output, "Binormal"), id)[2]), 1.0, 1e-12);
    }
  }
}

/// A plane through Origin spanned by the orthogonal (not necessarily unit) U and V.
struct TiltedPlane
{
  std::string Name;
  Point Origin;
  Point U;
  Point V;
};

/**
 * Places planar (x, y, 0) points in a tilted plane and checks that the cubic's
 * torsion is only the rounding that the tilt brings.
 *
 * Model: the out-of-plane component w(t) of the spline is the cubic spline
 * through the data's out-of-plane rounding, |w_i| <= delta; the moment
 * equations bound its third derivative by 24 delta / h^3 (alternating noise on
 * uniform knots is the worst case). To first order torsion = w''' /
 * (kappa |s'|^2) plus terms of the same size, so with chord-length knots
 * (|s'| near 1) |tau| kappa <= C delta / h_min^3; C = 100 leaves a factor 4
 * for the speed and the other terms. delta is the data's measured distance
 * from the plane, at least DBL_EPSILON times the coordinates (the spline's own
 * rounding). Near an inflection kappa -> 0 and tau may grow like 1 / kappa:
 * that is rounding, not a flaw, hence a bound on tau kappa rather than on tau.
 */
void ExpectTorsionOnlyFromRounding(const Polyline& planar, const TiltedPlane& plane)
{
  SCOPED_TRACE(plane.Name);
  const Polyline points = InPlane(planar, plane.Origin, plane.U, plane.V);
  const Point normal = (1.0 / Norm(Cross(plane.U, plane.V))) * Cross(plane.U, plane.V);

  long double distance = 0;
  double size = 0;
  double shortest = std::numeric_limits<double>::max();
  double diagonal = 0;
  for (size_t i = 0; i < points.size(); ++i)
  {
    const Point& p = points[i];
    long double offset = 0;
    for (int c = 0; c < 3; ++c)
    {
      offset += (static_cast<long double>(p[c]) - plane.Origin[c]) * normal[c];
      size = std::max(size, std::abs(p[c]));
    }
    distance = std::max(distance, std::abs(offset));
    if (i > 0)
    {
      shortest = std::min(shortest, Norm(p - points[i - 1]));
    }
    for (const Point& q : points)
    {
      diagonal = std::max(diagonal, Norm(p - q));
    }
  }
  const double delta =
    std::max(static_cast<double>(distance), std::numeric_limits<double>::epsilon() * size);

  const FilterRun run = RunCubic(PolylinesData({ points }));
  ExpectNoMessages(run);
  vtkPolyData* curve = run.Output;
  const IdList line = LinesOf(curve).at(0);
  ExpectOrthonormalFrames(curve, line);
  vtkDataArray* curvature = PointArray(curve, "Curvature");
  vtkDataArray* torsion = PointArray(curve, "Torsion");
  double ratio = 0;
  for (const vtkIdType id : line)
  {
    EXPECT_NEAR(Dot(PointOf(curve, id) - plane.Origin, normal), 0.0, 1e-12) << "sample " << id;
    ratio = std::max(ratio,
      std::abs(torsion->GetTuple1(id)) * curvature->GetTuple1(id) * std::pow(shortest, 3) / delta);
  }
  Measure(plane.Name + "_data_distance_from_plane", static_cast<double>(distance));
  Measure(plane.Name + "_max_abs_torsion_times_size", MaxAbs(torsion, line) * diagonal);
  Measure(plane.Name + "_max_tau_kappa_h3_over_delta", ratio);
  EXPECT_LE(ratio, 100.0);
}

Polyline EllipticArc()
{
  Polyline arc;
  for (int i = 0; i <= 8; ++i)
  {
    arc.push_back({ 5 * std::cos(0.2 * i), 3 * std::sin(0.2 * i), 0 });
  }
  return arc;
}

TEST(CubicSplineFilter, TiltedPlaneTorsionIsRoundingOnly)
{
  const Point origin = { 12.5, -7.25, 3.0 };
  for (const auto& [name, points] :
    { std::make_pair("arc", EllipticArc()), std::make_pair("akima", AkimaPoints()) })
  {
    const std::string prefix = std::string("tilted_") + name;
    // Dyadic basis: the points lie exactly on the plane x + y + z = 8.25.
    ExpectTorsionOnlyFromRounding(
      points, { prefix + "_dyadic", origin, { 0.5, -0.5, 0 }, { 0.5, 0.5, -1 } });
    // Orthonormal basis in thirds: the points leave the plane by rounding.
    ExpectTorsionOnlyFromRounding(points,
      { prefix + "_thirds", origin, { 1.0 / 3, 2.0 / 3, 2.0 / 3 },
        { 2.0 / 3, 1.0 / 3, -2.0 / 3 } });
  }
}

/// Five collinear, unevenly spaced points offset from the origin by the parameter.
class CollinearLine : public ::testing::TestWithParam<double>
{
};

TEST_P(CollinearLine, FlatFramesStayContinuous)
{
  const double offset = GetParam();
  const Point direction = { 1.0 / 7, 3.0 / 7, 6.0 / 7 }; // |d| = sqrt(46)/7: not unit on purpose
  const Point origin = { offset, -0.5 * offset, 0.25 * offset };
  Polyline points;
  for (const double s : { 0.0, 1.0, 3.0, 4.0, 7.5 })
  {
    points.push_back(origin + s * direction);
  }
  for (const int parameterization : { vtkShapeSplineFilter::UNIFORM,
         vtkShapeSplineFilter::CHORD_LENGTH, vtkShapeSplineFilter::CENTRIPETAL })
  {
    const std::string name = std::string("collinear_offset_") +
      std::to_string(static_cast<int>(offset)) + "_parameterization_" +
      std::to_string(parameterization);
    SCOPED_TRACE(name);
    const FilterRun run = RunCubic(PolylinesData({ points }),
      [&](vtkCubicSplineFilter* f) { f->SetParameterization(parameterization); });
    ExpectNoMessages(run);
    vtkPolyData* curve = run.Output;
    ExpectAllFinite(curve);
    const IdList line = LinesOf(curve).at(0);
    const double curvature = MaxAbs(PointArray(curve, "Curvature"), line);
    Measure(name + "_max_curvature", curvature);
    // The points are collinear only up to the rounding of their coordinates
    // (eps * |offset|), which the spline turns into curvature of order
    // eps |p| / h^2 (h = 1 * |direction|, the shortest segment); it is reported as it
    // is, far below anything real, while the frame ignores it (torsion 0, no flips).
    const double shortest = std::sqrt(46.0) / 7;
    const double rounding =
      std::numeric_limits<double>::epsilon() * (std::abs(offset) + 7.5 * shortest);
    EXPECT_LE(curvature, 1e3 * rounding / (shortest * shortest));
    EXPECT_EQ(MaxAbs(PointArray(curve, "Torsion"), line), 0.0);
    ExpectOrthonormalFrames(curve, line);
    vtkDataArray* normal = PointArray(curve, "Normal");
    double worstTurn = 0;
    for (size_t k = 1; k < line.size(); ++k)
    {
      const double cosine = Dot(Vector(normal, line[k - 1]), Vector(normal, line[k]));
      worstTurn = std::max(worstTurn, 1.0 - cosine);
    }
    Measure(name + "_max_normal_turn", worstTurn);
    EXPECT_LT(worstTurn, 1e-9) << "the normal turns between consecutive samples";
  }
}

INSTANTIATE_TEST_SUITE_P(CubicSplineFilter, CollinearLine, ::testing::Values(0.0, 1e3, 1e6));

// ===========================================================================
// vtkPolylineShapeAnalysis.

/// The analysis of data alone, or audited against the cubic spline of data.
FilterRun RunAnalysis(vtkPolyData* data, bool withCubic)
{
  vtkNew<vtkPolylineShapeAnalysis> analysis;
  vtkNew<vtkCubicSplineFilter> cubic;
  analysis->SetInputData(data);
  if (withCubic)
  {
    cubic->SetInputData(data);
    analysis->SetCurveConnection(cubic->GetOutputPort());
  }
  return UpdateChecked(data, analysis, { analysis, cubic });
}

TEST(PolylineShapeAnalysis, AkimaDiscreteShape)
{
  const auto akima = ReadData("akima.vtp");
  const FilterRun run = RunAnalysis(akima, false);
  ExpectNoMessages(run);
  vtkPolyData* out = run.Output;
  ASSERT_EQ(out->GetNumberOfPoints(), 11);
  const std::vector<std::pair<const char*, int>> arrays = { { "DiscreteCurvature", 1 },
    { "DiscreteTorsion", 1 }, { "DiscreteBinormal", 3 }, { "Collinear", 1 }, { "Convex", 1 },
    { "Coplanar", 1 } };
  for (const auto& [name, components] : arrays)
  {
    vtkDataArray* array = PointArray(out, name);
    ASSERT_NE(array, nullptr);
    EXPECT_EQ(array->GetNumberOfComponents(), components) << name;
    EXPECT_EQ(array->GetNumberOfTuples(), 11) << name;
  }
  EXPECT_EQ(out->GetPointData()->GetArray("ViolationMask"), nullptr) << "no audit without a curve";

  // y = 10 for points 0..5: the interior points 1..4 are collinear, nothing else.
  vtkDataArray* collinear = PointArray(out, "Collinear");
  vtkDataArray* convex = PointArray(out, "Convex");
  for (vtkIdType i = 0; i < 11; ++i)
  {
    EXPECT_EQ(collinear->GetTuple1(i), (i >= 1 && i <= 4) ? 1.0 : 0.0) << "point " << i;
    EXPECT_EQ(convex->GetTuple1(i), (i >= 5 && i <= 9) ? 1.0 : 0.0) << "point " << i;
  }
  EXPECT_EQ(
    MaxAbs(PointArray(out, "DiscreteTorsion"), IdList{ 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 }), 0.0);
}

TEST(PolylineShapeAnalysis, HelixDiscreteCurvatureAndTorsion)
{
  const auto helix = ReadData("helix.vtp");
  const FilterRun run = RunAnalysis(helix, false);
  ExpectNoMessages(run);
  vtkDataArray* curvature = PointArray(run.Output, "DiscreteCurvature");
  vtkDataArray* torsion = PointArray(run.Output, "DiscreteTorsion");
  ASSERT_TRUE(curvature && torsion);

  // Menger curvature of three consecutive helix points, 1 / circumradius
  // = 2 |a x b| / (|a| |b| |a + b|): the same at every interior point. With 8
  // points per turn it is 1.05% below the helix's 0.4, hence the 5% bound.
  const Point before = HelixPoint(0) - HelixPoint(-HelixStep);
  const Point after = HelixPoint(HelixStep) - HelixPoint(0);
  const double menger =
    2 * Norm(Cross(before, after)) / (Norm(before) * Norm(after) * Norm(before + after));
  Measure("helix_menger_relative_to_0.4", menger / HelixCurvature - 1);
  double worst = 0;
  for (vtkIdType i = 1; i < 32; ++i)
  {
    EXPECT_NEAR(curvature->GetTuple1(i), menger, 1e-12) << "point " << i;
    worst = std::max(worst, std::abs(curvature->GetTuple1(i) / HelixCurvature - 1));
  }
  Measure("helix_discrete_curvature_max_relative_error", worst);
  EXPECT_LT(worst, 0.05);
  EXPECT_EQ(curvature->GetTuple1(0), 0.0);
  EXPECT_EQ(curvature->GetTuple1(32), 0.0);

  // The segments with interior points at both ends (1..30) twist right-handedly.
  for (vtkIdType i = 1; i <= 30; ++i)
  {
    EXPECT_GT(torsion->GetTuple1(i), 0.0) << "segment " << i;
  }
  EXPECT_EQ(torsion->GetTuple1(0), 0.0);
  EXPECT_EQ(torsion->GetTuple1(31), 0.0);
}

TEST(PolylineShapeAnalysis, CubicBreaksAkimaShape)
{
  const auto akima = ReadData("akima.vtp");
  const FilterRun run = RunAnalysis(akima, true);
  ExpectNoMessages(run);
  const double violations = CellArray(run.Output, "ShapeViolations")->GetTuple1(0);
  Measure("akima_analysis_shape_violations", violations);
  EXPECT_GT(violations, 0);
  EXPECT_EQ(CellArray(run.Output, "ShapePreserving")->GetTuple1(0), 0.0);
  vtkDataArray* mask = PointArray(run.Output, "ViolationMask");
  ASSERT_NE(mask, nullptr);
  int flagged = 0;
  for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i)
  {
    flagged += mask->GetTuple1(i) != 0;
  }
  Measure("akima_analysis_flagged_segments", flagged);
  EXPECT_GT(flagged, 0);

  // The spline filter's own audit agrees that the shape is broken.
  const FilterRun cubic = RunCubic(akima);
  const double own = CellArray(cubic.Output, "ShapeViolations")->GetTuple1(0);
  Measure("akima_filter_shape_violations", own);
  EXPECT_GT(own, 0);
  EXPECT_EQ(CellArray(cubic.Output, "ShapePreserving")->GetTuple1(0), 0.0);
}

TEST(PolylineShapeAnalysis, CubicKeepsHelixShape)
{
  const auto helix = ReadData("helix.vtp");
  const FilterRun run = RunAnalysis(helix, true);
  ExpectNoMessages(run);
  EXPECT_EQ(CellArray(run.Output, "ShapeViolations")->GetTuple1(0), 0.0);
  EXPECT_EQ(CellArray(run.Output, "ShapePreserving")->GetTuple1(0), 1.0);
  vtkDataArray* mask = PointArray(run.Output, "ViolationMask");
  ASSERT_NE(mask, nullptr);
  for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i)
  {
    EXPECT_EQ(mask->GetTuple1(i), 0.0) << "point " << i;
  }
  const FilterRun cubic = RunCubic(helix);
  EXPECT_EQ(CellArray(cubic.Output, "ShapeViolations")->GetTuple1(0), 0.0);
}

// ===========================================================================
// Properties: PrintSelf and clamping.

template <typename Filter>
void ExpectPrintSelfMentions(Filter* filter, const std::vector<std::string>& names)
{
  std::ostringstream text;
  filter->Print(text);
  for (const std::string& name : names)
  {
    EXPECT_NE(text.str().find(name + ":"), std::string::npos) << name << " missing from\n"
                                                              << text.str();
  }
}

TEST(Properties, PrintSelfMentionsEveryProperty)
{
  vtkNew<vtkCubicSplineFilter> cubic;
  ExpectPrintSelfMentions(cubic.Get(),
    { "EndCondition", "Parameterization", "Closed", "SamplingMode", "NumberOfSubdivisions",
      "SampleLength", "DataShapeTolerance", "CurveShapeTolerance", "VMTKArrayNames" });
  vtkNew<vtkPolylineShapeAnalysis> analysis;
  ExpectPrintSelfMentions(
    analysis.Get(), { "Closed", "DataShapeTolerance", "CurveShapeTolerance" });
}

TEST(Properties, ClampMacrosClamp)
{
  vtkNew<vtkCubicSplineFilter> f;
  EXPECT_EQ(f->GetNumberOfSubdivisions(), 10);
  f->SetNumberOfSubdivisions(0);
  EXPECT_EQ(f->GetNumberOfSubdivisions(), 1);
  f->SetNumberOfSubdivisions(1000000);
  EXPECT_EQ(f->GetNumberOfSubdivisions(), 100000);
  f->SetEndCondition(-1);
  EXPECT_EQ(f->GetEndCondition(), vtkCubicSplineFilter::NATURAL);
  f->SetEndCondition(7);
  EXPECT_EQ(f->GetEndCondition(), vtkCubicSplineFilter::CLAMPED);
  f->SetParameterization(9);
  EXPECT_EQ(f->GetParameterization(), vtkShapeSplineFilter::CENTRIPETAL);
  f->SetParameterization(-2);
  EXPECT_EQ(f->GetParameterization(), vtkShapeSplineFilter::UNIFORM);
  f->SetSamplingMode(5);
  EXPECT_EQ(f->GetSamplingMode(), vtkShapeSplineFilter::ARC_LENGTH);
  f->SetSampleLength(-1.0); // refused when the filter runs (Settings tests)
  EXPECT_EQ(f->GetSampleLength(), 0.0);
  f->SetDataShapeTolerance(2.0);
  EXPECT_EQ(f->GetDataShapeTolerance(), 1.0);
  f->SetCurveShapeTolerance(-0.5);
  EXPECT_EQ(f->GetCurveShapeTolerance(), 0.0);

  vtkNew<vtkPolylineShapeAnalysis> a;
  a->SetDataShapeTolerance(-1.0);
  EXPECT_EQ(a->GetDataShapeTolerance(), 0.0);
  a->SetCurveShapeTolerance(3.0);
  EXPECT_EQ(a->GetCurveShapeTolerance(), 1.0);
}

// ===========================================================================
// Parallel execution.

/// splitmix64: the same numbers on every platform.
class Random
{
public:
  explicit Random(std::uint64_t seed)
    : State(seed)
  {
  }
  std::uint64_t Next()
  {
    std::uint64_t z = (this->State += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [lo, hi).
  double Uniform(double lo, double hi)
  {
    return lo + (hi - lo) * static_cast<double>(this->Next() >> 11) * 0x1.0p-53;
  }

private:
  std::uint64_t State;
};

/// count random walks of 2..40 points; some closed by a repeated id, some with repeats.
vtkSmartPointer<vtkPolyData> RandomLines(int count)
{
  Random random(20240531);
  PolyDataBuilder builder;
  for (int l = 0; l < count; ++l)
  {
    Polyline walk = { { random.Uniform(-50, 50), random.Uniform(-50, 50),
      random.Uniform(-50, 50) } };
    const int size = 2 + static_cast<int>(random.Next() % 39);
    while (static_cast<int>(walk.size()) < size)
    {
      walk.push_back(
        walk.back() + Point{ random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-1, 1) });
      if (l % 11 == 0 && walk.size() == 3)
      {
        walk.push_back(walk.back());
      }
    }
    IdList ids = builder.AddPoints(walk);
    if (l % 7 == 0 && ids.size() >= 3)
    {
      ids.push_back(ids.front());
    }
    builder.LineIds(ids);
  }
  return builder.Build();
}

/// Selects an SMP backend (and thread count) for its lifetime.
class BackendScope
{
public:
  BackendScope(const char* backend, int threads)
    : Previous(vtkSMPTools::GetBackend())
  {
    this->Selected = vtkSMPTools::SetBackend(backend);
    vtkSMPTools::Initialize(threads);
  }
  ~BackendScope()
  {
    vtkSMPTools::SetBackend(this->Previous.c_str());
    vtkSMPTools::Initialize();
  }
  BackendScope(const BackendScope&) = delete;
  BackendScope& operator=(const BackendScope&) = delete;

  bool Selected = false;

private:
  std::string Previous;
};

TEST(Parallel, SameOutputWithThreadsAndSequential)
{
  const auto input = RandomLines(200);
  ASSERT_EQ(input->GetNumberOfLines(), 200);
  vtkNew<vtkCubicSplineFilter> filter;
  filter->SetInputData(input);
  MessageLog log({ filter });

  auto runWith = [&](const char* backend) {
    BackendScope scope(backend, 4);
    filter->SetNumberOfThreads(std::string(backend) == "Sequential" ? 1 : 0);
    EXPECT_TRUE(scope.Selected) << backend << " backend not available";
    EXPECT_STREQ(vtkSMPTools::GetBackend(), backend);
    if (std::string(backend) == "STDThread")
    {
      EXPECT_GT(vtkSMPTools::GetEstimatedNumberOfThreads(), 1);
    }
    filter->Modified();
    filter->Update();
    return DeepCopy(filter->GetOutput());
  };
  const auto sequential = runWith("Sequential");
  const auto sequentialWarnings = log.Warnings;
  EXPECT_EQ(sequential->GetNumberOfLines(), 200);
  ExpectAllFinite(sequential);
  // Repeats and two-point lines warn, in cell order whatever the backend.
  EXPECT_FALSE(sequentialWarnings.empty());
  for (int trial = 0; trial < 3; ++trial)
  {
    SCOPED_TRACE("STDThread run " + std::to_string(trial));
    log.Warnings.clear();
    const auto threaded = runWith("STDThread");
    EXPECT_EQ(sequentialWarnings, log.Warnings);
    ExpectPolyDataNear(sequential, threaded, 0.0, "STDThread vs Sequential");
  }
  EXPECT_TRUE(log.Errors.empty()) << Joined(log.Errors);
}

TEST(Parallel, ThreadsByDefaultWhenNobodyChoseABackend)
{
  // What the filter runs on, seen from its progress events (sent inside the run).
  const auto input = RandomLines(50);
  vtkNew<vtkCubicSplineFilter> filter;
  filter->SetInputData(input);
  // The executive's first and last events come outside the run: the backend
  // at the event halfway (after the fit) is the run's.
  struct Seen
  {
    std::string Backend;
    int Threads = 0;
  } seen;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&seen);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
    auto* s = static_cast<Seen*>(clientData);
    if (*static_cast<double*>(callData) == 0.8)
    {
      s->Backend = vtkSMPTools::GetBackend();
      s->Threads = vtkSMPTools::GetEstimatedNumberOfThreads();
    }
  });
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
  const char* chosen = std::getenv("VTK_SMP_BACKEND_IN_USE");
  const std::string saved = chosen ? chosen : "";
  unsetenv("VTK_SMP_BACKEND_IN_USE");
  BackendScope scope("Sequential", 0);
  filter->Update();
  EXPECT_EQ(seen.Backend, "STDThread");
  EXPECT_GT(seen.Threads, 1);
  EXPECT_STREQ(vtkSMPTools::GetBackend(), "Sequential") << "the process's backend changed";

  filter->SetNumberOfThreads(1);
  filter->Modified();
  seen = Seen{};
  filter->Update();
  EXPECT_EQ(seen.Backend, "Sequential");
  EXPECT_EQ(seen.Threads, 1);

  // A backend the user chose is kept.
  setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 1);
  filter->SetNumberOfThreads(0);
  filter->Modified();
  seen = Seen{};
  filter->Update();
  EXPECT_EQ(seen.Backend, "Sequential");
  if (chosen)
  {
    setenv("VTK_SMP_BACKEND_IN_USE", saved.c_str(), 1);
  }
  else
  {
    unsetenv("VTK_SMP_BACKEND_IN_USE");
  }
}

TEST(Progress, ThreadedRunsReportOnTheCallingThreadAndStopWhenAsked)
{
  // Threads by default: the lines run on the pool, the events come from here
  // (every 50 ms: a line of 2e5 points takes about a second on this machine).
  Polyline helix;
  for (int i = 0; i < 200000; ++i)
  {
    helix.push_back(HelixPoint(0.3 * i));
  }
  const auto input = PolylinesData({ helix });
  vtkNew<vtkCubicSplineFilter> filter;
  filter->SetInputData(input);
  struct Watch
  {
    std::thread::id Caller = std::this_thread::get_id();
    int ElsewhereEvents = 0;
    std::vector<double> Values;
  } watch;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&watch);
  observer->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void* callData) {
    auto* w = static_cast<Watch*>(clientData);
    w->ElsewhereEvents += std::this_thread::get_id() != w->Caller ? 1 : 0;
    w->Values.push_back(*static_cast<double*>(callData));
    if (w->Values.back() > 0.0 && w->Values.back() < 0.8)
    {
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1); // at the first event of the fit
    }
  });
  filter->AddObserver(vtkCommand::ProgressEvent, observer);
  filter->Update();
  EXPECT_EQ(watch.ElsewhereEvents, 0);
  const bool midFit = std::any_of(
    watch.Values.begin(), watch.Values.end(), [](double v) { return v > 0.0 && v < 0.8; });
  EXPECT_TRUE(midFit) << "no progress while the line was fitted";
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(Progress, EventsKeepComingWhileALongLinesSearchHoldsItsFraction)
{
  // The quintic's automatic search on a noisy line of 1e5 points holds the
  // line's fraction for seconds (its refining reports from 0 again): events
  // repeat the value a few times a second, and ParaView's Cancel, which acts
  // from an event, stops the fit there. Before events repeated, none came for
  // 7 s and the fit ran to its end.
  const auto input = PolylinesData(NoisyHelices(1, 100000, 0.003, 5));
  vtkNew<vtkTensionQuinticSplineFilter> filter;
  filter->SetInputData(input);
  struct Watch
  {
    std::vector<double> Values;
    bool Aborted = false;
  } watch;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&watch);
  observer->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void* callData) {
    auto* w = static_cast<Watch*>(clientData);
    const double value = *static_cast<double*>(callData);
    const auto& v = w->Values;
    const bool held = v.size() >= 2 && v.end()[-1] == value && v.end()[-2] == value;
    w->Values.push_back(value);
    if (held && value > 0.0 && value < 0.8 && !w->Aborted)
    {
      w->Aborted = true; // the third event in a row at one value, while fitting
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    }
  });
  filter->AddObserver(vtkCommand::ProgressEvent, observer);
  filter->Update();
  EXPECT_TRUE(watch.Aborted) << "no event repeated a held fraction: " << watch.Values.size()
                             << " events";
  EXPECT_TRUE(std::is_sorted(watch.Values.begin(), watch.Values.end()));
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(Progress, MovesWithTheLinesAndAbortLeavesAnEmptyOutput)
{
  const auto input = RandomLines(400);
  BackendScope scope("Sequential", 1);
  vtkNew<vtkCubicSplineFilter> filter;
  filter->SetNumberOfThreads(1); // deterministic events: one per 1% of the lines
  filter->SetInputData(input);
  MessageLog log({ filter });
  struct Watch
  {
    std::vector<double> Values;
    double AbortAt = 2.0;
  } watch;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&watch);
  observer->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void* callData) {
    auto* w = static_cast<Watch*>(clientData);
    w->Values.push_back(*static_cast<double*>(callData));
    if (w->Values.back() >= w->AbortAt)
    {
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    }
  });
  filter->AddObserver(vtkCommand::ProgressEvent, observer);
  filter->Update();
  // Fitting and writing report by lines (1% steps), not only at phase ends.
  EXPECT_GE(watch.Values.size(), 50u);
  EXPECT_TRUE(std::is_sorted(watch.Values.begin(), watch.Values.end()));
  EXPECT_EQ(watch.Values.back(), 1.0);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfLines(), 400);

  // One long line moves the bar too (the math core reports inside it).
  const auto lines = input;
  PolyDataBuilder builder;
  Polyline helix;
  for (int i = 0; i < 30000; ++i)
  {
    helix.push_back(HelixPoint(0.3 * i));
  }
  builder.Line(helix);
  const auto longLine = builder.Build();
  filter->SetInputData(longLine);
  watch = Watch{};
  filter->Update();
  EXPECT_GE(watch.Values.size(), 50u);
  EXPECT_TRUE(std::is_sorted(watch.Values.begin(), watch.Values.end()));
  EXPECT_EQ(filter->GetOutput()->GetNumberOfLines(), 1);

  for (const auto& [data, abortAt] : { std::make_pair(lines, 0.3), std::make_pair(lines, 0.85),
         std::make_pair(longLine, 0.3), std::make_pair(longLine, 0.85) })
  {
    filter->SetInputData(data); // abort while fitting, while writing
    watch = Watch{ {}, abortAt };
    filter->Modified();
    filter->Update();
    // The run stops at the next line: at most the end-of-run event follows.
    const auto aborted = std::find_if(
      watch.Values.begin(), watch.Values.end(), [&](double v) { return v >= abortAt; });
    ASSERT_NE(aborted, watch.Values.end()) << abortAt;
    EXPECT_LE(watch.Values.end() - aborted, 2) << abortAt << ", " << data->GetNumberOfPoints();
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << abortAt;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfLines(), 0) << abortAt;
    filter->SetAbortExecute(0);
  }
  EXPECT_TRUE(log.Errors.empty()) << Joined(log.Errors);
}
} // namespace

// ===========================================================================
// Curvature and torsion combs.

/// Runs a comb filter on a curve made by the cubic spline filter.
FilterRun RunComb(vtkPolyData* curve, const std::function<void(vtkCurvatureCombFilter*)>& setup)
{
  vtkNew<vtkCurvatureCombFilter> comb;
  setup(comb);
  comb->SetInputData(curve);
  return UpdateChecked(curve, comb, { comb });
}

TEST(CurvatureComb, CircleTeethPointOutwardWithLengthScaleOverRadius)
{
  const FilterRun curve = RunCubic(ClosedCircleData());
  const FilterRun run = RunComb(curve.Output, [](vtkCurvatureCombFilter*) {});
  ExpectNoMessages(run);
  vtkPolyData* comb = run.Output;
  const auto cells = LinesOf(comb);
  const vtkIdType samples = curve.Output->GetNumberOfPoints();
  ASSERT_EQ(static_cast<vtkIdType>(cells.size()), samples + 1); // teeth, then one envelope
  // Automatic scale: the 95th percentile tooth is 0.15 of the curve's bounding-box diagonal.
  const double diagonal = curve.Output->GetLength();
  const double scale = comb->GetFieldData()->GetArray("CombScale")->GetTuple1(0);
  vtkDataArray* normal = PointArray(curve.Output, "Normal");
  vtkDataArray* curvature = PointArray(curve.Output, "Curvature");
  std::vector<double> lengths;
  for (vtkIdType t = 0; t < samples; ++t)
  {
    ASSERT_EQ(cells[t].size(), 2u);
    const Point base = PointOf(comb, cells[t][0]);
    const Point tip = PointOf(comb, cells[t][1]);
    EXPECT_LT(Norm(base - PointOf(curve.Output, t)), 1e-15 * diagonal);
    // Along -Normal, scaled by the curvature: away from the centre of curvature.
    const Point expected = base - scale * curvature->GetTuple1(t) * Vector(normal, t);
    EXPECT_LT(Norm(tip - expected), 1e-12 * diagonal) << t;
    const double length = Norm(tip - base);
    lengths.push_back(length);
    EXPECT_GT(Dot(tip - base, base - CircleCenter), 0.999 * length * Norm(base - CircleCenter));
    // The cubic through 16 points of a circle has a curvature within 3% of 1/r.
    EXPECT_NEAR(length, 0.15 * diagonal, 0.15 * diagonal * 0.03);
  }
  std::sort(lengths.begin(), lengths.end());
  EXPECT_NEAR(lengths[static_cast<size_t>(0.95 * (lengths.size() - 1))], 0.15 * diagonal,
    1e-12 * diagonal);
  // The envelope is closed and joins the tips in order.
  const IdList& envelope = cells.back();
  ASSERT_EQ(static_cast<vtkIdType>(envelope.size()), samples + 1);
  EXPECT_EQ(envelope.front(), envelope.back());
  EXPECT_EQ(envelope[1], cells[1][1]);
  EXPECT_EQ(CellArray(comb, "CombPart")->GetTuple1(samples), 1.0);
}

TEST(CurvatureComb, OneSpikeDoesNotShrinkTheAutomaticScale)
{
  // A straight run of 101 samples with curvature 1, except a spike of 1000.
  auto curve = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> curvature;
  curvature->SetName("Curvature");
  vtkNew<vtkDoubleArray> normal;
  normal->SetName("Normal");
  normal->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> line;
  line->InsertNextCell(101);
  for (int i = 0; i <= 100; ++i)
  {
    points->InsertNextPoint(0.1 * i, 0, 0);
    curvature->InsertNextValue(i == 40 ? 1000.0 : 1.0);
    normal->InsertNextTuple3(0, 1, 0);
    line->InsertCellPoint(i);
  }
  curve->SetPoints(points);
  curve->SetLines(line);
  curve->GetPointData()->AddArray(curvature);
  curve->GetPointData()->AddArray(normal);
  const FilterRun run = RunComb(curve, [](vtkCurvatureCombFilter*) {});
  ExpectNoMessages(run);
  const auto teeth = LinesOf(run.Output);
  const auto toothLength = [&](int t) {
    return Norm(PointOf(run.Output, teeth[t][1]) - PointOf(run.Output, teeth[t][0]));
  };
  EXPECT_NEAR(toothLength(10), 0.15 * 10.0, 1e-12);
  EXPECT_NEAR(toothLength(40), 1000 * 0.15 * 10.0, 1e-9);
}

TEST(CurvatureComb, HelixTorsionCombAlongBinormalWithFixedScale)
{
  const FilterRun curve = RunCubic(ReadData("helix.vtp"));
  const FilterRun run = RunComb(curve.Output, [](vtkCurvatureCombFilter* comb) {
    comb->SetCombTypeToTorsion();
    comb->SetScaleModeToFixed();
    comb->SetScaleFactor(2.0);
    comb->SetStride(3);
    comb->EnvelopeOff();
  });
  ExpectNoMessages(run);
  vtkPolyData* comb = run.Output;
  const auto cells = LinesOf(comb);
  const vtkIdType samples = curve.Output->GetNumberOfPoints();
  // Every third sample, and the last one.
  const vtkIdType teeth = (samples - 1) / 3 + 1 + ((samples - 1) % 3 != 0 ? 1 : 0);
  ASSERT_EQ(static_cast<vtkIdType>(cells.size()), teeth);
  vtkDataArray* binormal = PointArray(curve.Output, "Binormal");
  vtkDataArray* torsion = PointArray(curve.Output, "Torsion");
  for (vtkIdType t = 0; t < teeth; ++t)
  {
    const vtkIdType sample = std::min<vtkIdType>(3 * t, samples - 1);
    const Point expected =
      PointOf(curve.Output, sample) + 2.0 * torsion->GetTuple1(sample) * Vector(binormal, sample);
    EXPECT_LT(Norm(PointOf(comb, cells[t][1]) - expected), 1e-12) << t;
  }
  EXPECT_EQ(comb->GetFieldData()->GetArray("CombScale")->GetTuple1(0), 2.0);
}

TEST(CurvatureComb, MissingArraysAreAnErrorAndTheCombIsEmpty)
{
  const auto data = PolylinesData({ Circle(1.0, 8) });
  const FilterRun run = RunComb(data, [](vtkCurvatureCombFilter*) {});
  EXPECT_EQ(CountMessages(run.Errors, { "Curvature", "Normal" }), 1) << Joined(run.Errors);
  EXPECT_EQ(run.Output->GetNumberOfPoints(), 0);
}

TEST(CurvatureComb, NonFiniteValuesGiveZeroTeethWithAWarning)
{
  const FilterRun curve = RunCubic(ReadData("helix.vtp"));
  const auto damaged = DeepCopy(curve.Output);
  vtkDataArray::SafeDownCast(PointArray(damaged, "Curvature"))->SetTuple1(4, NaN);
  vtkDataArray::SafeDownCast(PointArray(damaged, "Normal"))->SetTuple3(5, Inf, 0, 0);
  const FilterRun run = RunComb(damaged, [](vtkCurvatureCombFilter*) {});
  EXPECT_EQ(CountMessages(run.Warnings, { "2 teeth", "zero length" }), 1) << Joined(run.Warnings);
  ExpectAllFinite(run.Output);
}

// ===========================================================================
// Numerical honesty: the condition of the spline system, reported and warned about.

TEST(CubicSplineFilter, UnevenSpacingKeepsTheSystemWellConditioned)
{
  // Spacing 1e-10 next to 1: the cubic's moment system stays diagonally
  // dominant, so its (row-equilibrated) condition stays small and nothing warns.
  const Polyline uneven = { { 0, 0, 0 }, { 1, 0.5, 0 }, { 1 + 1e-10, 0.5 + 1e-10, 1e-10 },
    { 2, 0, 1 }, { 3, 1, 1 } };
  const FilterRun run = RunCubic(PolylinesData({ uneven }));
  EXPECT_EQ(CountMessages(run.Warnings, { "ill-conditioned" }), 0) << Joined(run.Warnings);
  const double condition = CellArray(run.Output, "ConditionEstimate")->GetTuple1(0);
  Measure("cubic condition estimate, spacing 1e-10 next to 1", condition);
  EXPECT_GE(condition, 1.0);
  EXPECT_LT(condition, 100.0);
}

/// A curve reporting the condition its builder measured (the cubic's systems never are bad).
class ReportedCondition final : public shapesplines::Curve
{
public:
  ReportedCondition(std::unique_ptr<shapesplines::Curve> curve, double condition)
    : Curve(curve->knots(), curve->isClosed())
    , Inner(std::move(curve))
    , Condition(condition)
  {
  }
  shapesplines::Derivatives evaluateOnSpan(int span, double t, int order) const override
  {
    return this->Inner->evaluateOnSpan(span, t, order);
  }
  double conditionEstimate() const override { return this->Condition; }

private:
  std::unique_ptr<shapesplines::Curve> Inner;
  double Condition;
};

/// The cubic filter, claiming an ill-conditioned system on every line with more than four points.
class IllConditionedCubic : public vtkCubicSplineFilter
{
public:
  static IllConditionedCubic* New() { VTK_STANDARD_NEW_BODY(IllConditionedCubic); }
  vtkTypeMacro(IllConditionedCubic, vtkCubicSplineFilter);

protected:
  shapesplines::BuiltCurve BuildCurve(const shapesplines::FitContext& context) const override
  {
    shapesplines::BuiltCurve built = this->Superclass::BuildCurve(context);
    const double condition = context.Data.Points.size() > 4 ? 1e13 : 2.0;
    built.Spline = std::make_unique<ReportedCondition>(std::move(built.Spline), condition);
    return built;
  }
};

TEST(ShapeSplineFilter, IllConditionedSystemIsReportedAndWarned)
{
  const Polyline shortLine = { { 0, 0, 0 }, { 1, 0.5, 0 }, { 2, 0, 1 }, { 3, 1, 1 } };
  const Polyline longLine = { { 0, 0, 0 }, { 1, 0.5, 0 }, { 2, 0, 1 }, { 3, 1, 1 }, { 4, 0, 2 } };
  const auto input = PolylinesData({ shortLine, longLine });
  vtkNew<IllConditionedCubic> filter;
  filter->SetInputData(input);
  const FilterRun run = UpdateChecked(input, filter, { filter });
  EXPECT_EQ(CountMessages(run.Warnings, { "cell 0", "ill-conditioned" }), 0) << Joined(run.Warnings);
  EXPECT_EQ(CountMessages(run.Warnings, { "cell 1", "ill-conditioned", "1e+13" }), 1)
    << Joined(run.Warnings);
  vtkDataArray* condition = CellArray(run.Output, "ConditionEstimate");
  EXPECT_EQ(condition->GetTuple1(0), 2.0);
  EXPECT_EQ(condition->GetTuple1(1), 1e13);
  ExpectAllFinite(run.Output);
}

// ===========================================================================
// Settings and damaged cells beyond the bad-input table.

namespace
{
/// A copy of data whose line `cell` refers to point id 1000000.
vtkSmartPointer<vtkPolyData> WithDamagedLine(vtkPolyData* data, vtkIdType cell)
{
  auto damaged = DeepCopy(data);
  vtkNew<vtkCellArray> lines;
  const auto ids = LinesOf(data);
  for (size_t l = 0; l < ids.size(); ++l)
  {
    IdList line = ids[l];
    line[line.size() / 2] = static_cast<vtkIdType>(l) == cell ? 1000000 : line[line.size() / 2];
    lines->InsertNextCell(static_cast<vtkIdType>(line.size()), line.data());
  }
  damaged->SetLines(lines);
  return damaged;
}

/// count points of a helix of radius r and pitch parameter b, dt apart.
Polyline Helix(double r, double b, double dt, int count)
{
  Polyline points;
  for (int i = 0; i < count; ++i)
  {
    const double t = dt * i;
    points.push_back({ r * std::cos(t), r * std::sin(t), b * t });
  }
  return points;
}

vtkSmartPointer<vtkPolyData> TwoHelices()
{
  return PolylinesData({ Helix(1.0, 0.3, 0.5, 20), Helix(2.0, 0.2, 0.4, 30) });
}
} // namespace

TEST(Settings, SampleLengthNotPositiveOrNaNIsAnErrorAndNothingIsSampled)
{
  for (const double length : { 0.0, -1.0, NaN })
  {
    const FilterRun run = RunCubic(TwoHelices(), [length](vtkCubicSplineFilter* f) {
      f->SetSamplingModeToArcLength();
      f->SetSampleLength(length);
    });
    EXPECT_EQ(CountMessages(run.Errors, { "SampleLength must be positive and finite" }), 1)
      << length << ": " << Joined(run.Errors);
    EXPECT_EQ(run.Output->GetNumberOfPoints(), 0) << length;
  }
}

TEST(Settings, ARunBeyondTheSampleBudgetIsAnErrorNotAnAbort)
{
  // 1000 points at 100000 samples per span: 1e8 samples, about 40 GB.
  const FilterRun subdivided = RunCubic(PolylinesData({ Helix(1.0, 0.3, 0.05, 1000) }),
    [](vtkCubicSplineFilter* f) { f->SetNumberOfSubdivisions(100000); });
  EXPECT_EQ(CountMessages(subdivided.Errors, { "99900001 samples", "lower NumberOfSubdivisions (now 100000)" }),
    1)
    << Joined(subdivided.Errors);
  EXPECT_EQ(subdivided.Output->GetNumberOfPoints(), 0);
  // 40 short lines, each within its own 1e7 cap at a tiny spacing, 4e8 together.
  std::vector<Polyline> lines(40, Helix(1.0, 0.3, 0.5, 8));
  const FilterRun spaced = RunCubic(PolylinesData(lines), [](vtkCubicSplineFilter* f) {
    f->SetSamplingModeToArcLength();
    f->SetSampleLength(1e-300);
  });
  EXPECT_EQ(CountMessages(spaced.Errors, { "more than the 20000000 a run may make", "raise SampleLength" }), 1)
    << Joined(spaced.Errors);
  EXPECT_EQ(spaced.Output->GetNumberOfPoints(), 0);
}

TEST(Settings, NaNSettingsAreRefusedRatherThanSwitchingTheAuditOff)
{
  const auto data = TwoHelices();
  const FilterRun tolerance =
    RunCubic(data, [](vtkCubicSplineFilter* f) { f->SetCurveShapeTolerance(NaN); });
  EXPECT_EQ(CountMessages(tolerance.Errors, { "CurveShapeTolerance is NaN" }), 1) << Joined(tolerance.Errors);
  EXPECT_EQ(tolerance.Output->GetNumberOfPoints(), 0);
  vtkNew<vtkGeneralizedCubicSplineFilter> tensioned;
  tensioned->SetTension(NaN);
  tensioned->SetInputData(data);
  const FilterRun tension = UpdateChecked(data, tensioned, { tensioned });
  EXPECT_EQ(CountMessages(tension.Errors, { "Tension is NaN" }), 1) << Joined(tension.Errors);
  vtkNew<vtkQQRSplineFilter> qqr;
  qqr->SetX(1e300); // clamped: x beyond 1 made points at 2e300
  EXPECT_EQ(qqr->GetX(), 1.0);
  qqr->SetY(-3.0);
  EXPECT_EQ(qqr->GetY(), 0.0);
  qqr->SetZ(NaN);
  qqr->SetInputData(data);
  const FilterRun bias = UpdateChecked(data, qqr, { qqr });
  EXPECT_EQ(CountMessages(bias.Errors, { "Z is NaN" }), 1) << Joined(bias.Errors);

  vtkNew<vtkPolylineShapeAnalysis> analysis;
  analysis->SetDataShapeTolerance(NaN);
  analysis->SetInputData(data);
  const FilterRun analysed = UpdateChecked(data, analysis, { analysis });
  EXPECT_EQ(CountMessages(analysed.Errors, { "must not be NaN" }), 1) << Joined(analysed.Errors);
  const FilterRun curve = RunCubic(data);
  const FilterRun comb = RunComb(curve.Output, [](vtkCurvatureCombFilter* c) { c->SetScaleFactor(NaN); });
  EXPECT_EQ(CountMessages(comb.Errors, { "must not be NaN" }), 1) << Joined(comb.Errors);
}

TEST(DamagedCells, AnalysisAndCombSkipLinesWithPointIdsOutOfRange)
{
  const auto data = TwoHelices();
  const FilterRun curve = RunCubic(data);
  // A damaged curve: its line 1 is not audited, line 0 is.
  vtkNew<vtkPolylineShapeAnalysis> analysis;
  analysis->SetInputData(data);
  const auto damagedCurve = WithDamagedLine(curve.Output, 1);
  analysis->SetInputData(1, damagedCurve);
  const FilterRun audited = UpdateChecked(data, analysis, { analysis });
  EXPECT_EQ(CountMessages(audited.Errors, { "Curve line (cell 1) not audited", "point id 1000000" }), 1)
    << Joined(audited.Errors);
  EXPECT_GE(CellArray(audited.Output, "ShapeViolations")->GetTuple1(0), 0.0);
  EXPECT_EQ(CellArray(audited.Output, "ShapeViolations")->GetTuple1(1), -1.0);
  // Damaged data: that line skipped, the other analysed.
  const auto damagedData = WithDamagedLine(data, 0);
  vtkNew<vtkPolylineShapeAnalysis> shape;
  shape->SetInputData(damagedData);
  const FilterRun analysed = UpdateChecked(damagedData, shape, { shape });
  EXPECT_EQ(CountMessages(analysed.Errors, { "Line (cell 0) skipped", "out of range" }), 1)
    << Joined(analysed.Errors);
  EXPECT_GT(MaxAbs(PointArray(analysed.Output, "DiscreteCurvature"), LinesOf(data)[1]), 0.0);
  // A data file given as the curve: no curve arrays, nothing audited, no crash.
  vtkNew<vtkPolylineShapeAnalysis> mistaken;
  mistaken->SetInputData(data);
  mistaken->SetInputData(1, data);
  const FilterRun refused = UpdateChecked(data, mistaken, { mistaken });
  EXPECT_EQ(CountMessages(refused.Errors, { "lacks SpanIndex", "Nothing audited" }), 1) << Joined(refused.Errors);
  EXPECT_EQ(CellArray(refused.Output, "ShapeViolations")->GetTuple1(0), -1.0);
  // The comb: teeth on line 0 only.
  const FilterRun comb = RunComb(damagedCurve, [](vtkCurvatureCombFilter*) {});
  EXPECT_EQ(CountMessages(comb.Errors, { "Line (cell 1) skipped", "out of range" }), 1) << Joined(comb.Errors);
  EXPECT_GT(comb.Output->GetNumberOfPoints(), 0);
}

/// A copy of data whose point (cell) array `name` is one tuple short, as a damaged file holds.
vtkSmartPointer<vtkPolyData> WithShortArray(vtkPolyData* data, const char* name, bool cellArray = false)
{
  auto damaged = DeepCopy(data);
  vtkFieldData* arrays = cellArray ? static_cast<vtkFieldData*>(damaged->GetCellData())
                                   : static_cast<vtkFieldData*>(damaged->GetPointData());
  vtkAbstractArray* array = arrays->GetAbstractArray(name);
  array->SetNumberOfTuples(array->GetNumberOfTuples() - 1);
  return damaged;
}

TEST(DamagedArrays, ArraysWithoutATuplePerPointOrCellAreLeftOutWithAWarning)
{
  auto data = TwoHelices();
  const vtkIdType points = data->GetNumberOfPoints();
  for (const char* name : { "Full", "Short" })
  {
    vtkNew<vtkDoubleArray> values;
    values->SetName(name);
    values->SetNumberOfTuples(std::string(name) == "Full" ? points : points - 1);
    values->FillValue(2.0);
    data->GetPointData()->AddArray(values);
    vtkNew<vtkDoubleArray> perCell;
    perCell->SetName((std::string(name) + "Cells").c_str());
    perCell->SetNumberOfTuples(std::string(name) == "Full" ? 2 : 1);
    perCell->FillValue(3.0);
    data->GetCellData()->AddArray(perCell);
  }
  // The spline filters: the short arrays are neither carried nor read.
  const FilterRun curve = RunCubic(data);
  EXPECT_NE(curve.Output->GetPointData()->GetArray("Full"), nullptr);
  EXPECT_EQ(curve.Output->GetPointData()->GetArray("Short"), nullptr);
  EXPECT_NE(curve.Output->GetCellData()->GetArray("FullCells"), nullptr);
  EXPECT_EQ(curve.Output->GetCellData()->GetArray("ShortCells"), nullptr);
  EXPECT_EQ(CountMessages(curve.Warnings, { "Point arrays without one tuple per point", "Short (" }), 1)
    << Joined(curve.Warnings);
  EXPECT_EQ(CountMessages(curve.Warnings, { "Cell arrays without one tuple per cell", "ShortCells (1 tuples)" }), 1)
    << Joined(curve.Warnings);
  EXPECT_EQ(LinesOf(curve.Output).size(), 2u);
  // A per-point parameter array one tuple short is not read either.
  vtkNew<vtkGeneralizedCubicSplineFilter> tensioned;
  tensioned->SetTensionArrayName("Short");
  tensioned->SetInputData(data);
  const FilterRun tension = UpdateChecked(data, tensioned, { tensioned });
  EXPECT_EQ(LinesOf(tension.Output).size(), 2u);
  EXPECT_GE(CountMessages(tension.Warnings, { "Short (" }), 1) << Joined(tension.Warnings);
  // The analysis passes its input on without them.
  vtkNew<vtkPolylineShapeAnalysis> analysis;
  analysis->SetInputData(data);
  analysis->SetInputData(1, curve.Output);
  const FilterRun analysed = UpdateChecked(data, analysis, { analysis });
  EXPECT_NE(analysed.Output->GetPointData()->GetArray("Full"), nullptr);
  EXPECT_EQ(analysed.Output->GetPointData()->GetArray("Short"), nullptr);
  EXPECT_EQ(analysed.Output->GetCellData()->GetArray("ShortCells"), nullptr);
  EXPECT_GE(CellArray(analysed.Output, "ShapeViolations")->GetTuple1(0), 0.0);
  EXPECT_EQ(CountMessages(analysed.Warnings, { "left out of the output", "Short (" }), 1)
    << Joined(analysed.Warnings);
  // A curve whose Curvature lost a tuple: not audited, and the comb refuses it.
  const auto damagedCurve = WithShortArray(curve.Output, "Curvature");
  vtkNew<vtkPolylineShapeAnalysis> audit;
  audit->SetInputData(data);
  audit->SetInputData(1, damagedCurve);
  const FilterRun refused = UpdateChecked(data, audit, { audit });
  EXPECT_EQ(CountMessages(refused.Errors, { "one tuple per point", "Nothing audited" }), 1)
    << Joined(refused.Errors);
  EXPECT_EQ(CellArray(refused.Output, "ShapeViolations")->GetTuple1(0), -1.0);
  const FilterRun comb = RunComb(damagedCurve, [](vtkCurvatureCombFilter*) {});
  EXPECT_EQ(CountMessages(comb.Errors, { "one tuple per point" }), 1) << Joined(comb.Errors);
  EXPECT_EQ(comb.Output->GetNumberOfPoints(), 0);
}

TEST(RunawayCurve, ArcLengthSamplingStopsAtAHundredTimesThePolyline)
{
  // A closed line through two points 7e31 apart, one 1.25e22 from them and
  // one 1e-31 from that (found by fuzz_filters): the variable degree spline
  // through it (condition estimate 1e17) is about 1e6 diagonals long. Sampled every hundredth of a diagonal
  // it took 1e7 samples and a minute; the samples now stop at what 100
  // polylines would take, and the warnings say why.
  const Polyline points = { { 2.6173876791765426e+29, 1.6201960940301341e+25, 7.1439580550144634e+31 },
    { 2.5166807544035772e-38, 1.0170419441111061e-31, 1.4901407869630105e-41 },
    { 0, -1.2526493273453299e+22, 1.5871023001658282e-36 }, { 0, 0, 0 } };
  const auto data = PolylinesData({ points });
  double bounds[6];
  data->GetBounds(bounds);
  const double diagonal = std::hypot(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);
  double polyline = 0.0;
  for (size_t k = 0; k < points.size(); ++k)
  {
    const Point& a = points[k];
    const Point& b = points[(k + 1) % points.size()];
    polyline += std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  }
  vtkNew<vtkVariableDegreeSplineFilter> spline;
  spline->SetClosed(true);
  spline->SetLambda(10.0); // the settings fuzz_filters found it with
  spline->SetMaxDegree(100.0);
  spline->SetSamplingModeToArcLength();
  spline->SetSampleLength(1e-2 * diagonal);
  spline->SetInputData(data);
  const FilterRun run = UpdateChecked(data, spline, { spline });
  ASSERT_EQ(run.Output->GetNumberOfLines(), 1) << Joined(run.Errors);
  EXPECT_GT(CellArray(run.Output, "Length")->GetTuple1(0), 1e3 * polyline);
  EXPECT_LE(run.Output->GetNumberOfPoints(), 100.0 * polyline / (1e-2 * diagonal) + 10);
  EXPECT_GT(run.Output->GetNumberOfPoints(), 1000);
  EXPECT_EQ(CellArray(run.Output, "ShapePreserving")->GetTuple1(0), 0.0);
  EXPECT_EQ(CountMessages(run.Warnings, { "sample spacing widened", "100 times" }), 1) << Joined(run.Warnings);
  // Its points run straight back at the third (0 -> (0, -1e22, 0) -> 0): the
  // warning about that says the curve may stray there, instead of the
  // straying span's.
  EXPECT_EQ(CountMessages(run.Warnings, { "run straight back", "may stray" }), 1)
    << Joined(run.Warnings);
}

/// Distance from p to the segment ab.
double DistanceToSegment(const Point& p, const Point& a, const Point& b)
{
  const Point ab = b - a;
  const double squared = Dot(ab, ab);
  const double along = squared > 0.0 ? std::clamp(Dot(p - a, ab) / squared, 0.0, 1.0) : 0.0;
  return Norm(p - (a + along * ab));
}

TEST(PolygonDeviation, ACurveThatLeavesItsDataIsNeverShapePreserving)
{
  // Seven points spanning 50 units, two of them 5e-4 apart: the classical
  // quintic through them strayed up to 33 segment lengths (length 39 times
  // the polyline's) with no flag. Measured here on the output samples,
  // independently of the filter's own audit.
  std::vector<std::function<vtkSmartPointer<vtkShapeSplineFilter>()>> families = {
    [] { return vtkSmartPointer<vtkShapeSplineFilter>(vtkSmartPointer<vtkCubicSplineFilter>::New()); },
    [] { return vtkSmartPointer<vtkShapeSplineFilter>(vtkSmartPointer<vtkGeneralizedCubicSplineFilter>::New()); },
    [] { return vtkSmartPointer<vtkShapeSplineFilter>(vtkSmartPointer<vtkTensionQuinticSplineFilter>::New()); },
    [] {
      auto fixed = vtkSmartPointer<vtkTensionQuinticSplineFilter>::New();
      fixed->AutomaticOff();
      return vtkSmartPointer<vtkShapeSplineFilter>(fixed);
    },
    [] { return vtkSmartPointer<vtkShapeSplineFilter>(vtkSmartPointer<vtkVariableDegreeSplineFilter>::New()); },
    [] { return vtkSmartPointer<vtkShapeSplineFilter>(vtkSmartPointer<vtkQQRSplineFilter>::New()); } };
  Random random(11);
  int strayed = 0, flagged = 0;
  for (int trial = 0; trial < 40; ++trial)
  {
    std::vector<double> x(7);
    for (double& v : x)
    {
      v = random.Uniform(0.0, 50.0);
    }
    std::sort(x.begin(), x.end());
    x.front() = 0.0;
    x.back() = 50.0;
    const int gap = 1 + trial % 4;
    x[gap + 1] = x[gap] + 5e-4;
    Polyline points;
    for (const double v : x)
    {
      points.push_back({ v, random.Uniform(-5.0, 5.0), random.Uniform(-2.0, 2.0) });
    }
    const auto data = PolylinesData({ points });
    for (const auto& make : families)
    {
      auto filter = make();
      filter->SetInputData(data);
      const FilterRun run = UpdateChecked(data, filter, { filter });
      // The largest distance of a sample from its span's data segment, over
      // the longest of that segment and its neighbours.
      vtkDataArray* span = PointArray(run.Output, "SpanIndex");
      double measured = 0.0;
      for (vtkIdType k = 0; k < run.Output->GetNumberOfPoints(); ++k)
      {
        const int j = static_cast<int>(span->GetTuple1(k));
        const Point p = PointOf(run.Output, k);
        double local = 0.0;
        for (int n = std::max(j - 1, 0); n <= std::min(j + 1, 5); ++n)
        {
          local = std::max(local, Norm(points[n + 1] - points[n]));
        }
        measured = std::max(measured, DistanceToSegment(p, points[j], points[j + 1]) / local);
      }
      const double reported = CellArray(run.Output, "PolygonDeviation")->GetTuple1(0);
      const bool preserving = CellArray(run.Output, "ShapePreserving")->GetTuple1(0) == 1.0;
      EXPECT_LE(measured, reported * 1.05 + 1e-9) << filter->GetClassName() << " trial " << trial;
      if (measured > 0.6)
      {
        ++strayed;
        EXPECT_FALSE(preserving) << filter->GetClassName() << " trial " << trial << ": " << measured;
        flagged += CountMessages(run.Warnings, { "cell 0", "strays" }) == 1 ? 1 : 0;
      }
    }
  }
  Measure("curves straying beyond 0.6 local segment lengths", strayed);
  EXPECT_GT(strayed, 0); // the data provoke it
  EXPECT_EQ(flagged, strayed);
}

// ---------------------------------------------------------------------------
// Points without line cells (a table's rows): Connect Points.

namespace
{
/// Two helices' points and no cells, with a point array "Track" of 5 then 7.
vtkSmartPointer<vtkPolyData> TwoTracksAsPoints(bool withVertices)
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkIntArray> track;
  track->SetName("Track");
  for (const int id : { 5, 7 })
  {
    for (int i = 0; i < 20; ++i)
    {
      const double t = 0.4 * i;
      points->InsertNextPoint(std::cos(t), std::sin(t) + 10.0 * (id == 7), 0.25 * t);
      track->InsertNextValue(id);
    }
  }
  data->SetPoints(points);
  data->GetPointData()->AddArray(track);
  if (withVertices)
  {
    vtkNew<vtkCellArray> vertices;
    for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
    {
      vertices->InsertNextCell(1, &p);
    }
    data->SetVerts(vertices);
  }
  return data;
}

/// The same helices as two polyline cells.
vtkSmartPointer<vtkPolyData> TwoTracksAsLines()
{
  auto data = TwoTracksAsPoints(false);
  vtkNew<vtkCellArray> lines;
  for (const vtkIdType first : { 0, 20 })
  {
    lines->InsertNextCell(20);
    for (vtkIdType p = first; p < first + 20; ++p)
    {
      lines->InsertCellPoint(p);
    }
  }
  data->SetLines(lines);
  return data;
}
} // namespace

TEST(ConnectPoints, ALineIdArrayOneTupleShortIsNotRead)
{
  // Guessed (Track) it is left out: one line of every point; named, an error.
  const auto damaged = WithShortArray(TwoTracksAsPoints(false), "Track");
  const FilterRun guessed = RunCubic(damaged);
  EXPECT_EQ(CountMessages(guessed.Warnings, { "Point arrays without one tuple per point", "Track (39 tuples)" }), 1)
    << Joined(guessed.Warnings);
  EXPECT_EQ(guessed.Output->GetNumberOfLines(), 1);
  vtkNew<vtkCubicSplineFilter> named;
  named->SetLineIdArrayName("Track");
  named->SetInputData(damaged);
  const FilterRun refused = UpdateChecked(damaged, named, { named });
  EXPECT_EQ(CountMessages(refused.Errors, { "'Track' with one tuple per point", "nothing fitted" }), 1)
    << Joined(refused.Errors);
  EXPECT_EQ(refused.Output->GetNumberOfPoints(), 0);
}

TEST(ConnectPoints, PointsInOrderBecomeTheLinesTheirIdsName)
{
  const FilterRun lines = RunCubic(TwoTracksAsLines());
  ExpectNoMessages(lines);
  for (const bool withVertices : { false, true })
  {
    const FilterRun points = RunCubic(TwoTracksAsPoints(withVertices));
    ExpectNoMessages(points);
    ASSERT_EQ(points.Output->GetNumberOfLines(), 2);
    // The same curves as from the line cells, arrays and all.
    for (const char* name : CurveCellArrays)
    {
      for (vtkIdType c = 0; c < 2; ++c)
      {
        EXPECT_NEAR(CellArray(points.Output, name)->GetTuple1(c),
          CellArray(lines.Output, name)->GetTuple1(c), 1e-12)
          << name;
      }
    }
    ASSERT_EQ(points.Output->GetNumberOfPoints(), lines.Output->GetNumberOfPoints());
    for (vtkIdType p = 0; p < points.Output->GetNumberOfPoints(); ++p)
    {
      EXPECT_NEAR(PointArray(points.Output, "Curvature")->GetTuple1(p),
        PointArray(lines.Output, "Curvature")->GetTuple1(p), 1e-12);
    }
    // Each helix is one line (7.6 turns of speed 1.0308), not one through both.
    EXPECT_NEAR(CellArray(points.Output, "Length")->GetTuple1(0), 7.834, 0.01);
    vtkDataArray* lineId = CellArray(points.Output, "LineId");
    ASSERT_NE(lineId, nullptr);
    EXPECT_TRUE(lineId->IsA("vtkIntArray"));
    EXPECT_EQ(lineId->GetTuple1(0), 5);
    EXPECT_EQ(lineId->GetTuple1(1), 7);
  }
}

TEST(ConnectPoints, WithoutALineIdArrayAllPointsAreOneLine)
{
  auto data = TwoTracksAsPoints(false);
  data->GetPointData()->RemoveArray("Track");
  const FilterRun run = RunCubic(data);
  ExpectNoMessages(run);
  ASSERT_EQ(run.Output->GetNumberOfLines(), 1);
  EXPECT_EQ(run.Output->GetCellData()->GetArray("LineId"), nullptr);
  EXPECT_GT(CellArray(run.Output, "Length")->GetTuple1(0), 2 * 7.834);
}

TEST(ConnectPoints, NamedArrayOffNaNAndMissingArray)
{
  // A named array wins over the name rule: "Label" here, "id" ignored.
  auto data = TwoTracksAsPoints(false);
  data->GetPointData()->GetArray("Track")->SetName("Label");
  vtkNew<vtkIntArray> id;
  id->SetName("id");
  id->SetNumberOfTuples(data->GetNumberOfPoints());
  id->FillValue(1);
  data->GetPointData()->AddArray(id);
  FilterRun run = RunCubic(data, [](vtkCubicSplineFilter* f) { f->SetLineIdArrayName("Label"); });
  ExpectNoMessages(run);
  EXPECT_EQ(run.Output->GetNumberOfLines(), 2);
  run = RunCubic(data); // "id" is a line id name; a single value, a single line
  EXPECT_EQ(run.Output->GetNumberOfLines(), 1);

  run = RunCubic(data, [](vtkCubicSplineFilter* f) { f->SetLineIdArrayName("Nothing"); });
  EXPECT_EQ(CountMessages(run.Errors, { "'Nothing'", "line ids" }), 1) << Joined(run.Errors);
  EXPECT_EQ(run.Output->GetNumberOfPoints(), 0);

  run = RunCubic(data, [](vtkCubicSplineFilter* f) { f->ConnectPointsOff(); });
  EXPECT_EQ(CountMessages(run.Warnings, { "no lines", "Connect Points" }), 1)
    << Joined(run.Warnings);
  EXPECT_EQ(run.Output->GetNumberOfPoints(), 0);

  // Points whose id is NaN belong to no line.
  vtkNew<vtkDoubleArray> lineId;
  lineId->SetName("line_id");
  for (vtkIdType p = 0; p < data->GetNumberOfPoints(); ++p)
  {
    lineId->InsertNextValue(p == 3 ? std::nan("") : p < 20 ? 0.0 : 1.0);
  }
  data->GetPointData()->RemoveArray("id");
  data->GetPointData()->RemoveArray("Label");
  data->GetPointData()->AddArray(lineId);
  run = RunCubic(data);
  EXPECT_TRUE(run.Errors.empty()) << Joined(run.Errors);
  EXPECT_EQ(CountMessages(run.Warnings, { "1 point(s)", "line_id", "no line" }), 1)
    << Joined(run.Warnings);
  ASSERT_EQ(run.Output->GetNumberOfLines(), 2);
  EXPECT_EQ(CellArray(run.Output, "LineId")->GetTuple1(1), 1.0);
}

TEST(CurvatureBound, ACuspIsNamedInAWarning)
{
  // The quintic at a tension far below its default makes cusps on the Akima
  // data (curvature 1e10 against a box of about 10); at its default it does not.
  const auto data = PolylinesData({ AkimaPoints() });
  for (const double gamma : { 1e-4, 1.0 })
  {
    vtkNew<vtkTensionQuinticSplineFilter> filter;
    filter->SetAutomatic(false);
    filter->SetGamma(gamma);
    filter->SetInputData(data);
    const FilterRun run = UpdateChecked(data, filter, { filter });
    const double largest = run.Output->GetPointData()->GetArray("Curvature")->GetRange()[1];
    const bool cusp = largest * data->GetLength() > 1e6;
    EXPECT_EQ(cusp, gamma < 1.0) << "largest curvature " << largest;
    EXPECT_EQ(CountMessages(run.Warnings, { "Line (cell 0)", "curvature up to", "cusp" }),
      cusp ? 1 : 0)
      << Joined(run.Warnings);
  }
}

TEST(NoisyPoints, InterpolatingThemWarnsOnceButNotOnAStaircase)
{
  // Two noisy helices (100 points, 0.5% of the radius, 16 a turn) and a
  // clean 3D staircase (runs of 5 steps): one warning names the two noisy
  // lines; the staircase's exact corners are no noise. Approximated, the
  // helices need no warning.
  std::vector<Polyline> lines = NoisyHelices(2, 100, 0.005, 7);
  Polyline stairs = { { 0, 0, 0 } };
  for (int run = 0; run < 6; ++run)
  {
    for (int step = 0; step < 5; ++step)
    {
      Point next = stairs.back();
      next[run % 3] += 0.5;
      stairs.push_back(next);
    }
  }
  const auto noisy = PolylinesData(lines);
  lines.push_back(stairs);
  const FilterRun interpolated = RunCubic(PolylinesData(lines));
  EXPECT_EQ(CountMessages(interpolated.Warnings,
              { "2 line(s) interpolated through points that look noisy", "Mode Approximate" }),
    1)
    << Joined(interpolated.Warnings);
  EXPECT_EQ(CountMessages(RunCubic(PolylinesData({ stairs })).Warnings, { "look noisy" }), 0);
  vtkNew<vtkTensionQuinticSplineFilter> approximation;
  approximation->SetModeToApproximate();
  approximation->SetInputData(noisy);
  const FilterRun approximated = UpdateChecked(noisy, approximation, { approximation });
  EXPECT_EQ(CountMessages(approximated.Warnings, { "look noisy" }), 0)
    << Joined(approximated.Warnings);
}

TEST(TorsionColorRange, CentredOnZeroAndNotSquashedBySpikes)
{
  const auto range = [](vtkPolyData* curve) {
    vtkDataArray* values = curve->GetFieldData()->GetArray("TorsionColorRange");
    EXPECT_NE(values, nullptr);
    EXPECT_EQ(values ? values->GetNumberOfTuples() : 0, 2);
    return values ? std::make_pair(values->GetTuple1(0), values->GetTuple1(1))
                  : std::make_pair(0.0, 0.0);
  };
  // A helix: torsion 0.2 everywhere, so the 95th percentile is 0.2.
  const FilterRun helix = RunCubic(ReadData("helix.vtp"));
  const auto [low, high] = range(helix.Output);
  EXPECT_EQ(low, -high);
  EXPECT_NEAR(high, 0.2, 0.2 * 0.1); // the cubic at 8 points per turn, ends included
  // The noisy aorta's cubic: spikes of 100-200, most samples far below.
  const FilterRun aorta = RunCubic(ReadData("aorta-centerline.vtp"));
  const double largest = MaxAbs(PointArray(aorta.Output, "Torsion"), DistinctIds(LinesOf(aorta.Output)[0]));
  EXPECT_GT(largest, 100.0);
  EXPECT_LT(range(aorta.Output).second, 0.2 * largest);
  EXPECT_GT(range(aorta.Output).second, 0.0);
}

// The selection by bits (long arrays) and the direct one (short arrays) give the
// 95th percentile of |v| over the finite values that a sort gives.
TEST(TypicalMagnitude, IsTheSorted95thPercentileOfTheFiniteMagnitudes)
{
  std::mt19937 random(7);
  std::normal_distribution<double> gauss(0.0, 3.0);
  const auto sorted = [](std::vector<double> values) {
    values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
      values.end());
    for (double& v : values)
    {
      v = std::abs(v);
    }
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[static_cast<size_t>(0.95 * (values.size() - 1))];
  };
  for (const size_t count : { size_t(1), size_t(10), size_t(10000), size_t(65536), size_t(300000) })
  {
    SCOPED_TRACE(count);
    std::vector<double> values(count);
    for (double& v : values)
    {
      v = gauss(random);
    }
    values[0] = std::numeric_limits<double>::quiet_NaN();
    values[count / 2] = -std::numeric_limits<double>::infinity();
    EXPECT_EQ(shapesplines::typicalMagnitude(values), sorted(values));
    // A crowd of one value (every bit decided) among a few others.
    std::vector<double> crowded(count, -0.2);
    crowded[count - 1] = 1e9;
    EXPECT_EQ(shapesplines::typicalMagnitude(crowded), sorted(crowded));
  }
  EXPECT_EQ(shapesplines::typicalMagnitude(std::vector<double>{}), 0.0);
  EXPECT_EQ(shapesplines::typicalMagnitude(std::vector<double>(5, std::nan(""))), 0.0);
}

// ---------------------------------------------------------------------------
// Composite data on both ports of the analysis.

TEST(CompositeAnalysis, EachBlockMeetsTheCurveBlockAtTheSamePlace)
{
  const auto akima = PolylinesData({ AkimaPoints() });
  const auto helix = ReadData("helix.vtp");
  // The same blocks as a multiblock and as a partitioned data set.
  vtkNew<vtkMultiBlockDataSet> multiblock;
  multiblock->SetBlock(0, akima);
  multiblock->SetBlock(1, helix);
  vtkNew<vtkPartitionedDataSet> partitioned;
  partitioned->SetPartition(0, akima);
  partitioned->SetPartition(1, helix);
  for (vtkDataObjectTree* data : std::initializer_list<vtkDataObjectTree*>{ multiblock, partitioned })
  {
    SCOPED_TRACE(data->GetClassName());
    vtkNew<vtkCubicSplineFilter> cubic;
    cubic->SetInputData(data);
    vtkNew<vtkPolylineShapeAnalysis> analysis;
    analysis->SetInputData(data);
    analysis->SetCurveConnection(cubic->GetOutputPort());
    MessageLog log({ cubic, analysis });
    analysis->Update();
    EXPECT_TRUE(log.Errors.empty()) << Joined(log.Errors);
    auto* output = vtkDataObjectTree::SafeDownCast(analysis->GetOutputDataObject(0));
    ASSERT_NE(output, nullptr);
    EXPECT_STREQ(output->GetClassName(), data->GetClassName());
    const auto blocks = vtkCompositeDataSet::GetDataSets<vtkPolyData>(output);
    ASSERT_EQ(blocks.size(), 2u);
    // Each block as its own poly data run gives the same audit.
    const FilterRun akimaAlone = RunAnalysis(akima, true);
    const FilterRun helixAlone = RunAnalysis(helix, true);
    EXPECT_EQ(CellArray(blocks[0], "ShapeViolations")->GetTuple1(0),
      CellArray(akimaAlone.Output, "ShapeViolations")->GetTuple1(0));
    EXPECT_GT(CellArray(blocks[0], "ShapeViolations")->GetTuple1(0), 0); // the cubic breaks Akima's shape
    EXPECT_EQ(CellArray(blocks[1], "ShapeViolations")->GetTuple1(0),
      CellArray(helixAlone.Output, "ShapeViolations")->GetTuple1(0));
  }
}

TEST(CompositeAnalysis, OneBlockCurveForPolyDataAndOtherBlocksNamed)
{
  const auto akima = PolylinesData({ AkimaPoints() });
  // Poly data against a composite curve of one block: audited.
  vtkNew<vtkMultiBlockDataSet> oneBlock;
  oneBlock->SetBlock(0, akima);
  vtkNew<vtkCubicSplineFilter> cubic;
  cubic->SetInputData(oneBlock);
  vtkNew<vtkPolylineShapeAnalysis> analysis;
  analysis->SetInputData(akima);
  analysis->SetCurveConnection(cubic->GetOutputPort());
  {
    MessageLog log({ cubic, analysis });
    analysis->Update();
    EXPECT_TRUE(log.Errors.empty()) << Joined(log.Errors);
  }
  ASSERT_NE(analysis->GetOutput(), nullptr);
  EXPECT_GT(CellArray(analysis->GetOutput(), "ShapeViolations")->GetTuple1(0), 0);

  // A block that is not poly data is left out with a warning naming it.
  vtkNew<vtkMultiBlockDataSet> mixed;
  mixed->SetBlock(0, akima);
  mixed->SetBlock(1, vtkNew<vtkUnstructuredGrid>());
  vtkNew<vtkPolylineShapeAnalysis> dataOnly;
  dataOnly->SetInputData(mixed);
  MessageLog log({ dataOnly });
  dataOnly->Update();
  EXPECT_EQ(CountMessages(log.Warnings, { "Block 2", "vtkUnstructuredGrid", "not poly data" }), 1)
    << Joined(log.Warnings);
  const auto blocks =
    vtkCompositeDataSet::GetDataSets<vtkPolyData>(dataOnly->GetOutputDataObject(0));
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_NE(blocks[0]->GetPointData()->GetArray("DiscreteCurvature"), nullptr);
}

TEST(CompositeInput, ABlockThatIsNotPolyDataIsNamedAndTheOthersGoThrough)
{
  vtkNew<vtkMultiBlockDataSet> mixed;
  mixed->SetBlock(0, PolylinesData({ AkimaPoints() }));
  mixed->SetBlock(1, vtkNew<vtkUnstructuredGrid>());
  vtkNew<vtkCubicSplineFilter> cubic;
  cubic->SetInputData(mixed);
  vtkNew<vtkCurvatureCombFilter> comb;
  comb->SetInputConnection(cubic->GetOutputPort());
  MessageLog log({ cubic, comb });
  comb->Update();
  EXPECT_TRUE(log.Errors.empty()) << Joined(log.Errors);
  EXPECT_EQ(CountMessages(log.Warnings, { "vtkUnstructuredGrid", "not poly data", "left out" }), 1)
    << Joined(log.Warnings);
  const auto curves = vtkCompositeDataSet::GetDataSets<vtkPolyData>(cubic->GetOutputDataObject(0));
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_EQ(curves[0]->GetNumberOfLines(), 1);
  EXPECT_EQ(curves[1]->GetNumberOfPoints(), 0);
  const auto combs = vtkCompositeDataSet::GetDataSets<vtkPolyData>(comb->GetOutputDataObject(0));
  ASSERT_EQ(combs.size(), 2u);
  EXPECT_GT(combs[0]->GetNumberOfLines(), 1);
}

// ===========================================================================
// One name for the automatic shape mode on every shape-preserving family.

namespace
{
template <typename Filter>
void ExpectAutomaticSwitch()
{
  vtkNew<Filter> filter;
  EXPECT_TRUE(filter->GetAutomatic()) << filter->GetClassName();
  filter->AutomaticOff();
  EXPECT_FALSE(filter->GetAutomatic()) << filter->GetClassName();
  filter->SetAutomatic(true);
  EXPECT_TRUE(filter->GetAutomatic()) << filter->GetClassName();
}

// Fixed parameters break Akima's data somewhere, the automatic mode less.
double AkimaViolations(vtkShapeSplineFilter* filter)
{
  filter->SetInputData(PolylinesData({ AkimaPoints() }));
  filter->Update();
  return CellArray(filter->GetOutput(), "ShapeViolations")->GetTuple1(0);
}
} // namespace

TEST(ShapeSplineFilters, AutomaticIsTheSwitchOfEveryShapePreservingFamily)
{
  ExpectAutomaticSwitch<vtkGeneralizedCubicSplineFilter>();
  ExpectAutomaticSwitch<vtkTensionQuinticSplineFilter>();
  ExpectAutomaticSwitch<vtkVariableDegreeSplineFilter>();
  ExpectAutomaticSwitch<vtkQQRSplineFilter>();
}

// Code written against the older names keeps working: they set and read the
// same switch (the build warns that they are deprecated, not here).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
TEST(ShapeSplineFilters, DeprecatedAutomaticNamesForwardToAutomatic)
{
  vtkNew<vtkGeneralizedCubicSplineFilter> generalized;
  generalized->AutomaticTensionOff();
  EXPECT_FALSE(generalized->GetAutomatic());
  generalized->AutomaticTensionOn();
  EXPECT_TRUE(generalized->GetAutomatic());
  generalized->SetAutomaticTension(false);
  EXPECT_FALSE(generalized->GetAutomatic());
  generalized->AutomaticOn();
  EXPECT_TRUE(generalized->GetAutomaticTension());

  vtkNew<vtkVariableDegreeSplineFilter> variable;
  variable->AutomaticDegreesOff();
  EXPECT_FALSE(variable->GetAutomatic());
  variable->AutomaticDegreesOn();
  EXPECT_TRUE(variable->GetAutomatic());
  variable->SetAutomaticDegrees(false);
  EXPECT_FALSE(variable->GetAutomatic());
  variable->AutomaticOn();
  EXPECT_TRUE(variable->GetAutomaticDegrees());

  // And the curve is the one the new name gives.
  vtkNew<vtkGeneralizedCubicSplineFilter> oldName, newName;
  oldName->AutomaticTensionOff();
  newName->AutomaticOff();
  const double fixed = AkimaViolations(newName);
  EXPECT_GT(fixed, 0);
  EXPECT_EQ(AkimaViolations(oldName), fixed);
  oldName->AutomaticTensionOn();
  EXPECT_LT(AkimaViolations(oldName), fixed);
}
#pragma GCC diagnostic pop
