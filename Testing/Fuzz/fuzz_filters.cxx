// libFuzzer target of the VTK layer: poly data a damaged or hostile file can
// hold (point ids out of range or negative, vertices and polygons among the
// lines, NaN/Inf/huge coordinates, per-point arrays with junk values, too
// short or of strings) through every spline filter at random settings, then
// Polyline Shape Analysis and the curvature comb on what comes out. Every
// invariant failure calls abort().
//
// Input format (missing bytes read as zero):
//   byte  0      filter: b % 5 (cubic, generalized cubic, variable degree,
//                tension quintic, qqr)
//   byte  1      flags: bit 0 closed; bit 1 automatic; bit 2 arc-length sampling;
//                bit 3 approximate (or the family's other mode); bit 4 a per-point
//                array named as the family's per-point parameter; bit 5 that array
//                one tuple short; bit 6 that array of strings; bit 7 two threads
//   byte  2      subdivisions 1 + b % 16; arc length: the data's box diagonal
//                times 10^-(b % 4)
//   byte  3      parameterization b % 3; bits 2-3 the family's kind/continuity/end
//   bytes 4-5    the family's two parameters, each a Values[b % 16]
//   byte  6      number of knots (approximations): 0 (chosen) or b % 40
//   byte  7      point count b % 33
//   byte  8      bits 0-1 point encoding (0 double, 1 float, 2 and 3 small
//                integers); bits 2-7 small integers' scale 2^((b >> 2) - 32)
//   points       3 coordinates each: 8 bytes (double), 4 (float) or 1 (small
//                integer: (b % 9) - 4 times the scale)
//   byte         cell count b % 5; then per cell: type b % 4 (poly line, line,
//                vertex, polygon), length b % 24, ids: b < 224 is point b % n,
//                others BadIds[b % 8]
//   bytes        per point, the per-point array's value Values[b % 16]
//   byte         damage: bit 0 an input cell array, bit 1 one tuple short; bit 2
//                the curve given to the analysis and the comb with its Curvature
//                array one tuple short, bit 3 its Tangent array of 2 components; bit 4
//                the per-point array named as the line id array (Connect Points)
//
// FUZZ_FILTERS_VERBOSE=1 prints each decoded input (to describe a reproducer).
#define FUZZ_TARGET_NAME "fuzz_filters"
#include "FuzzCheck.h"

#include "ArrayNames.h"
#include "ShapeAnalysis.h" // MaximumPolygonDeviation

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCubicSplineFilter.h"
#include "vtkCurvatureCombFilter.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGeneralizedCubicSplineFilter.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolylineShapeAnalysis.h"
#include "vtkQQRSplineFilter.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTensionQuinticSplineFilter.h"
#include "vtkVariableDegreeSplineFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
constexpr double Inf = std::numeric_limits<double>::infinity();
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr double Values[16] = { 0.0, 1.0, 0.5, -1.0, 2.0, 4.0, 5.0, 10.0, 100.0, 1e6, 1e300,
  -1e300, NaN, Inf, -Inf, 1e-300 };
constexpr vtkIdType BadIds[8] = { -1, -7, 1000, 100000000, VTK_ID_MAX, VTK_ID_MIN, 0, 0 };
constexpr const char* PerPointArray = "Values";

