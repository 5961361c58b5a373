// Helpers of the VTK filter tests: building inputs, running filters while
// capturing their messages and checking the input is untouched, and
// properties every curve output must have.
#ifndef shapesplines_FilterTestUtilities_h
#define shapesplines_FilterTestUtilities_h

#include "FitPolyline.h"
#include "vtkCubicSplineFilter.h"
#include "vtkCurvatureCombFilter.h"
#include "vtkPolylineShapeAnalysis.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkVariant.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"
#include <gtest/gtest.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <initializer_list>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace shapesplines::filtertest
{
using Point = std::array<double, 3>;
using Polyline = std::vector<Point>;
using IdList = std::vector<vtkIdType>;

constexpr double Pi = 3.14159265358979323846;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr double Inf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------
// Small vector algebra on Point.
inline Point operator-(const Point& a, const Point& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
inline Point operator+(const Point& a, const Point& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
inline Point operator*(double s, const Point& a)
{
  return { s * a[0], s * a[1], s * a[2] };
}
inline double Dot(const Point& a, const Point& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Point Cross(const Point& a, const Point& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline double Norm(const Point& a)
{
  return std::sqrt(Dot(a, a));
}
inline bool IsFinite(const Point& a)
{
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

/// Reports a measured figure on stdout and in the test's XML record.
inline void Measure(const std::string& name, double value)
{
  std::ostringstream text;
  text.precision(6);
  text << value;
  std::cout << "[  MEASURE ] " << name << " = " << text.str() << std::endl;
  ::testing::Test::RecordProperty(name, text.str());
}

// ---------------------------------------------------------------------------
// Building inputs.

/**
 * Builds poly data from polylines and other cells. Every cell gets its cell
 * id in the cell array InputCellId (VTK orders cells verts, lines, polys,
 * strips) and every point the point array Value = x + 2y + 3z, so tests can
 * follow input data into the output.
 */
class PolyDataBuilder
{
public:
  PolyDataBuilder() { this->Points->SetDataTypeToDouble(); }

  IdList AddPoints(const Polyline& points)
  {
    IdList ids;
    for (const Point& p : points)
    {
      ids.push_back(this->Points->InsertNextPoint(p.data()));
    }
    return ids;
  }
  PolyDataBuilder& LineIds(const IdList& ids) { return this->Insert(this->Lines, ids); }
  PolyDataBuilder& Line(const Polyline& points) { return this->LineIds(this->AddPoints(points)); }
  PolyDataBuilder& Vertex(const Point& p)
  {
    return this->Insert(this->Verts, this->AddPoints({ p }));
  }
  PolyDataBuilder& Polygon(const Polyline& points)
  {
    return this->Insert(this->Polys, this->AddPoints(points));
  }
  PolyDataBuilder& Strip(const Polyline& points)
  {
    return this->Insert(this->Strips, this->AddPoints(points));
  }

  vtkSmartPointer<vtkPolyData> Build() const
  {
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(this->Points);
    polyData->SetVerts(this->Verts);
    polyData->SetLines(this->Lines);
    polyData->SetPolys(this->Polys);
    polyData->SetStrips(this->Strips);
    vtkNew<vtkDoubleArray> value;
    value->SetName("Value");
    value->SetNumberOfTuples(this->Points->GetNumberOfPoints());
    for (vtkIdType i = 0; i < this->Points->GetNumberOfPoints(); ++i)
    {
      const double* p = this->Points->GetPoint(i);
      value->SetValue(i, p[0] + 2 * p[1] + 3 * p[2]);
    }
    polyData->GetPointData()->AddArray(value);
    vtkNew<vtkIdTypeArray> cellId;
    cellId->SetName("InputCellId");
    cellId->SetNumberOfTuples(polyData->GetNumberOfCells());
    for (vtkIdType c = 0; c < polyData->GetNumberOfCells(); ++c)
    {
      cellId->SetValue(c, c);
    }
    polyData->GetCellData()->AddArray(cellId);
    return polyData;
  }

private:
  PolyDataBuilder& Insert(vtkCellArray* cells, const IdList& ids)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    return *this;
  }

  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Verts;
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkCellArray> Polys;
  vtkNew<vtkCellArray> Strips;
};

inline vtkSmartPointer<vtkPolyData> PolylinesData(const std::vector<Polyline>& lines)
{
  PolyDataBuilder builder;
  for (const Polyline& line : lines)
  {
    builder.Line(line);
  }
  return builder.Build();
}

/// count points on the circle of radius r about center in the plane z = center z.
inline Polyline Circle(double r, int count, const Point& center = { 0, 0, 0 })
{
  Polyline points;
  for (int i = 0; i < count; ++i)
  {
    const double angle = 2 * Pi * i / count;
    points.push_back(center + Point{ r * std::cos(angle), r * std::sin(angle), 0.0 });
  }
  return points;
}

/// Helices (cos t, sin t, t / 4) of count points, 16 a turn, with Gaussian
/// noise of sigma on every coordinate.
inline std::vector<Polyline> NoisyHelices(int lines, int count, double sigma, unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Polyline> helices(lines);
  for (Polyline& helix : helices)
  {
    for (int i = 0; i < count; ++i)
    {
      const double t = 2 * Pi * i / 16.0;
      helix.push_back(
        { std::cos(t) + noise(random), std::sin(t) + noise(random), 0.25 * t + noise(random) });
    }
  }
  return helices;
}

/// Points origin + x u + y v of the planar points (x, y, 0).
inline Polyline InPlane(const Polyline& planar, const Point& origin, const Point& u, const Point& v)
{
  Polyline points;
  for (const Point& p : planar)
  {
    points.push_back(origin + p[0] * u + p[1] * v);
  }
  return points;
}

/// Akima's data (Data/akima.vtp), in the plane z = 0.
inline Polyline AkimaPoints()
{
  const std::vector<double> x = { 0, 2, 3, 5, 6, 8, 9, 11, 12, 14, 15 };
  const std::vector<double> y = { 10, 10, 10, 10, 10, 10, 10.5, 15, 50, 60, 85 };
  Polyline points;
  for (size_t i = 0; i < x.size(); ++i)
  {
    points.push_back({ x[i], y[i], 0.0 });
  }
  return points;
}

inline vtkSmartPointer<vtkPolyData> ReadData(const std::string& name)
{
  const char* dir = std::getenv("SHAPESPLINES_DATA_DIR");
  if (!dir)
  {
    ADD_FAILURE() << "SHAPESPLINES_DATA_DIR is not set";
    return vtkSmartPointer<vtkPolyData>::New();
  }
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName((std::string(dir) + "/" + name).c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> data = reader->GetOutput();
  EXPECT_GT(data->GetNumberOfPoints(), 0) << "cannot read " << name;
  return data;
}

inline vtkSmartPointer<vtkPolyData> DeepCopy(vtkPolyData* polyData)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(polyData);
  return copy;
}

// ---------------------------------------------------------------------------
// Reading outputs.

inline Point PointOf(vtkPolyData* polyData, vtkIdType id)
{
  Point p;
  polyData->GetPoint(id, p.data());
  return p;
}

inline std::vector<IdList> CellsOf(vtkCellArray* cells)
{
  std::vector<IdList> result;
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* ids;
    it->GetCurrentCell(npts, ids);
    result.emplace_back(ids, ids + npts);
  }
  return result;
}

inline std::vector<IdList> LinesOf(vtkPolyData* polyData)
{
  return CellsOf(polyData->GetLines());
}

inline vtkDataArray* PointArray(vtkPolyData* polyData, const char* name)
{
  vtkDataArray* array = polyData->GetPointData()->GetArray(name);
  EXPECT_NE(array, nullptr) << "no point array " << name;
  return array;
}

inline vtkDataArray* CellArray(vtkPolyData* polyData, const char* name)
{
  vtkDataArray* array = polyData->GetCellData()->GetArray(name);
  EXPECT_NE(array, nullptr) << "no cell array " << name;
  return array;
}

inline Point Vector(vtkDataArray* array, vtkIdType id)
{
  Point v;
  array->GetTuple(id, v.data());
  return v;
}

/// The i-th value of an array, components of a tuple being consecutive.
inline double FlatValue(vtkDataArray* array, vtkIdType i)
{
  const int components = array->GetNumberOfComponents();
  return array->GetComponent(i / components, static_cast<int>(i % components));
}

/// Largest |value| of a one-component array over the given ids.
inline double MaxAbs(vtkDataArray* array, const IdList& ids)
{
  double largest = 0;
  for (const vtkIdType id : ids)
  {
    largest = std::max(largest, std::abs(array->GetTuple1(id)));
  }
  return largest;
}

/// The distinct point ids of a line (a closed line's repeated seam id once).
inline IdList DistinctIds(const IdList& line)
{
  const bool closed = line.size() > 1 && line.front() == line.back();
  return IdList(line.begin(), closed ? line.end() - 1 : line.end());
}

// ---------------------------------------------------------------------------
// Comparing poly data.

/// Equal within tolerance, NaN equal to NaN.
inline bool Near(double a, double b, double tolerance)
{
  if (std::isnan(a) || std::isnan(b))
  {
    return std::isnan(a) && std::isnan(b);
  }
  return a == b || std::abs(a - b) <= tolerance;
}

inline void ExpectArraysNear(
  vtkFieldData* expected, vtkFieldData* actual, double tolerance, const std::string& what)
{
  ASSERT_EQ(expected->GetNumberOfArrays(), actual->GetNumberOfArrays()) << what;
  for (int a = 0; a < expected->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* e = expected->GetArray(a);
    if (!e) // a string or variant array: compared value by value
    {
      vtkAbstractArray* es = expected->GetAbstractArray(a);
      vtkAbstractArray* bs = actual->GetAbstractArray(es->GetName());
      ASSERT_NE(bs, nullptr) << what << ": no array " << es->GetName();
      ASSERT_EQ(es->GetNumberOfValues(), bs->GetNumberOfValues()) << what << es->GetName();
      for (vtkIdType i = 0; i < es->GetNumberOfValues(); ++i)
      {
        ASSERT_EQ(es->GetVariantValue(i), bs->GetVariantValue(i)) << what << es->GetName() << " " << i;
      }
      continue;
    }
    vtkDataArray* b = actual->GetArray(e->GetName());
    ASSERT_NE(b, nullptr) << what << ": no array " << e->GetName();
    ASSERT_EQ(e->GetNumberOfComponents(), b->GetNumberOfComponents()) << what << e->GetName();
    ASSERT_EQ(e->GetNumberOfTuples(), b->GetNumberOfTuples()) << what << e->GetName();
    int reported = 0;
    for (vtkIdType i = 0; i < e->GetNumberOfValues(); ++i)
    {
      const double x = FlatValue(e, i);
      const double y = FlatValue(b, i);
      if (!Near(x, y, tolerance) && reported++ < 5)
      {
        ADD_FAILURE() << what << ": array " << e->GetName() << " value " << i << ": " << x << " vs "
                      << y;
      }
    }
  }
}

/// Same points (within tolerance), cells and arrays.
inline void ExpectPolyDataNear(
  vtkPolyData* expected, vtkPolyData* actual, double tolerance, const std::string& what)
{
  ASSERT_EQ(expected->GetNumberOfPoints(), actual->GetNumberOfPoints()) << what;
  int reported = 0;
  for (vtkIdType i = 0; i < expected->GetNumberOfPoints(); ++i)
  {
    const Point p = PointOf(expected, i);
    const Point q = PointOf(actual, i);
    for (int c = 0; c < 3; ++c)
    {
      if (!Near(p[c], q[c], tolerance) && reported++ < 5)
      {
        ADD_FAILURE() << what << ": point " << i << " component " << c << ": " << p[c] << " vs "
                      << q[c];
      }
    }
  }
  EXPECT_EQ(CellsOf(expected->GetVerts()), CellsOf(actual->GetVerts())) << what;
  EXPECT_EQ(CellsOf(expected->GetLines()), CellsOf(actual->GetLines())) << what;
  EXPECT_EQ(CellsOf(expected->GetPolys()), CellsOf(actual->GetPolys())) << what;
  EXPECT_EQ(CellsOf(expected->GetStrips()), CellsOf(actual->GetStrips())) << what;
  ExpectArraysNear(expected->GetPointData(), actual->GetPointData(), tolerance, what + " (points)");
  ExpectArraysNear(expected->GetCellData(), actual->GetCellData(), tolerance, what + " (cells)");
}

// ---------------------------------------------------------------------------
// Running filters and capturing their messages.

/// Records the error and warning messages objects emit while it lives.
class MessageLog
{
public:
  explicit MessageLog(std::initializer_list<vtkObject*> objects)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(&MessageLog::Record);
    for (vtkObject* object : objects)
    {
      for (const unsigned long event : { vtkCommand::ErrorEvent, vtkCommand::WarningEvent })
      {
        this->Tags.emplace_back(object, object->AddObserver(event, this->Callback));
      }
    }
  }
  ~MessageLog()
  {
    for (const auto& [object, tag] : this->Tags)
    {
      object->RemoveObserver(tag);
    }
  }
  MessageLog(const MessageLog&) = delete;
  MessageLog& operator=(const MessageLog&) = delete;

  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;

private:
  static void Record(vtkObject*, unsigned long event, void* self, void* message)
  {
    auto* log = static_cast<MessageLog*>(self);
    (event == vtkCommand::ErrorEvent ? log->Errors : log->Warnings)
      .emplace_back(message ? static_cast<const char*>(message) : "");
  }

  vtkNew<vtkCallbackCommand> Callback;
  std::vector<std::pair<vtkSmartPointer<vtkObject>, unsigned long>> Tags;
};

/// Messages containing every one of the given fragments.
inline int CountMessages(
  const std::vector<std::string>& messages, const std::vector<std::string>& fragments)
{
  return static_cast<int>(
    std::count_if(messages.begin(), messages.end(), [&](const std::string& m) {
      return std::all_of(fragments.begin(), fragments.end(),
        [&](const std::string& f) { return m.find(f) != std::string::npos; });
    }));
}

inline std::string Joined(const std::vector<std::string>& messages)
{
  std::string all;
  for (const std::string& m : messages)
  {
    all += m;
  }
  return all;
}

/// The output of a pipeline and the messages its filters emitted.
struct FilterRun
{
  vtkSmartPointer<vtkPolyData> Output;
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};

/**
 * Updates the last filter of a pipeline that reads input, capturing the
 * messages of every filter in it, and checks that input comes out unmodified.
 */
inline FilterRun UpdateChecked(
  vtkPolyData* input, vtkPolyDataAlgorithm* last, std::initializer_list<vtkObject*> filters)
{
  const auto before = DeepCopy(input);
  FilterRun run;
  {
    MessageLog log(filters);
    last->Update();
    run.Errors = log.Errors;
    run.Warnings = log.Warnings;
  }
  run.Output = last->GetOutput();
  ExpectPolyDataNear(before, input, 0.0, "input after the filter");
  return run;
}

using CubicSetup = std::function<void(vtkCubicSplineFilter*)>;

/// Runs a cubic spline filter (configured by setup) on input.
inline FilterRun RunCubic(vtkPolyData* input, const CubicSetup& setup = {})
{
  vtkNew<vtkCubicSplineFilter> filter;
  if (setup)
  {
    setup(filter);
  }
  filter->SetInputData(input);
  return UpdateChecked(input, filter, { filter });
}

inline void ExpectNoMessages(const FilterRun& run)
{
  EXPECT_TRUE(run.Errors.empty()) << Joined(run.Errors);
  EXPECT_TRUE(run.Warnings.empty()) << Joined(run.Warnings);
}

// ---------------------------------------------------------------------------
// Properties of curve outputs.

inline const std::vector<std::pair<const char*, int>> CurvePointArrays = { { "Curvature", 1 },
  { "Torsion", 1 }, { "Tangent", 3 }, { "Normal", 3 }, { "Binormal", 3 }, { "Parameter", 1 },
  { "ArcLength", 1 }, { "SpanIndex", 1 } };
inline const std::vector<const char*> CurveCellArrays = { "ShapePreserving", "ShapeViolations", "Length",
  "Tortuosity", "ConditionEstimate" };

/// Tangent, Normal, Binormal unit, orthogonal and right-handed at ids; the
/// worst deviation is reported once, with the sample where it occurs.
inline void ExpectOrthonormalFrames(vtkPolyData* curve, const IdList& ids, double tolerance = 1e-12)
{
  vtkDataArray* tangent = PointArray(curve, "Tangent");
  vtkDataArray* normal = PointArray(curve, "Normal");
  vtkDataArray* binormal = PointArray(curve, "Binormal");
  ASSERT_TRUE(tangent && normal && binormal);
  double worst = 0;
  vtkIdType worstId = -1;
  for (const vtkIdType id : ids)
  {
    const Point t = Vector(tangent, id);
    const Point n = Vector(normal, id);
    const Point b = Vector(binormal, id);
    ASSERT_TRUE(IsFinite(t) && IsFinite(n) && IsFinite(b)) << "sample " << id;
    for (const double deviation : { Norm(t) - 1, Norm(n) - 1, Norm(b) - 1, Dot(t, n), Dot(t, b),
           Dot(n, b), Norm(Cross(t, n) - b) })
    {
      if (std::abs(deviation) > worst)
      {
        worst = std::abs(deviation);
        worstId = id;
      }
    }
  }
  EXPECT_LE(worst, tolerance) << "frame not orthonormal at sample " << worstId;
}

/// No NaN or Inf in the points or in any point array.
inline void ExpectAllFinite(vtkPolyData* polyData)
{
  for (vtkIdType i = 0; i < polyData->GetNumberOfPoints(); ++i)
  {
    ASSERT_TRUE(IsFinite(PointOf(polyData, i))) << "point " << i;
  }
  vtkPointData* pd = polyData->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    for (vtkIdType v = 0; array && v < array->GetNumberOfValues(); ++v)
    {
      ASSERT_TRUE(std::isfinite(FlatValue(array, v))) << array->GetName() << " value " << v;
    }
  }
}

/// The samples k * subdivisions of an open line are its k-th (distinct) input point.
inline void ExpectDataPointsAmongSamples(
  const Polyline& data, vtkPolyData* curve, const IdList& line, int subdivisions)
{
  ASSERT_EQ(line.size(), (data.size() - 1) * subdivisions + 1);
  for (size_t k = 0; k < data.size(); ++k)
  {
    // Exactly: the data points are returned bit for bit, not recomputed.
    EXPECT_EQ(PointOf(curve, line[k * subdivisions]), data[k]) << "data point " << k;
  }
}

/**
 * The largest factor between two runs' curvature at the same samples of one
 * line, where the first's stands out of what its noise can bend (three
 * times the curvature of an arc with the reference's vertex noise as sagitta
 * over a span, from the cell arrays NoiseLevel, NumberOfKnots and Length,
 * and the line's points; the noise of a vertex inside evenly spread points,
 * within 10%, see leastSquaresPolygonNoise): what an automatic approximation may change
 * (ShapeBounds::CurvatureChange).
 */
inline double CurvatureChange(vtkPolyData* fixed, vtkPolyData* automatic, vtkIdType line, double points)
{
  const IdList a = LinesOf(fixed)[line], b = LinesOf(automatic)[line];
  EXPECT_EQ(a.size(), b.size());
  const double knots = CellArray(fixed, "NumberOfKnots")->GetTuple1(line);
  const double noise = CellArray(fixed, "NoiseLevel")->GetTuple1(line);
  const double span = CellArray(fixed, "Length")->GetTuple1(line) / std::max(1.0, knots - 1.0);
  const double vertexNoise = noise * std::sqrt(std::max(1.0, knots) / std::max(1.0, 0.5 * points));
  const double floor = 3.0 * 8.0 * vertexNoise / (span * span);
  double change = 1.0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    const double k0 = PointArray(fixed, "Curvature")->GetTuple1(a[i]);
    const double k1 = PointArray(automatic, "Curvature")->GetTuple1(b[i]);
    if (k0 > floor)
    {
      change = std::max({ change, k0 / std::max(k1, 1e-300), k1 / k0 });
    }
  }
  return change;
}

inline Polyline PointsOfLine(vtkPolyData* polyData, const IdList& line)
{
  Polyline points;
  for (const vtkIdType id : line)
  {
    points.push_back(PointOf(polyData, id));
  }
  return points;
}

} // namespace shapesplines::filtertest

#endif
