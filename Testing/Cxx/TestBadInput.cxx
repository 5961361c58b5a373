// Hostile input, table-driven: every spline filter against every row of the
// bad-input table (one CTest case per row per filter). Each row checks what
// holds for any input (no crash or hang, no NaN or Inf in any output array,
// the input unmodified, the good lines around a bad one still processed) and
// what the row is about (the message naming the cell, exact zeros, scaling).
// A new spline family joins by adding its filter to Filters() below.
#include "FilterTestUtilities.h"

#include "vtkCubicSplineFilter.h"
#include "vtkFloatArray.h"
#include "vtkGeneralizedCubicSplineFilter.h"
#include "vtkQQRSplineFilter.h"
#include "vtkShapeSplineFilter.h"
#include "vtkTensionQuinticSplineFilter.h"
#include "vtkVariableDegreeSplineFilter.h"

#include <gtest/gtest.h>

using namespace shapesplines::filtertest;

namespace
{
struct SplineFilter
{
  std::string Name;
  std::function<vtkSmartPointer<vtkShapeSplineFilter>()> Make;
  bool Interpolates = true; ///< rows then check that the curve passes through the data
};

std::vector<SplineFilter> Filters()
{
  auto quintic = [](int continuity) {
    auto filter = vtkSmartPointer<vtkTensionQuinticSplineFilter>::New();
    filter->SetContinuity(continuity);
    return vtkSmartPointer<vtkShapeSplineFilter>(filter);
  };
  return { { "Cubic", [] { return vtkSmartPointer<vtkShapeSplineFilter>(
                             vtkSmartPointer<vtkCubicSplineFilter>::New()); } },
    { "GeneralizedCubic", [] { return vtkSmartPointer<vtkShapeSplineFilter>(
                                vtkSmartPointer<vtkGeneralizedCubicSplineFilter>::New()); } },
    { "GeneralizedCubicVariableDegree", [] {
       auto filter = vtkSmartPointer<vtkGeneralizedCubicSplineFilter>::New();
       filter->SetSpaceKindToVariableDegree();
       filter->SetTension(3.0);
       return vtkSmartPointer<vtkShapeSplineFilter>(filter);
     } },
    { "TensionQuinticC4", [=] { return quintic(vtkTensionQuinticSplineFilter::C4); } },
    { "TensionQuinticC3", [=] { return quintic(vtkTensionQuinticSplineFilter::C3); } },
    { "VariableDegree", [] { return vtkSmartPointer<vtkShapeSplineFilter>(
                              vtkSmartPointer<vtkVariableDegreeSplineFilter>::New()); } },
    { "VariableDegreeClampedFixed", [] {
       auto filter = vtkSmartPointer<vtkVariableDegreeSplineFilter>::New();
       filter->SetEndCondition(vtkVariableDegreeSplineFilter::CLAMPED);
       filter->AutomaticOff();
       filter->SetDegree(12.0);
       return vtkSmartPointer<vtkShapeSplineFilter>(filter);
     } },
    { "QQR", [] { return vtkSmartPointer<vtkShapeSplineFilter>(
                   vtkSmartPointer<vtkQQRSplineFilter>::New()); } },
    { "QQRFixedCustom", [] {
       auto filter = vtkSmartPointer<vtkQQRSplineFilter>::New();
       filter->SetModeToLocalInterpolation();
       filter->AutomaticOff();
       filter->SetAlpha(7.0);
       filter->SetBeta(7.0);
       filter->SetLocalParameters(vtkQQRSplineFilter::CUSTOM);
       filter->SetZ(0.3);
       return vtkSmartPointer<vtkShapeSplineFilter>(filter);
     } },
    { "VariableDegreeApproximateLocal",
      [] {
       auto filter = vtkSmartPointer<vtkVariableDegreeSplineFilter>::New();
       filter->SetModeToApproximateLocal();
       filter->SetNumberOfKnots(5);
       return vtkSmartPointer<vtkShapeSplineFilter>(filter);
     },
      false },
    { "TensionQuinticApproximate",
      [] {
        auto filter = vtkSmartPointer<vtkTensionQuinticSplineFilter>::New();
        filter->SetModeToApproximate();
        filter->SetNumberOfKnots(5);
        return vtkSmartPointer<vtkShapeSplineFilter>(filter);
      },
      false },
    { "QQRControlPolygon",
      [] {
        auto filter = vtkSmartPointer<vtkQQRSplineFilter>::New();
        filter->SetModeToApproximate();
        return vtkSmartPointer<vtkShapeSplineFilter>(filter);
      },
      false } };
}

/// A curved, non-planar line (part of a conical helix), scaled and moved.
Polyline GoodLine(double scale = 1.0, const Point& offset = { 0, 0, 0 }, int count = 12)
{
  Polyline points;
  for (int i = 0; i < count; ++i)
  {
    const double t = 0.6 * i;
    const double r = 1.0 + 0.1 * t;
    points.push_back(offset + scale * Point{ r * std::cos(t), r * std::sin(t), 0.3 * t });
  }
  return points;
}

/// The bad line as cell 1 between two good lines (cells 0 and 2).
vtkSmartPointer<vtkPolyData> Between(const Polyline& bad)
{
  return PolylinesData({ GoodLine(), bad, GoodLine(2.0, { 5, 0, 0 }) });
}

struct Outcome
{
  FilterRun Run;
  vtkPolyData* Input;
  std::function<FilterRun(vtkPolyData*)> Rerun; ///< the same filter on other input
  bool Interpolates; ///< the filter's curves pass through the data
};

struct BadInput
{
  std::string Name;
  std::function<vtkSmartPointer<vtkPolyData>()> Make;
  std::function<void(const Outcome&)> Check;
};

/// Routine merges are counted in the cell array MergedPoints, not warned about.
void ExpectMerged(const Outcome& o, vtkIdType cell, int merged)
{
  EXPECT_EQ(CellArray(o.Run.Output, "MergedPoints")->GetTuple1(cell), merged);
  EXPECT_EQ(CountMessages(o.Run.Warnings, { "repeated" }), 0) << Joined(o.Run.Warnings);
}

void ExpectMessage(const std::vector<std::string>& messages, std::vector<std::string> fragments)
{
  EXPECT_GE(CountMessages(messages, fragments), 1)
    << "no message with all of: " << Joined(fragments) << "\ngot: " << Joined(messages);
}

/// Lines 0 and 2 of the output are the good lines' curves (their data points among the samples).
void ExpectGoodLinesProcessed(vtkPolyData* output, size_t lines)
{
  const auto cells = LinesOf(output);
  ASSERT_EQ(cells.size(), lines);
  for (const size_t c : { size_t(0), lines - 1 })
  {
    EXPECT_GT(cells[c].size(), 11u) << "line " << c << " not sampled";
  }
}

double MaxAbsAll(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = PointArray(data, name);
  double largest = 0.0;
  for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
  {
    largest = std::max(largest, std::abs(FlatValue(array, i)));
  }
  return largest;
}

/// Compares a run on scaled (and moved) input with the run on GoodLine():
/// positions map exactly, curvature and torsion scale by 1 / scale.
void ExpectScaledLike(const Outcome& o, double scale, const Point& offset, double tolerance)
{
  const FilterRun reference = o.Rerun(PolylinesData({ GoodLine() }));
  vtkPolyData* a = reference.Output;
  vtkPolyData* b = o.Run.Output;
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  double position = 0, curvature = 0, torsion = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    const Point expected = offset + scale * PointOf(a, i);
    position = std::max(position, Norm(PointOf(b, i) - expected) / (scale * 10.0));
    const double k = PointArray(a, "Curvature")->GetTuple1(i);
    const double t = PointArray(a, "Torsion")->GetTuple1(i);
    curvature = std::max(curvature, std::abs(scale * PointArray(b, "Curvature")->GetTuple1(i) - k) / 1.0);
    torsion = std::max(torsion, std::abs(scale * PointArray(b, "Torsion")->GetTuple1(i) - t) / 1.0);
  }
  Measure("largest relative position difference", position);
  Measure("largest curvature difference (unit scale)", curvature);
  Measure("largest torsion difference (unit scale)", torsion);
  EXPECT_LT(position, tolerance);
  EXPECT_LT(curvature, 1e3 * tolerance);
  EXPECT_LT(torsion, 1e3 * tolerance);
}