class Reader
{
public:
  Reader(const uint8_t* data, size_t size)
    : Data(data)
    , Size(size)
  {
  }
  uint8_t byte() { return this->Position < this->Size ? this->Data[this->Position++] : 0; }
  template <class T>
  T raw()
  {
    uint8_t bytes[sizeof(T)] = {};
    for (auto& b : bytes)
    {
      b = this->byte();
    }
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

private:
  const uint8_t* Data;
  size_t Size;
  size_t Position = 0;
};

struct Input
{
  int Filter = 0;
  uint8_t Flags = 0, Sampling = 0, Kinds = 0, Knots = 0, Damage = 0;
  double First = 0.0, Second = 0.0;
  vtkSmartPointer<vtkPolyData> Data = vtkSmartPointer<vtkPolyData>::New();
  bool flag(int bit) const { return (this->Flags >> bit) & 1; }
};

Input decode(const uint8_t* data, size_t size)
{
  Reader in(data, size);
  Input input;
  input.Filter = in.byte() % 5;
  input.Flags = in.byte();
  input.Sampling = in.byte();
  input.Kinds = in.byte();
  input.First = Values[in.byte() % 16];
  input.Second = Values[in.byte() % 16];
  input.Knots = in.byte();
  const int n = in.byte() % 33;
  const uint8_t encoding = in.byte();
  const double scale = std::ldexp(1.0, (encoding >> 2) - 32);
  vtkNew<vtkPoints> points;
  points->SetDataType((encoding & 3) == 1 ? VTK_FLOAT : VTK_DOUBLE);
  for (int i = 0; i < n; ++i)
  {
    double p[3];
    for (double& c : p)
    {
      switch (encoding & 3)
      {
        case 0:
          c = in.raw<double>();
          break;
        case 1:
          c = in.raw<float>();
          break;
        default:
          c = ((in.byte() % 9) - 4) * scale;
      }
    }
    points->InsertNextPoint(p);
  }
  input.Data->SetPoints(points);
  vtkNew<vtkCellArray> lines, verts, polys;
  const int cells = in.byte() % 5;
  for (int c = 0; c < cells; ++c)
  {
    const int type = in.byte() % 4;
    std::vector<vtkIdType> ids(in.byte() % 24);
    for (vtkIdType& id : ids)
    {
      const uint8_t b = in.byte();
      id = b < 224 ? b % std::max(n, 1) : BadIds[b % 8];
    }
    if (type == 1)
    {
      ids.resize(std::min<size_t>(ids.size(), 2)); // a VTK_LINE cell: two ids at most
    }
    vtkCellArray* target = type == 2 ? verts.Get() : (type == 3 ? polys.Get() : lines.Get());
    target->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  input.Data->SetLines(lines);
  input.Data->SetVerts(verts);
  input.Data->SetPolys(polys);
  // An input array the filters carry onto their samples.
  vtkNew<vtkIntArray> carried;
  carried->SetName("PointIndex");
  for (int i = 0; i < n; ++i)
  {
    carried->InsertNextValue(i);
  }
  input.Data->GetPointData()->AddArray(carried);
  if (input.flag(4))
  {
    const int tuples = input.flag(5) ? std::max(n - 1, 0) : n;
    if (input.flag(6))
    {
      vtkNew<vtkStringArray> strings;
      strings->SetName(PerPointArray);
      for (int i = 0; i < tuples; ++i)
      {
        strings->InsertNextValue(std::to_string(Values[in.byte() % 16]));
      }
      input.Data->GetPointData()->AddArray(strings);
    }
    else
    {
      vtkNew<vtkDoubleArray> values;
      values->SetName(PerPointArray);
      for (int i = 0; i < tuples; ++i)
      {
        values->InsertNextValue(Values[in.byte() % 16]);
      }
      input.Data->GetPointData()->AddArray(values);
    }
  }
  input.Damage = in.byte();
  if (input.Damage & 1)
  {
    vtkNew<vtkDoubleArray> values;
    values->SetName("CellValues");
    const vtkIdType cellCount = input.Data->GetNumberOfCells();
    for (vtkIdType c = 0; c < cellCount - ((input.Damage & 2) ? 1 : 0); ++c)
    {
      values->InsertNextValue(static_cast<double>(c));
    }
    input.Data->GetCellData()->AddArray(values);
  }
  return input;
}

double diagonal(vtkPolyData* data)
{
  double bounds[6];
  data->GetPoints()->GetBounds(bounds);
  const double d = std::hypot(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);
  return std::isfinite(d) && d > 0.0 ? d : 1.0;
}

/// The filter of input.Filter at the input's settings; approximates: whether
/// its curve is audited against a polygon other than the data.
vtkSmartPointer<vtkShapeSplineFilter> makeFilter(const Input& input, bool& approximates)
{
  const bool automatic = input.flag(1), other = input.flag(3);
  const int kind = (input.Kinds >> 2) & 3;
  const int knots = input.Knots < 128 ? 0 : input.Knots % 40;
  approximates = false;
  vtkSmartPointer<vtkShapeSplineFilter> filter;
  switch (input.Filter)
  {
    case 0:
    {
      auto cubic = vtkSmartPointer<vtkCubicSplineFilter>::New();
      cubic->SetEndCondition(kind);
      filter = cubic;
      break;
    }
    case 1:
    {
      auto generalized = vtkSmartPointer<vtkGeneralizedCubicSplineFilter>::New();
      generalized->SetSpaceKind(kind);
      generalized->SetAutomatic(automatic);
      generalized->SetTension(input.First);
      generalized->SetMaxTension(input.Second);
      generalized->SetTensionArrayName(input.flag(4) ? PerPointArray : nullptr);
      filter = generalized;
      break;
    }
    case 2:
    {
      auto variable = vtkSmartPointer<vtkVariableDegreeSplineFilter>::New();
      variable->SetMode(other ? 1 + (kind & 1) : 0);
      approximates = other;
      variable->SetNumberOfKnots(knots);
      variable->SetAutomatic(automatic);
      variable->SetDegree(input.First);
      variable->SetMaxDegree(input.Second);
      variable->SetLambda(input.Second);
      variable->SetEndCondition(kind);
      variable->SetDegreeArrayName(input.flag(4) ? PerPointArray : nullptr);
      filter = variable;
      break;
    }
    case 3:
    {
      auto quintic = vtkSmartPointer<vtkTensionQuinticSplineFilter>::New();
      quintic->SetMode(other ? vtkTensionQuinticSplineFilter::APPROXIMATE
                             : vtkTensionQuinticSplineFilter::INTERPOLATE);
      approximates = other;
      quintic->SetNumberOfKnots(knots);
      quintic->SetContinuity(kind & 1 ? vtkTensionQuinticSplineFilter::C3
                                      : vtkTensionQuinticSplineFilter::C4);
      quintic->SetAutomatic(automatic);
      quintic->SetGamma(input.First);
      quintic->SetLambda(input.Second);
      filter = quintic;
      break;
    }
    default:
    {
      auto qqr = vtkSmartPointer<vtkQQRSplineFilter>::New();
      // Interpolate, Approximate (the points are the control polygon: still
      // the reference) or the local interpolation.
      qqr->SetMode(other ? 1 + (kind & 1) : 0);
      qqr->SetAutomatic(automatic);
      qqr->SetAlpha(input.First);
      qqr->SetBeta(input.Second);
      qqr->SetMaxAlpha(input.Second);
      qqr->SetLocalParameters(kind >> 1);
      qqr->SetX(input.First);
      qqr->SetY(input.Second);
      qqr->SetZ(input.First);
      qqr->SetZArrayName(input.flag(4) ? PerPointArray : nullptr);
      filter = qqr;
      break;
    }
  }
  filter->SetLineIdArrayName((input.Damage & 16) ? PerPointArray : nullptr);
  filter->SetClosed(input.flag(0));
  filter->SetParameterization(input.Kinds % 3);
  filter->SetNumberOfThreads(input.flag(7) ? 2 : 1);
  if (input.flag(2))
  {
    filter->SetSamplingModeToArcLength();
    filter->SetSampleLength(diagonal(input.Data) * std::pow(10.0, -(input.Sampling % 4)));
  }
  else
  {
    filter->SetNumberOfSubdivisions(1 + input.Sampling % 16);
  }
  return filter;
}

/// Bit-for-bit copies of what a filter must not change.
struct Snapshot
{
  std::vector<unsigned char> Points, Connectivity, Arrays;
  vtkMTimeType Time = 0;

  static void append(std::vector<unsigned char>& to, vtkDataArray* array)
  {
    if (array)
    {
      const auto* bytes = static_cast<const unsigned char*>(array->GetVoidPointer(0));
      to.insert(to.end(), bytes, bytes + array->GetDataSize() * array->GetDataTypeSize());
    }
  }

  explicit Snapshot(vtkPolyData* data)
  {
    append(this->Points, data->GetPoints()->GetData());
    for (vtkCellArray* cells : { data->GetLines(), data->GetVerts(), data->GetPolys() })
    {
      append(this->Connectivity, cells->GetConnectivityArray());
      append(this->Connectivity, cells->GetOffsetsArray());
    }
    vtkPointData* pd = data->GetPointData();
    for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
    {
      append(this->Arrays, pd->GetArray(a));
    }
    this->Time = data->GetMTime();
  }

  bool operator==(const Snapshot& other) const
  {
    return this->Points == other.Points && this->Connectivity == other.Connectivity &&
      this->Arrays == other.Arrays && this->Time == other.Time;
  }
};

/// Output arrays of the right sizes, finite points, cells within the points
/// (passesInput: the input's points and cells, damage included, with arrays added).
void checkOutput(vtkPolyData* output, const char* what, bool passesInput = false)
{
  CHECK(output, "%s: no output object", what);
  const vtkIdType points = output->GetNumberOfPoints();
  for (vtkIdType i = 0; i < points && !passesInput; ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    CHECK(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]),
      "%s: output point %lld is not finite", what, static_cast<long long>(i));
  }
  vtkPointData* pd = output->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    CHECK(pd->GetAbstractArray(a)->GetNumberOfTuples() == points,
      "%s: point array %s has %lld tuples for %lld points", what, pd->GetArrayName(a),
      static_cast<long long>(pd->GetAbstractArray(a)->GetNumberOfTuples()),
      static_cast<long long>(points));
  }
  vtkCellData* cd = output->GetCellData();
  for (int a = 0; a < cd->GetNumberOfArrays(); ++a)
  {
    CHECK(cd->GetAbstractArray(a)->GetNumberOfTuples() == output->GetNumberOfCells(),
      "%s: cell array %s has %lld tuples for %lld cells", what, cd->GetArrayName(a),
      static_cast<long long>(cd->GetAbstractArray(a)->GetNumberOfTuples()),
      static_cast<long long>(output->GetNumberOfCells()));
  }
  for (vtkCellArray* cells : { output->GetLines(), output->GetVerts(), output->GetPolys() })
  {
    if (passesInput)
    {
      break;
    }
    vtkDataArray* connectivity = cells->GetConnectivityArray();
    for (vtkIdType k = 0; k < connectivity->GetNumberOfTuples(); ++k)
    {
      const double id = connectivity->GetTuple1(k);
      CHECK(id >= 0 && id < points, "%s: output cell refers to point %g of %lld", what, id,
        static_cast<long long>(points));
    }
  }
}

/// Distance from p to segment ab.
double segmentDistance(const double p[3], const double a[3], const double b[3])
{
  double ab[3], ap[3], along = 0.0, length2 = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    ab[c] = b[c] - a[c];
    ap[c] = p[c] - a[c];
    along += ab[c] * ap[c];
    length2 += ab[c] * ab[c];
  }
  const double t = length2 > 0.0 ? std::clamp(along / length2, 0.0, 1.0) : 0.0;
  double d2 = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    d2 += (ap[c] - t * ab[c]) * (ap[c] - t * ab[c]);
  }
  return std::sqrt(d2);
}

/**
 * A curve that leaves its data is never called shape-preserving: a line
 * flagged ShapePreserving has PolygonDeviation within the bound, and (an
 * interpolation: its reference polygon is the data) each of its samples lies
 * within the bound of some segment of the input's finite, in-range lines,
 * relative to the longest of them (twice the audit's bound: the audit looks
 * at its own samples, not the output's).
 */
void checkDeviation(vtkPolyData* input, vtkPolyData* output, bool approximates, bool closed)
{
  vtkDataArray* preserving = output->GetCellData()->GetArray(shapesplines::names::ShapePreserving);
  vtkDataArray* deviation = output->GetCellData()->GetArray(shapesplines::names::PolygonDeviation);
  if (!preserving || !deviation)
  {
    return;
  }
  std::vector<std::array<double, 6>> segments;
  double longest = 0.0, largest = 0.0;
  const vtkIdType n = input->GetNumberOfPoints();
  vtkCellArray* lines = input->GetLines();
  const vtkIdType* ids = nullptr;
  vtkIdType count = 0;
  for (lines->InitTraversal(); lines->GetNextCell(count, ids);)
  {
    if (std::any_of(ids, ids + count, [n](vtkIdType id) { return id < 0 || id >= n; }))
    {
      continue;
    }
    // A one-point line (passed through) is a segment of length 0.
    const vtkIdType segmentCount = count == 1 ? 1 : count - 1 + (closed && count > 2 ? 1 : 0);
    for (vtkIdType k = 0; k < segmentCount; ++k)
    {
      std::array<double, 6> s;
      input->GetPoint(ids[k], s.data());
      input->GetPoint(ids[(k + 1) % count], s.data() + 3);
      if (std::all_of(s.begin(), s.end(), [](double v) { return std::isfinite(v); }))
      {
        segments.push_back(s);
        longest = std::max(longest, std::hypot(s[3] - s[0], s[4] - s[1], s[5] - s[2]));
        for (const double v : s)
        {
          largest = std::max(largest, std::abs(v));
        }
      }
    }
  }
  // Distances in units of the largest coordinate (a power of two): squares of
  // coordinates near 1e300 would overflow.
  const double unit = largest > 0.0 ? std::ldexp(1.0, std::ilogb(largest)) : 1.0;
  for (auto& s : segments)
  {
    for (double& v : s)
    {
      v /= unit;
    }
  }
  vtkCellArray* curves = output->GetLines();
  vtkIdType cell = 0;
  for (curves->InitTraversal(); curves->GetNextCell(count, ids); ++cell)
  {
    if (preserving->GetTuple1(cell) == 0.0)
    {
      continue;
    }
    CHECK(deviation->GetTuple1(cell) <= shapesplines::MaximumPolygonDeviation,
      "line %lld is called shape-preserving with PolygonDeviation %g", static_cast<long long>(cell),
      deviation->GetTuple1(cell));
    if (approximates || segments.empty())
    {
      continue;
    }
    const double bound =
      (2.0 * shapesplines::MaximumPolygonDeviation * longest + 1e-9 * largest) / unit;
    for (vtkIdType k = 0; k < count; ++k)
    {
      double p[3];
      output->GetPoint(ids[k], p);
      for (double& v : p)
      {
        v /= unit;
      }
      double nearest = Inf;
      for (const auto& s : segments)
      {
        nearest = std::min(nearest, segmentDistance(p, s.data(), s.data() + 3));
      }
      CHECK(nearest <= bound,
        "line %lld is called shape-preserving but its sample %lld is %g from the data (bound %g)",
        static_cast<long long>(cell), static_cast<long long>(k), nearest, bound);
    }
  }
}