std::vector<BadInput> Table()
{
  const Point p = { 1, 2, 3 };
  return {
    { "EmptyInput", [] { return vtkSmartPointer<vtkPolyData>::New(); },
      [](const Outcome& o) {
        EXPECT_EQ(o.Run.Output->GetNumberOfPoints(), 0);
        ExpectMessage(o.Run.Warnings, { "no lines" });
      } },
    { "NoLines",
      [] {
        PolyDataBuilder b;
        b.Vertex({ 0, 0, 0 }).Polygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } });
        return b.Build();
      },
      [](const Outcome& o) {
        EXPECT_EQ(o.Run.Output->GetNumberOfLines(), 0);
        ExpectMessage(o.Run.Warnings, { "no lines" });
      } },
    { "OnePointLine", [p] { return Between({ p }); },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        EXPECT_EQ(LinesOf(o.Run.Output)[1].size(), 1u);
        ExpectMessage(o.Run.Warnings, { "cell 1", "fewer than two distinct points" });
      } },
    { "TwoPointLine", [] { return Between({ { 0, 0, 0 }, { 1, 2, 2 } }); },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        const IdList line = LinesOf(o.Run.Output)[1];
        EXPECT_EQ(MaxAbs(PointArray(o.Run.Output, "Curvature"), line), 0.0);
        ExpectMessage(o.Run.Warnings, { "cell 1", "straight segment" });
      } },
    { "ThreePointLine", [] { return Between({ { 0, 0, 0 }, { 1, 1, 0.5 }, { 2, 0, 1 } }); },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        // Three points are coplanar: zero torsion, exactly.
        EXPECT_EQ(MaxAbs(PointArray(o.Run.Output, "Torsion"), LinesOf(o.Run.Output)[1]), 0.0);
      } },
    { "AllPointsIdentical", [p] { return Between({ p, p, p, p, p }); },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        EXPECT_EQ(DistinctIds(LinesOf(o.Run.Output)[1]).size(), 5u); // passed through
        ExpectMessage(o.Run.Warnings, { "cell 1", "fewer than two distinct points" });
      } },
    { "RepeatedPointOnce",
      [] {
        Polyline line = GoodLine();
        line.insert(line.begin() + 5, line[5]);
        return Between(line);
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        ExpectMerged(o, 1, 1);
      } },
    { "RepeatedPointManyTimes",
      [] {
        Polyline line = GoodLine();
        line.insert(line.begin() + 5, 50, line[5]);
        return Between(line);
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        ExpectMerged(o, 1, 50);
      } },
    { "RepeatedPointsAtTheEnds",
      [] {
        Polyline line = GoodLine();
        line.insert(line.begin(), 3, line.front());
        line.insert(line.end(), 3, line.back());
        return Between(line);
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        ExpectMerged(o, 1, 6);
        // An interpolation's ends stay where the data end.
        const IdList line = LinesOf(o.Run.Output)[1];
        if (o.Interpolates)
        {
          EXPECT_EQ(PointOf(o.Run.Output, line.back()), GoodLine().back());
        }
      } },
    { "ExactlyCollinear",
      [] {
        Polyline line;
        for (const double s : { 0.0, 0.5, 0.75, 2.0, 2.5, 4.0 })
        {
          line.push_back({ s, 2 * s, 3 * s });
        }
        return Between(line);
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        const IdList line = LinesOf(o.Run.Output)[1];
        EXPECT_EQ(MaxAbs(PointArray(o.Run.Output, "Torsion"), line), 0.0);
        EXPECT_LT(MaxAbs(PointArray(o.Run.Output, "Curvature"), line), 1e-9);
        double offLine = 0.0;
        for (const vtkIdType id : line)
        {
          const Point q = PointOf(o.Run.Output, id);
          offLine = std::max(offLine, Norm(Cross(q, { 1, 2, 3 })) / Norm({ 1, 2, 3 }));
        }
        // Least squares solve normal equations: their condition is squared.
        EXPECT_LT(offLine, (o.Interpolates ? 1e-12 : 1e-10) * 15) << "the straight line bends";
      } },
    { "ExactlyCoplanar",
      [] {
        Polyline line = GoodLine();
        for (Point& q : line)
        {
          q[2] = 0.0;
        }
        return Between(line);
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        const IdList line = LinesOf(o.Run.Output)[1];
        EXPECT_EQ(MaxAbs(PointArray(o.Run.Output, "Torsion"), line), 0.0);
        for (const vtkIdType id : line)
        {
          ASSERT_EQ(PointOf(o.Run.Output, id)[2], 0.0) << "sample " << id << " leaves the plane";
        }
      } },
    { "NaNCoordinate",
      [] {
        Polyline line = GoodLine();
        line[4][1] = NaN;
        return Between(line);
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 2);
        ExpectMessage(o.Run.Errors, { "cell 1", "not finite" });
      } },
    { "PointIdOutOfRange",
      [] {
        // A damaged file: cell 1 refers to points the data do not have.
        auto data = Between(GoodLine());
        vtkNew<vtkCellArray> lines;
        vtkIdType id = 0;
        for (vtkIdType cell = 0; cell < 3; ++cell)
        {
          std::vector<vtkIdType> ids(12);
          for (vtkIdType& k : ids)
          {
            k = id++;
          }
          ids[5] = cell == 1 ? 1000 : ids[5];
          ids[6] = cell == 1 ? -7 : ids[6];
          lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
        }
        data->SetLines(lines);
        return data;
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 2);
        ExpectMessage(o.Run.Errors, { "cell 1", "point id 1000 out of range", "36 points" });
      } },
    { "SubnormalExtent",
      [] {
        // Distinct points all within 1e-310 of each other: subnormal differences.
        return Between(GoodLine(1e-311));
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 2);
        ExpectMessage(o.Run.Errors, { "cell 1", "less than 1e-300" });
      } },
    { "InfCoordinate",
      [] {
        Polyline line = GoodLine();
        line[0][2] = -Inf;
        return Between(line);
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 2);
        ExpectMessage(o.Run.Errors, { "cell 1", "not finite" });
      } },
    { "HugeCoordinates", [] { return PolylinesData({ GoodLine(1e12) }); },
      [](const Outcome& o) { ExpectScaledLike(o, 1e12, { 0, 0, 0 }, 1e-12); } },
    { "TinyCoordinates", [] { return PolylinesData({ GoodLine(1e-12) }); },
      [](const Outcome& o) { ExpectScaledLike(o, 1e-12, { 0, 0, 0 }, 1e-12); } },
    { "FarFromTheOrigin", [] { return PolylinesData({ GoodLine(1.0, { 1e8, -1e8, 1e8 }) }); },
      // Coordinates near 1e8 carry 1.5e-8 of rounding on a line of unit detail.
      [](const Outcome& o) { ExpectScaledLike(o, 1.0, { 1e8, -1e8, 1e8 }, 1e-7); } },
    { "ExtremelyUnevenSpacing",
      [] {
        Polyline line = GoodLine();
        line.insert(line.begin() + 6, line[5] + 1e-9 * (line[6] - line[5]));
        return Between(line);
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        EXPECT_TRUE(o.Run.Errors.empty()) << Joined(o.Run.Errors);
      } },
    { "ClosedLine",
      [] {
        Polyline line = Circle(2.0, 12);
        line.push_back(line.front());
        return Between(line);
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        const IdList line = LinesOf(o.Run.Output)[1];
        EXPECT_EQ(line.front(), line.back()) << "a closed line must come out closed";
      } },
    { "AlmostClosedLine",
      [] {
        Polyline line = Circle(2.0, 12);
        line.push_back(line.front() + Point{ 1e-6, 0, 0 });
        return Between(line);
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 3);
        const IdList line = LinesOf(o.Run.Output)[1];
        EXPECT_NE(line.front(), line.back()) << "a line that does not close must stay open";
      } },
    { "MixedCellTypes",
      [] {
        PolyDataBuilder b;
        b.Vertex({ 0, 0, 0 }).Line(GoodLine()).Polygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } });
        b.Strip({ { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 }, { 1, 1, 1 } }).Line(GoodLine(2.0));
        return b.Build();
      },
      [](const Outcome& o) {
        ExpectGoodLinesProcessed(o.Run.Output, 2);
        ExpectMessage(o.Run.Warnings, { "3 non-line cells" });
        EXPECT_EQ(o.Run.Output->GetNumberOfPolys() + o.Run.Output->GetNumberOfVerts() +
            o.Run.Output->GetNumberOfStrips(),
          0);
      } },
    { "FloatPoints",
      [] {
        auto data = PolylinesData({ GoodLine() });
        vtkNew<vtkPoints> points;
        points->SetDataTypeToFloat();
        points->DeepCopy(data->GetPoints());
        data->SetPoints(points);
        return data;
      },
      [](const Outcome& o) {
        ASSERT_EQ(o.Input->GetPoints()->GetDataType(), VTK_FLOAT);
        const FilterRun reference = o.Rerun(PolylinesData({ GoodLine() }));
        ASSERT_EQ(reference.Output->GetNumberOfPoints(), o.Run.Output->GetNumberOfPoints());
        double difference = 0.0;
        for (vtkIdType i = 0; i < o.Run.Output->GetNumberOfPoints(); ++i)
        {
          difference = std::max(difference, std::abs(PointArray(o.Run.Output, "Curvature")->GetTuple1(i) -
                                   PointArray(reference.Output, "Curvature")->GetTuple1(i)));
        }
        Measure("curvature difference, float against double input", difference);
        EXPECT_LT(difference, 1e-4);
      } },
  };
}