void printLines(const char* what, vtkPolyData* data)
{
  vtkCellArray* lines = data->GetLines();
  const vtkIdType* ids = nullptr;
  vtkIdType count = 0, cell = 0;
  for (lines->InitTraversal(); lines->GetNextCell(count, ids); ++cell)
  {
    std::fprintf(stderr, "%s line %lld:", what, static_cast<long long>(cell));
    for (vtkIdType k = 0; k < count; ++k)
    {
      double p[3] = { NaN, NaN, NaN };
      if (ids[k] >= 0 && ids[k] < data->GetNumberOfPoints())
      {
        data->GetPoint(ids[k], p);
      }
      std::fprintf(stderr, " %lld (%g %g %g)", static_cast<long long>(ids[k]), p[0], p[1], p[2]);
    }
    std::fprintf(stderr, "\n");
  }
}

bool verbose()
{
  static const bool on = std::getenv("FUZZ_FILTERS_VERBOSE") != nullptr;
  return on;
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // Errors and warnings are the expected answer to most inputs here.
  vtkObject::GlobalWarningDisplayOff();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  Input input = decode(data, size);
  if (verbose())
  {
    vtkObject::GlobalWarningDisplayOn();
    std::fprintf(stderr, "filter %d flags 0x%02x sampling %d kinds %d values %g %g knots %d\n",
      input.Filter, input.Flags, input.Sampling, input.Kinds, input.First, input.Second,
      input.Knots);
    for (vtkIdType i = 0; i < input.Data->GetNumberOfPoints(); ++i)
    {
      double p[3];
      input.Data->GetPoint(i, p);
      std::fprintf(stderr, "point %lld: %.17g %.17g %.17g\n", static_cast<long long>(i), p[0], p[1], p[2]);
    }
    printLines("input", input.Data);
  }
  const Snapshot before(input.Data);
  bool approximates = false;
  vtkSmartPointer<vtkShapeSplineFilter> filter = makeFilter(input, approximates);
  filter->SetInputData(input.Data);
  filter->Update();
  CHECK(Snapshot(input.Data) == before, "the spline filter changed its input");
  vtkPolyData* curve = filter->GetOutput();
  if (verbose())
  {
    printLines("output", curve);
  }
  checkOutput(curve, filter->GetClassName());
  checkDeviation(input.Data, curve, approximates, input.flag(0));

  // A curve file damaged on its way back: arrays of the wrong size.
  vtkNew<vtkPolyData> damaged;
  damaged->DeepCopy(curve);
  vtkDataArray* curvature = damaged->GetPointData()->GetArray(shapesplines::names::Curvature);
  vtkDataArray* tangent = damaged->GetPointData()->GetArray(shapesplines::names::Tangent);
  if ((input.Damage & 4) && curvature && curvature->GetNumberOfTuples() > 0)
  {
    curvature->SetNumberOfTuples(curvature->GetNumberOfTuples() - 1);
  }
  if ((input.Damage & 8) && tangent)
  {
    tangent->SetNumberOfComponents(2);
  }
  const Snapshot curveBefore(damaged);

  vtkNew<vtkPolylineShapeAnalysis> analysis;
  analysis->SetInputData(0, input.Data);
  analysis->SetInputData(1, damaged);
  analysis->SetClosed(input.flag(0));
  analysis->Update();
  CHECK(Snapshot(input.Data) == before, "the shape analysis changed its input");
  checkOutput(analysis->GetOutput(), "vtkPolylineShapeAnalysis", true);

  vtkNew<vtkCurvatureCombFilter> comb;
  comb->SetInputData(damaged);
  comb->SetCombType(input.Kinds & 1);
  comb->Update();
  CHECK(Snapshot(damaged) == curveBefore, "the analysis or the comb changed the curve");
  checkOutput(comb->GetOutput(), "vtkCurvatureCombFilter");
  return 0;
}