using Case = std::tuple<SplineFilter, BadInput>;

class BadInputTable : public ::testing::TestWithParam<Case>
{
};

TEST_P(BadInputTable, NoCrashNoNaNInputUntouchedClearMessage)
{
  const auto& [filter, row] = this->GetParam();
  const vtkSmartPointer<vtkPolyData> input = row.Make();
  const auto run = [&filter](vtkPolyData* data) {
    vtkSmartPointer<vtkShapeSplineFilter> spline = filter.Make();
    spline->SetInputData(data);
    return UpdateChecked(data, spline, { spline });
  };
  Outcome outcome{ run(input), input, run, filter.Interpolates };
  ExpectAllFinite(outcome.Run.Output);
  vtkCellData* cd = outcome.Run.Output->GetCellData();
  for (int a = 0; a < cd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = cd->GetArray(a);
    for (vtkIdType v = 0; array && v < array->GetNumberOfValues(); ++v)
    {
      ASSERT_TRUE(std::isfinite(FlatValue(array, v))) << array->GetName() << " value " << v;
    }
  }
  row.Check(outcome);
}

INSTANTIATE_TEST_SUITE_P(Filters, BadInputTable,
  ::testing::Combine(::testing::ValuesIn(Filters()), ::testing::ValuesIn(Table())),
  [](const ::testing::TestParamInfo<Case>& info) {
    return std::get<0>(info.param).Name + "_" + std::get<1>(info.param).Name;
  });
} // namespace
