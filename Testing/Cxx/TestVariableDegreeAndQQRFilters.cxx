// vtkVariableDegreeSplineFilter and vtkQQRSplineFilter through VTK pipelines:
// their options, their arrays and their warnings; the knots of both
// approximating families (with vtkTensionQuinticSplineFilter); and the warning
// of every automatic shape mode.
#include "FilterTestUtilities.h"
#include "LineCells.h"
#include "ShapeAnalysis.h"

#include "vtkCellData.h"
#include "vtkCubicSplineFilter.h"
#include "vtkDoubleArray.h"
#include "vtkGeneralizedCubicSplineFilter.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkQQRSplineFilter.h"
#include "vtkStringArray.h"
#include "vtkTensionQuinticSplineFilter.h"
#include "vtkVariableDegreeSplineFilter.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <random>
#include <utility>

using namespace shapesplines::filtertest;

namespace
{
template <class Filter>
FilterRun RunFilter(vtkPolyData* input, const std::function<void(Filter*)>& setup = {})
{
  vtkNew<Filter> filter;
  if (setup)
  {
    setup(filter);
  }
  filter->SetInputData(input);
  return UpdateChecked(input, filter, { filter });
}

using VariableDegree = vtkVariableDegreeSplineFilter;
using QQR = vtkQQRSplineFilter;
using Quintic = vtkTensionQuinticSplineFilter;
} // namespace

TEST(VariableDegreeSplineFilter, AutomaticDegreesKeepTheShapeTheQuinticBreaks)
{
  for (const char* name : { "akima.vtp", "rpn15a.vtp", "titanium.vtp" })
  {
    const auto data = ReadData(name);
    const FilterRun quintic = RunFilter<VariableDegree>(data, [](VariableDegree* f) { f->AutomaticOff(); });
    const FilterRun automatic = RunFilter<VariableDegree>(data);
    ExpectNoMessages(automatic);
    const double before = CellArray(quintic.Output, "ShapeViolations")->GetTuple1(0);
    const double after = CellArray(automatic.Output, "ShapeViolations")->GetTuple1(0);
    const double maxDegree = CellArray(automatic.Output, "MaxDegree")->GetTuple1(0);
    Measure(std::string(name) + ": quintic violations", before);
    Measure(std::string(name) + ": automatic violations", after);
    Measure(std::string(name) + ": max degree", maxDegree);
    EXPECT_GT(before, 0) << name;
    EXPECT_EQ(after, 0) << name;
    EXPECT_EQ(MaxAbs(PointArray(automatic.Output, "Degree"), DistinctIds(LinesOf(automatic.Output)[0])),
      maxDegree);
    EXPECT_EQ(MaxAbs(PointArray(quintic.Output, "Degree"), DistinctIds(LinesOf(quintic.Output)[0])), 5.0);
  }
}

TEST(VariableDegreeSplineFilter, DegreePerPointFromAnInputArray)
{
  // The helix with degree 30 on point 10, 2 (below the minimum: falls back to Degree) on point 20.
  const auto data = DeepCopy(ReadData("helix.vtp"));
  vtkNew<vtkDoubleArray> given;
  given->SetName("k");
  given->SetNumberOfTuples(data->GetNumberOfPoints());
  given->Fill(0.0);
  given->SetValue(10, 30.0);
  given->SetValue(20, 2.0);
  data->GetPointData()->AddArray(given);
  const FilterRun run = RunFilter<VariableDegree>(data, [](VariableDegree* f) {
    f->AutomaticOff();
    f->SetDegree(6.0);
    f->SetDegreeArrayName("k");
  });
  ExpectNoMessages(run);
  vtkDataArray* degree = PointArray(run.Output, "Degree");
  vtkDataArray* span = PointArray(run.Output, "SpanIndex");
  for (vtkIdType i = 0; i < degree->GetNumberOfTuples(); ++i)
  {
    const int j = static_cast<int>(span->GetTuple1(i));
    ASSERT_EQ(degree->GetTuple1(i), j == 9 || j == 10 ? 30.0 : 6.0) << "sample " << i << " span " << j;
  }
}

TEST(VariableDegreeSplineFilter, ApproximationModesKeepTheShapeOfPsiWithoutFlatteningTheCurve)
{
  // Both automatic schemes against degree 5 on the aorta with 40 knots:
  // never more violations of psi's shape (where it stands out of the noise),
  // never a curvature more than 2 times off the degree 5 curve's where that
  // stands out of the noise (flattening a curved stretch to keep a noisy
  // polygon's shape is what the automatic mode must not do).
  const auto data = ReadData("aorta-centerline.vtp");
  const std::vector<double> points = { 211.0, 198.0 }; // each line's points
  for (const int mode : { VariableDegree::APPROXIMATE_GLOBAL, VariableDegree::APPROXIMATE_LOCAL })
  {
    const FilterRun fixed = RunFilter<VariableDegree>(data, [mode](VariableDegree* f) {
      f->SetMode(mode);
      f->SetNumberOfKnots(40);
      f->SetNumberOfSubdivisions(4);
      f->AutomaticOff();
    });
    const FilterRun run = RunFilter<VariableDegree>(data, [mode](VariableDegree* f) {
      f->SetMode(mode);
      f->SetNumberOfKnots(40);
      f->SetNumberOfSubdivisions(4);
    });
    EXPECT_TRUE(run.Errors.empty()) << Joined(run.Errors);
    ExpectAllFinite(run.Output);
    const auto lines = LinesOf(run.Output);
    ASSERT_EQ(lines.size(), 2u);
    for (size_t c = 0; c < lines.size(); ++c)
    {
      // 40 knots, 39 spans of 4 samples: the approximation's own knots, not the data's.
      EXPECT_EQ(lines[c].size(), 39u * 4u + 1u) << "line " << c;
      const double before = CellArray(fixed.Output, "ShapeViolations")->GetTuple1(c);
      const double after = CellArray(run.Output, "ShapeViolations")->GetTuple1(c);
      const double change = CurvatureChange(fixed.Output, run.Output, c, points[c]);
      Measure("aorta line " + std::to_string(c) + ", mode " + std::to_string(mode) +
          ": violations of psi, degree 5 then automatic",
        before * 1000 + after);
      Measure("  largest curvature change", change);
      EXPECT_LE(after, before) << "line " << c;
      EXPECT_LE(change, 2.0 + 1e-9) << "line " << c;
    }
  }
}

/// Knots and median |curvature - 0.4| / 0.4 on the middle half of an approximation of a helix of
/// radius 2 and pitch 2 pi (6 turns, 32 points per turn) with Gaussian noise
/// of 0.5% of the radius (seeded), on uniform parameters, 2 samples per span.
template <class Filter>
std::pair<int, double> ApproximateNoisyHelix(
  const std::function<void(Filter*)>& approximate, int numberOfKnots)
{
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.01);
  Polyline points;
  for (int i = 0; i <= 192; ++i)
  {
    const double t = 2.0 * Pi * i / 32.0;
    points.push_back({ 2.0 * std::cos(t) + noise(rng), 2.0 * std::sin(t) + noise(rng), t + noise(rng) });
  }
  const FilterRun run = RunFilter<Filter>(PolylinesData({ points }), [&](Filter* f) {
    approximate(f);
    f->SetNumberOfKnots(numberOfKnots);
    f->SetParameterizationToUniform();
    f->SetNumberOfSubdivisions(2);
  });
  EXPECT_TRUE(run.Errors.empty() && run.Warnings.empty()) << Joined(run.Errors) << Joined(run.Warnings);
  vtkDataArray* curvature = PointArray(run.Output, "Curvature");
  std::vector<double> errors;
  const vtkIdType count = curvature->GetNumberOfTuples();
  for (vtkIdType i = count / 4; i < count - count / 4; ++i)
  {
    errors.push_back(std::abs(curvature->GetTuple1(i) - 0.4) / 0.4);
  }
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  return { static_cast<int>(run.Output->GetNumberOfPoints() - 1) / 2 + 1, errors[errors.size() / 2] };
}

TEST(ApproximatingFilters, NumberOfKnotsZeroLetsCrossValidationChoose)
{
  const std::function<void(Quintic*)> quintic = [](Quintic* f) {
    f->SetModeToApproximate();
    f->AutomaticOff();
  };
  const std::function<void(VariableDegree*)> variableDegree = [](VariableDegree* f) {
    f->SetModeToApproximateLocal();
    f->AutomaticOff();
  };
  EXPECT_EQ(vtkNew<Quintic>()->GetNumberOfKnots(), 0);
  EXPECT_EQ(vtkNew<VariableDegree>()->GetNumberOfKnots(), 0);
  const auto [quinticKnots, quinticError] = ApproximateNoisyHelix(quintic, 0);
  const auto [variableKnots, variableError] = ApproximateNoisyHelix(variableDegree, 0);
  const auto [allKnots, allError] = ApproximateNoisyHelix(quintic, 1000);
  Measure("noisy helix, quintic: knots chosen", quinticKnots);
  Measure("noisy helix, quintic: median curvature error", quinticError);
  Measure("noisy helix, variable degree: median curvature error", variableError);
  Measure("noisy helix, quintic with 96 knots: median curvature error", allError);
  // Both families take the count chosen from the data: fewer than the 96
  // the points allow, which follow the noise. (The fewest knots within half
  // a standard error of the best score lean to the smooth side: 1.3% at the
  // best score's count here, 2.7% at the one taken, which on randomly
  // sampled trefoils halves the worst torsion error.)
  EXPECT_EQ(variableKnots, quinticKnots);
  EXPECT_EQ(allKnots, 96);
  EXPECT_GE(quinticKnots, 12);
  EXPECT_LE(quinticKnots, 60);
  EXPECT_LT(quinticError, 0.03);
  EXPECT_LT(variableError, 0.03);
  EXPECT_GT(allError, 2 * quinticError);
}

TEST(ApproximatingFilters, TheAortaCenterlineAtTheDefaults)
{
  // Both approximating families at their defaults on the shipped aorta
  // centerline (uneven chords up to 8 times their median, repeated points,
  // a curled end): within 1% of the length of the cubic through the points,
  // no hook at the ends (before the ends were continued by mirrored points,
  // the least squares' ends followed the last points into curvatures of 12
  // to 16; the data's own end curls by about 100 degrees in its last 2.5
  // mm), and no violation of the reference polygon's shape left.
  const auto data = ReadData("aorta-centerline.vtp");
  const FilterRun cubic = RunFilter<vtkCubicSplineFilter>(data);
  const std::vector<std::pair<std::string, std::function<FilterRun(bool)>>> runs = {
    { "quintic", [&](bool automatic) {
       return RunFilter<Quintic>(data, [automatic](Quintic* f) {
         f->SetModeToApproximate();
         f->SetAutomatic(automatic);
       });
     } },
    { "variable degree", [&](bool automatic) {
       return RunFilter<VariableDegree>(data, [automatic](VariableDegree* f) {
         f->SetModeToApproximateLocal();
         f->SetAutomatic(automatic);
       });
     } } };
  for (const auto& [name, run] : runs)
  {
    const FilterRun fixed = run(false), approximation = run(true);
    EXPECT_TRUE(approximation.Errors.empty()) << Joined(approximation.Errors);
    ASSERT_EQ(LinesOf(approximation.Output).size(), 2u);
    for (vtkIdType c = 0; c < 2; ++c)
    {
      const double length = CellArray(approximation.Output, "Length")->GetTuple1(c);
      const double through = CellArray(cubic.Output, "Length")->GetTuple1(c);
      const double largest = MaxAbs(PointArray(approximation.Output, "Curvature"), LinesOf(approximation.Output)[c]);
      const double before = CellArray(fixed.Output, "ShapeViolations")->GetTuple1(c);
      const double after = CellArray(approximation.Output, "ShapeViolations")->GetTuple1(c);
      Measure(name + ", aorta line " + std::to_string(c) + ": length / cubic's", length / through);
      Measure("  largest curvature", largest);
      Measure("  knots", CellArray(approximation.Output, "NumberOfKnots")->GetTuple1(c));
      Measure("  noise level", CellArray(approximation.Output, "NoiseLevel")->GetTuple1(c));
      const double knots = CellArray(approximation.Output, "NumberOfKnots")->GetTuple1(c);
      const double chosen = CellArray(fixed.Output, "NumberOfKnots")->GetTuple1(c);
      Measure("  violations, fixed then automatic", 1000 * before + after);
      EXPECT_NEAR(length / through, 1.0, 0.01);
      EXPECT_LE(largest, 1.0);
      // Violations come and go with the knot count near the curled ends
      // (line 0 keeps 1 at the cross-validated 34, line 1 2 at 30): the
      // automatic mode takes a count up to two away that keeps none.
      EXPECT_EQ(after, 0.0);
      EXPECT_LE(std::abs(knots - chosen), 2.0);
    }
  }
}

TEST(ApproximatingFilters, CarriedArraysStayFiniteWhereCorrectedParametersTie)
{
  // Scattered points (random 3D clouds and walks, 8 to 59 of them): the
  // corrected parameters of the points past a fit's end all project onto
  // its end and tie. The input's arrays on the samples are interpolated
  // between the data points around each sample's parameter; across a tie
  // there is nothing to interpolate over (before: NaN at the last sample of
  // 1 of these 40 lines with the quintic, 4 with the variable degree spline).
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  std::uniform_int_distribution<int> count(8, 59);
  std::vector<Polyline> lines;
  for (int line = 0; line < 40; ++line)
  {
    Polyline points(count(random));
    Point walk{ 0.0, 0.0, 0.0 };
    for (Point& p : points)
    {
      const Point step{ normal(random), normal(random), normal(random) };
      walk = walk + step;
      p = line % 2 == 0 ? step : walk;
    }
    lines.push_back(points);
  }
  const auto data = PolylinesData(lines);
  vtkNew<vtkDoubleArray> constant;
  constant->SetName("Constant");
  constant->SetNumberOfTuples(data->GetNumberOfPoints());
  constant->Fill(7.0);
  data->GetPointData()->AddArray(constant);
  const std::vector<std::pair<std::string, FilterRun>> runs = {
    { "quintic", RunFilter<Quintic>(data, [](Quintic* f) { f->SetModeToApproximate(); }) },
    { "variable degree, local", RunFilter<VariableDegree>(data,
      [](VariableDegree* f) { f->SetModeToApproximateLocal(); }) },
    { "variable degree, global", RunFilter<VariableDegree>(data,
      [](VariableDegree* f) { f->SetModeToApproximateGlobal(); }) } };
  for (const auto& [name, run] : runs)
  {
    vtkDataArray* carried = PointArray(run.Output, "Constant");
    ASSERT_NE(carried, nullptr) << name;
    int off = 0;
    for (vtkIdType i = 0; i < carried->GetNumberOfTuples(); ++i)
    {
      off += !(std::abs(carried->GetTuple1(i) - 7.0) < 1e-12);
    }
    EXPECT_EQ(off, 0) << name << ": samples whose carried value is not the input's 7";
  }
}

TEST(ApproximatingFilters, TheAutomaticModeNeverKinksTheCurve)
{
  // The aorta approximated with 26 to 39 knots, each family's automatic
  // mode against its fixed parameters: nowhere more than twice the fixed
  // fit's largest curvature. The bound against flattening only looked where
  // the fixed fit bends beyond what the noise can: on its straighter
  // stretches the variable degree spline raised a span to degree 231 for
  // one violation, a kink of curvature 9.8 where the fixed fit's largest is
  // 0.44 (33 knots; 8.6 for 1.1 at 32).
  const auto data = ReadData("aorta-centerline.vtp");
  auto run = [&](bool quintic, int knots, bool automatic) {
    if (quintic)
    {
      return RunFilter<Quintic>(data, [=](Quintic* f) {
        f->SetModeToApproximate();
        f->SetNumberOfKnots(knots);
        f->SetAutomatic(automatic);
      });
    }
    return RunFilter<VariableDegree>(data, [=](VariableDegree* f) {
      f->SetModeToApproximateLocal();
      f->SetNumberOfKnots(knots);
      f->SetAutomatic(automatic);
    });
  };
  for (const bool quintic : { true, false })
  {
    double worst = 0.0;
    for (int knots = 26; knots <= 39; ++knots)
    {
      const FilterRun fixed = run(quintic, knots, false), automatic = run(quintic, knots, true);
      ASSERT_EQ(LinesOf(automatic.Output).size(), 2u);
      for (vtkIdType c = 0; c < 2; ++c)
      {
        const double ratio =
          MaxAbs(PointArray(automatic.Output, "Curvature"), LinesOf(automatic.Output)[c]) /
          MaxAbs(PointArray(fixed.Output, "Curvature"), LinesOf(fixed.Output)[c]);
        worst = std::max(worst, ratio);
        EXPECT_LE(ratio, 2.0) << (quintic ? "quintic" : "variable degree") << ", " << knots
                              << " knots, line " << c;
      }
    }
    Measure(std::string(quintic ? "quintic" : "variable degree") +
        ": largest curvature, automatic over fixed, worst of 28 lines",
      worst);
  }
}

TEST(ApproximatingFilters, ApproximateClosedLinesAndReportShortOnesTheyInterpolate)
{
  // A noisy closed circle (radius 1, 60 points, last = first): a closed
  // approximation, smooth across the seam, near the circle.
  std::mt19937 rng(6);
  std::normal_distribution<double> noise(0.0, 0.005);
  Polyline ring = Circle(1.0, 60);
  for (Point& p : ring)
  {
    p = p + Point{ noise(rng), noise(rng), noise(rng) };
  }
  ring.push_back(ring.front());
  const auto input = PolylinesData({ ring });
  const FilterRun quintic = RunFilter<Quintic>(input, [](Quintic* f) {
    f->SetModeToApproximate();
    f->SetNumberOfKnots(0);
  });
  const FilterRun variable =
    RunFilter<VariableDegree>(input, [](VariableDegree* f) { f->SetModeToApproximateGlobal(); });
  for (const FilterRun* run : { &quintic, &variable })
  {
    ExpectNoMessages(*run);
    const auto lines = LinesOf(run->Output);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].front(), lines[0].back()); // closed
    // Fewer knots than points (10 samples a span), and the circle's curvature.
    EXPECT_LT(run->Output->GetNumberOfPoints(), 30 * 10);
    double range[2];
    PointArray(run->Output, "Curvature")->GetRange(range);
    Measure("noisy closed circle: curvature range width", range[1] - range[0]);
    EXPECT_GT(range[0], 0.9);
    EXPECT_LT(range[1], 1.1);
  }
  // Five points are too few to approximate: interpolated, with a warning.
  const auto shortLine = PolylinesData({ { { 0, 0, 0 }, { 1, 0.2, 0 }, { 2, 0, 0.3 }, { 3, 0.4, 0 }, { 4, 0, 0 } } });
  const FilterRun tooShort = RunFilter<Quintic>(shortLine, [](Quintic* f) { f->SetModeToApproximate(); });
  EXPECT_EQ(CountMessages(tooShort.Warnings, { "interpolated, not approximated", "too few points" }), 1)
    << Joined(tooShort.Warnings);
  EXPECT_EQ(tooShort.Output->GetNumberOfPoints(), 4 * 10 + 1);
}

TEST(ApproximationFilters, KnotsThatLeaveASpanWithoutPointsAreWarnedAbout)
{
  // A helix with a turn missing: 20 knots uniform in chord length leave a
  // span in the gap without points; both approximating families keep the
  // count asked for and say so, once; chosen per line (0), no warning.
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.005);
  Polyline points;
  for (int i = 0; i < 80; ++i)
  {
    const double t = 2.0 * Pi * (i < 40 ? i / 39.0 : 2.0 + (i - 40) / 39.0);
    points.push_back({ std::cos(t) + noise(rng), std::sin(t) + noise(rng), 0.25 * t + noise(rng) });
  }
  const auto input = PolylinesData({ points });
  for (const int knots : { 20, 0 })
  {
    const FilterRun quintic = RunFilter<Quintic>(input, [&](Quintic* f) {
      f->SetModeToApproximate();
      f->SetNumberOfKnots(knots);
    });
    const FilterRun variable = RunFilter<VariableDegree>(input, [&](VariableDegree* f) {
      f->SetModeToApproximateLocal();
      f->SetNumberOfKnots(knots);
    });
    for (const FilterRun* run : { &quintic, &variable })
    {
      EXPECT_EQ(CountMessages(run->Warnings, { "too few points to decide it", "Number Of Knots 0" }),
        knots > 0 ? 1 : 0)
        << knots << " knots: " << Joined(run->Warnings);
      if (knots > 0)
      {
        EXPECT_EQ(CellArray(run->Output, "NumberOfKnots")->GetTuple1(0), knots);
      }
      EXPECT_EQ(CellArray(run->Output, "NoiseLevel")->GetTuple1(0) > 0.0, knots == 0);
    }
  }
}

TEST(VariableDegreeSplineFilter, SettingsTheAutomaticModeCannotUseAreReported)
{
  const auto data = ReadData("helix.vtp");
  const FilterRun capped = RunFilter<VariableDegree>(data, [](VariableDegree* f) {
    f->SetDegree(20.0);
    f->SetMaxDegree(10.0);
  });
  EXPECT_EQ(CountMessages(capped.Warnings, { "MaxDegree", "cannot raise" }), 1) << Joined(capped.Warnings);
  const FilterRun array = RunFilter<VariableDegree>(data, [](VariableDegree* f) {
    f->SetModeToApproximateGlobal();
    f->SetDegreeArrayName("Anything");
  });
  EXPECT_EQ(CountMessages(array.Warnings, { "DegreeArrayName", "interpolation only" }), 1)
    << Joined(array.Warnings);
  vtkNew<VariableDegree> clamped;
  clamped->SetDegree(2.0);
  clamped->SetLambda(-1.0);
  EXPECT_EQ(clamped->GetDegree(), 5.0);
  EXPECT_EQ(clamped->GetLambda(), 0.001);
}

TEST(QQRSplineFilter, InterpolatesAndWritesItsExponents)
{
  const auto data = ReadData("akima.vtp");
  const FilterRun run = RunFilter<QQR>(data, [](QQR* f) { f->AutomaticOff(); });
  ExpectNoMessages(run);
  const auto line = LinesOf(run.Output)[0];
  ExpectDataPointsAmongSamples(PointsOfLine(data, LinesOf(data)[0]), run.Output, line, 10);
  EXPECT_EQ(MaxAbs(PointArray(run.Output, "Alpha"), DistinctIds(line)), 4.0);
  EXPECT_EQ(CellArray(run.Output, "MaxAlpha")->GetTuple1(0), 4.0);
  const FilterRun automatic = RunFilter<QQR>(data);
  Measure("Akima, qqr interpolation: alpha = 4 violations",
    CellArray(run.Output, "ShapeViolations")->GetTuple1(0));
  Measure("Akima, qqr interpolation: automatic violations",
    CellArray(automatic.Output, "ShapeViolations")->GetTuple1(0));
  EXPECT_LE(CellArray(automatic.Output, "ShapeViolations")->GetTuple1(0),
    CellArray(run.Output, "ShapeViolations")->GetTuple1(0));
  // The automatic mode straightens spans; the fixed one leaves them.
  EXPECT_EQ(CellArray(run.Output, "MaxStraightness")->GetTuple1(0), 0.0);
  EXPECT_GT(CellArray(automatic.Output, "MaxStraightness")->GetTuple1(0), 0.5);
  EXPECT_LE(MaxAbs(PointArray(automatic.Output, "Straightness"), DistinctIds(line)), 1.0);
}

TEST(QQRSplineFilter, CustomXAndYShapeOnlyTheControlPolygonsCurve)
{
  // As documented, the interpolations use Z only. Before, Interpolate took
  // X and Y too: at X = 1 a clean helix of 20 points swung out to 6e6 times
  // its size, and its Length (3.1e7) fell short of its own samples' polygon.
  const auto data = PolylinesData(NoisyHelices(1, 20, 0.0, 1));
  auto run = [&](int mode, double x, double y) {
    return RunFilter<QQR>(data, [=](QQR* f) {
      f->SetMode(mode);
      f->AutomaticOff();
      f->SetLocalParametersToCustom();
      f->SetX(x);
      f->SetY(y);
      f->SetZ(0.5);
    });
  };
  for (const int mode : { QQR::INTERPOLATE, QQR::LOCAL_INTERPOLATION, QQR::APPROXIMATE })
  {
    const FilterRun low = run(mode, 0.0, 0.0), high = run(mode, 1.0, 0.9);
    double moved = 0.0;
    for (vtkIdType i = 0; i < low.Output->GetNumberOfPoints(); ++i)
    {
      moved = std::max(moved, std::sqrt(vtkMath::Distance2BetweenPoints(
                                low.Output->GetPoint(i), high.Output->GetPoint(i))));
    }
    if (mode == QQR::APPROXIMATE)
    {
      EXPECT_GT(moved, 0.01) << "X and Y shape the control polygon's curve";
    }
    else
    {
      EXPECT_EQ(moved, 0.0) << "mode " << mode;
      EXPECT_LT(CellArray(high.Output, "Length")->GetTuple1(0), 20.0) << "mode " << mode;
    }
  }
}

TEST(QQRSplineFilter, FlattensTheCurveOnlyWhereStraighteningLeavesViolations)
{
  // Helices with noise: the fixed curve fails torsion signs where the points
  // barely twist. Moving spans towards their chords mends them at 0.1% noise,
  // and then no knot is flattened (a flattened knot has curvature 0); at 0.2%
  // it leaves some, and the automatic mode flattens the curve at those
  // spans' knots (Flattening, MaxFlattening) and keeps every sign.
  for (const double noise : { 0.001, 0.002 })
  {
    const auto data = PolylinesData(NoisyHelices(4, 50, noise, noise == 0.001 ? 11 : 2));
    const FilterRun fixed = RunFilter<QQR>(data, [](QQR* f) { f->AutomaticOff(); });
    const FilterRun automatic = RunFilter<QQR>(data);
    const std::vector<IdList> lines = LinesOf(automatic.Output);
    ASSERT_EQ(lines.size(), 4u);
    double before = 0.0, after = 0.0;
    for (vtkIdType c = 0; c < 4; ++c)
    {
      before += CellArray(fixed.Output, "ShapeViolations")->GetTuple1(c);
      after += CellArray(automatic.Output, "ShapeViolations")->GetTuple1(c);
      EXPECT_EQ(CellArray(fixed.Output, "MaxFlattening")->GetTuple1(c), 0.0);
      EXPECT_LE(MaxAbs(PointArray(automatic.Output, "Flattening"), lines[c]), 1.0);
    }
    const std::string helices = "four helices with noise " + std::to_string(noise);
    Measure(helices + ", qqr: violations fixed", before);
    Measure(helices + ", qqr: violations automatic", after);
    EXPECT_GT(before, 20.0);
    EXPECT_EQ(after, 0.0);
    const double flattened = CellArray(automatic.Output, "MaxFlattening")->GetRange()[1];
    if (noise == 0.001)
    {
      EXPECT_EQ(flattened, 0.0);
    }
    else
    {
      EXPECT_GT(flattened, 0.0);
    }
  }
}

TEST(AutomaticShapeFilters, ViolationsLeftAreNamedInOneWarning)
{
  // Two noisy helices (400 points, 0.2% of the radius, 16 a turn): qqr cannot
  // straighten two neighbouring spans where the points turn, and leaves some
  // violations within the automatic mode's bounds; the generalized cubic's
  // tension removes them all. The warning names each line and a failing
  // criterion, and the families that gather each bend at its knot.
  const auto data = PolylinesData(NoisyHelices(2, 400, 0.002, 1));
  const FilterRun automatic = RunFilter<QQR>(data);
  vtkDataArray* left = CellArray(automatic.Output, "ShapeViolations");
  ASSERT_EQ(left->GetNumberOfTuples(), 2);
  Measure("two noisy helices, qqr automatic: violations left on line 0", left->GetTuple1(0));
  Measure("two noisy helices, qqr automatic: violations left on line 1", left->GetTuple1(1));
  ASSERT_GT(left->GetTuple1(0), 0.0);
  ASSERT_GT(left->GetTuple1(1), 0.0);
  EXPECT_EQ(CountMessages(automatic.Warnings,
              { "2 line(s) keep shape violations", "cell 0", "cell 1", "convexity on span at spans",
                "the Generalized Cubic Spline and the Variable Degree Spline" }),
    1)
    << Joined(automatic.Warnings);
  const FilterRun fixed = RunFilter<QQR>(data, [](QQR* f) { f->AutomaticOff(); });
  EXPECT_GT(CellArray(fixed.Output, "ShapeViolations")->GetTuple1(0), 0.0);
  EXPECT_EQ(CountMessages(fixed.Warnings, { "keep shape violations" }), 0) << Joined(fixed.Warnings);
  vtkNew<vtkGeneralizedCubicSplineFilter> tensioned;
  tensioned->SetInputData(data);
  const FilterRun preserved = UpdateChecked(data, tensioned, { tensioned });
  EXPECT_EQ(CellArray(preserved.Output, "ShapeViolations")->GetTuple1(0), 0.0);
  EXPECT_EQ(CountMessages(preserved.Warnings, { "keep shape violations" }), 0)
    << Joined(preserved.Warnings);
}

TEST(AutomaticShapeFilters, ALineLeftStrayingFromItsDataIsNamed)
{
  // Six points of a random walk, approximated: the least squares on the two
  // knots cross-validation takes bulges 1.3 local segment lengths off L*,
  // its one segment. That straying is the line's only violation, and the
  // warning about what is left names it (it gave "Line (cell 0): ." before).
  const Polyline walk = { { 0.504, 1.053, 1.037 }, { 1.642, 1.541, 1.286 },
    { 1.420, 2.185, 0.836 }, { 0.591, 2.346, 1.506 }, { 1.664, 2.505, 2.810 },
    { 1.615, 2.132, 0.938 } };
  const auto data = PolylinesData({ walk });
  const std::vector<std::string> named = { "1 line(s) keep shape violations",
    "Line (cell 0): straying from its data at span 0." };
  const FilterRun quintic = RunFilter<Quintic>(data, [](Quintic* f) { f->SetModeToApproximate(); });
  EXPECT_EQ(CellArray(quintic.Output, "ShapeViolations")->GetTuple1(0), 1.0);
  EXPECT_EQ(CountMessages(quintic.Warnings, named), 1) << Joined(quintic.Warnings);
  const FilterRun variableDegree =
    RunFilter<VariableDegree>(data, [](VariableDegree* f) { f->SetModeToApproximateGlobal(); });
  EXPECT_EQ(CellArray(variableDegree.Output, "ShapeViolations")->GetTuple1(0), 1.0);
  EXPECT_EQ(CountMessages(variableDegree.Warnings, named), 1) << Joined(variableDegree.Warnings);
}

TEST(AutomaticShapeFilters, ALineThatRunsStraightBackIsNamedNotBlamedOnTheFamily)
{
  // A helix whose last points go back and forth between its last two (as a
  // streamline oscillating about a critical point): every smooth curve
  // through them stops at the turns (a cusp). One warning names the line
  // and its first such point, instead of a curvature spike warning that
  // recommends another family and a straying span's that blames the
  // spacing; the clean helix beside it is not named; an approximation,
  // which does not pass through the points, has none.
  Polyline helix;
  for (int i = 0; i < 40; ++i)
  {
    const double t = 2.0 * vtkMath::Pi() * i / 16.0;
    helix.push_back({ std::cos(t), std::sin(t), 0.25 * t });
  }
  Polyline reversing = helix;
  for (int k = 0; k < 4; ++k)
  {
    reversing.push_back(helix[k % 2 == 0 ? 38 : 39]);
  }
  const auto data = PolylinesData({ reversing, helix });
  const FilterRun tensioned = RunFilter<vtkGeneralizedCubicSplineFilter>(data);
  EXPECT_EQ(CountMessages(tensioned.Warnings,
              { "1 line(s) run straight back", "Line (cell 0): 4 point(s), the first its point 39" }),
    1)
    << Joined(tensioned.Warnings);
  EXPECT_EQ(CountMessages(tensioned.Warnings, { "run straight back", "cell 1" }), 0);
  EXPECT_EQ(CountMessages(tensioned.Warnings, { "cusp or a kink" }), 0)
    << Joined(tensioned.Warnings);
  const FilterRun interpolated = RunFilter<Quintic>(data);
  EXPECT_EQ(CountMessages(interpolated.Warnings, { "1 line(s) run straight back", "cell 0" }), 1)
    << Joined(interpolated.Warnings);
  EXPECT_EQ(CountMessages(interpolated.Warnings, { "strays" }), 0) << Joined(interpolated.Warnings);
  EXPECT_EQ(CountMessages(interpolated.Warnings, { "cusp or a kink" }), 0)
    << Joined(interpolated.Warnings);
  const FilterRun approximated =
    RunFilter<Quintic>(data, [](Quintic* f) { f->SetModeToApproximate(); });
  EXPECT_EQ(CountMessages(approximated.Warnings, { "run straight back" }), 0)
    << Joined(approximated.Warnings);
}

namespace
{
/// Per line of the aorta in Data/: a family's violations in its fixed and
/// default (automatic) modes, and the automatic curve's largest curvature,
/// absolute and over the data's largest discrete curvature (measured).
struct AortaFigures
{
  double Fixed = 0.0, Automatic = 0.0, Curvature = 0.0, CurvatureOverData = 0.0;
};

template <class Filter>
std::vector<AortaFigures> OnTheAorta(const std::string& family, FilterRun& automatic)
{
  const auto data = ReadData("aorta-centerline.vtp");
  const FilterRun fixed = RunFilter<Filter>(data, [](Filter* f) { f->AutomaticOff(); });
  automatic = RunFilter<Filter>(data);
  const FilterRun discrete = RunFilter<vtkPolylineShapeAnalysis>(data);
  const std::vector<IdList> inputLines = LinesOf(data), lines = LinesOf(automatic.Output);
  std::vector<AortaFigures> figures(lines.size());
  for (size_t c = 0; c < lines.size() && c < inputLines.size(); ++c)
  {
    AortaFigures& line = figures[c];
    line.Fixed = CellArray(fixed.Output, "ShapeViolations")->GetTuple1(c);
    line.Automatic = CellArray(automatic.Output, "ShapeViolations")->GetTuple1(c);
    line.Curvature = MaxAbs(PointArray(automatic.Output, "Curvature"), lines[c]);
    line.CurvatureOverData =
      line.Curvature / MaxAbs(PointArray(discrete.Output, "DiscreteCurvature"), inputLines[c]);
    const std::string name = "aorta line " + std::to_string(c) + ", " + family;
    Measure(name + ": violations fixed", line.Fixed);
    Measure(name + ": violations automatic", line.Automatic);
    Measure(name + ": curvature / data's", line.CurvatureOverData);
  }
  return figures;
}
} // namespace

TEST(AutomaticShapeFilters, TheQuinticsTensionKeepsTheAortasShape)
{
  // The aorta's chords range from 9e-5 to 1: lowering gamma a little on a
  // span pushes the curve beyond the automatic mode's bounds (gamma 0.5
  // everywhere: 1.9e4 times the data's curvature) where lowering it much
  // (0.05) is fine. Searched span by span only, the tension stopped at the
  // bounds with 49 and 27 violations left; from the best common level it
  // leaves a few, within the bounds, and short of what the filter warns
  // about as a cusp (line 0 had kept 1.1e6 over its bounding box diagonal,
  // within 1e3 times the data's curvature).
  FilterRun automatic;
  const std::vector<AortaFigures> figures = OnTheAorta<Quintic>("quintic", automatic);
  ASSERT_EQ(figures.size(), 2u);
  const double diagonal = ReadData("aorta-centerline.vtp")->GetLength(); // of the bounding box
  for (size_t c = 0; c < 2; ++c)
  {
    EXPECT_LE(figures[c].Automatic, 0.05 * figures[c].Fixed) << c;
    EXPECT_LE(figures[c].Automatic, 1.0) << c; // a convexity at knot 84 of line 0
    EXPECT_LE(figures[c].CurvatureOverData, 1e3) << c;
    EXPECT_LE(figures[c].Curvature * diagonal, 1e6) << c;
  }
  EXPECT_EQ(CountMessages(automatic.Warnings, { "cusp or a kink" }), 0)
    << Joined(automatic.Warnings);
}

TEST(AutomaticShapeFilters, QQRsDefaultModeOnTheAorta)
{
  // The aorta's second line: straightening a span moves the curve (a global
  // solve) beyond what the audit of its neighbourhood sees, and the search's
  // best curve, audited whole, failed 3 times (2 convexity, 1 torsion sign).
  // Searched on from it, 1 was left (a convexity failure on span 140);
  // refining the searches' curves, none. The fixed exponents' curve fails 43 and 27.
  FilterRun automatic;
  const std::vector<AortaFigures> figures = OnTheAorta<QQR>("qqr", automatic);
  ASSERT_EQ(figures.size(), 2u);
  for (size_t c = 0; c < 2; ++c)
  {
    EXPECT_GT(figures[c].Fixed, 20.0) << c;
    EXPECT_EQ(figures[c].Automatic, 0.0) << c;
    EXPECT_LE(figures[c].CurvatureOverData, 1e3) << c;
  }
}

TEST(AutomaticShapeFilters, FloatPointsConvertedToDoubleKeepTheirRounding)
{
  // The aorta's float coordinates, converted to double (as a script that
  // reads them into numpy and back does): the audit counts no turn or
  // twist within float rounding for float points, and treated the same
  // values as exact once they were doubles (qqr's default left 12 on line
  // 0 instead of 0, the cubic failed 71 / 39 instead of 43 / 27). Double
  // points that are all float values now carry float's rounding: the same
  // counts. One value off a float makes them doubles again.
  const auto floats = ReadData("aorta-centerline.vtp");
  ASSERT_EQ(floats->GetPoints()->GetDataType(), VTK_FLOAT);
  vtkNew<vtkPolyData> doubles;
  doubles->DeepCopy(floats);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(floats->GetPoints());
  doubles->SetPoints(points);
  ASSERT_EQ(doubles->GetPoints()->GetDataType(), VTK_DOUBLE);
  const FilterRun original = RunFilter<QQR>(floats);
  vtkDataArray* fromFloat = CellArray(original.Output, "ShapeViolations");
  const FilterRun converted = RunFilter<QQR>(doubles);
  vtkDataArray* fromDouble = CellArray(converted.Output, "ShapeViolations");
  ASSERT_EQ(fromDouble->GetNumberOfTuples(), 2);
  for (vtkIdType c = 0; c < 2; ++c)
  {
    EXPECT_EQ(fromDouble->GetTuple1(c), fromFloat->GetTuple1(c)) << c;
    EXPECT_LE(fromDouble->GetTuple1(c), 1.0) << c;
  }
  const auto cubicViolations = [](vtkPolyData* data) {
    const FilterRun cubic = RunFilter<vtkCubicSplineFilter>(data);
    vtkDataArray* left = CellArray(cubic.Output, "ShapeViolations");
    return left->GetTuple1(0) + left->GetTuple1(1);
  };
  const double asFloat = cubicViolations(floats);
  EXPECT_EQ(cubicViolations(doubles), asFloat);
  double moved[3];
  points->GetPoint(0, moved);
  moved[0] += 1e-9 * std::abs(moved[0]); // no longer a float value
  points->SetPoint(0, moved);
  doubles->Modified();
  EXPECT_GT(cubicViolations(doubles), asFloat);
}

namespace
{
using Steps = std::array<double, 3>;

/// The steps data's coordinates were written with, as the filters read a line's.
Steps StepsOf(vtkPolyData* data)
{
  std::vector<shapesplines::Vec3> points(data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    data->GetPoint(i, points[i].data());
  }
  const shapesplines::Vec3 steps =
    shapesplines::coordinateSteps(points, shapesplines::coordinatePrecision(data));
  return { steps.x(), steps.y(), steps.z() };
}

/// A sine wave of amplitude 1.5 in a tilted plane (two periods, x from 3 to
/// 15) at `points` points, each coordinate written by `write`, and the same
/// values moved off their digits by up to `jitter` times themselves: the
/// rounded line and one taken as exact.
std::pair<Polyline, Polyline> WrittenSineWave(
  int points, const std::function<double(double)>& write, double jitter)
{
  const double tilt = 0.7, turn = 0.4;
  const Point u{ std::cos(turn), 0.0, -std::sin(turn) };
  const Point v{ std::sin(turn) * std::sin(tilt), std::cos(tilt), std::cos(turn) * std::sin(tilt) };
  std::mt19937 random(5);
  std::uniform_real_distribution<double> off(-jitter, jitter);
  Polyline rounded, jittered;
  for (int i = 0; i < points; ++i)
  {
    const double t = 4 * Pi * i / (points - 1);
    Point p = Point{ 3.0, -2.0, 5.0 } + t * u + 1.5 * std::sin(t) * v;
    for (double& c : p)
    {
      c = write(c);
    }
    rounded.push_back(p);
    for (double& c : p)
    {
      c += off(random) * std::abs(c);
    }
    jittered.push_back(p);
  }
  return { rounded, jittered };
}

template <class Filter>
struct Family
{
  using type = Filter;
  const char* Name;
};

/// expect(Family<F>) for each automatic family's filter F, traced by name.
template <class Expect>
void ForEveryFamily(const Expect& expect)
{
  const auto run = [&](auto family) {
    SCOPED_TRACE(family.Name);
    expect(family);
  };
  run(Family<vtkGeneralizedCubicSplineFilter>{ "generalized cubic" });
  run(Family<VariableDegree>{ "variable degree" });
  run(Family<Quintic>{ "quintic" });
  run(Family<QQR>{ "qqr" });
}

/// The same step on every axis.
Steps Each(double step)
{
  return { step, step, step };
}

/// Poly data of points (x, y, z, x, ...) of a type, without cells.
vtkSmartPointer<vtkPolyData> PointsData(const std::vector<double>& values, int type)
{
  vtkNew<vtkPoints> points;
  points->SetDataType(type);
  for (size_t i = 0; i + 2 < values.size(); i += 3)
  {
    points->InsertNextPoint(values[i], values[i + 1], values[i + 2]);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  return data;
}

/// value as a text format writes it with `digits` significant digits
/// ("%.5e", ParaView's CSV export, has six) and a reader reads it back.
double WrittenWith(double value, int digits)
{
  char text[40];
  std::snprintf(text, sizeof(text), "%.*e", digits - 1, value);
  return std::strtod(text, nullptr);
}

/// The largest curvature of a run's output.
double LargestCurvature(const FilterRun& run)
{
  vtkDataArray* curvature = PointArray(run.Output, "Curvature");
  return curvature->GetRange()[1];
}

/// Filter's fixed and default modes on rounded points and on the same
/// values jittered off their digits (taken as exact).
struct RoundingRuns
{
  FilterRun Fixed, Automatic, ExactFixed, ExactAutomatic;
};

template <class Filter>
RoundingRuns RunRoundedAndExact(vtkPolyData* rounded, vtkPolyData* jittered)
{
  const auto fixedMode = [](Filter* f) { f->AutomaticOff(); };
  return { RunFilter<Filter>(rounded, fixedMode), RunFilter<Filter>(rounded),
    RunFilter<Filter>(jittered, fixedMode), RunFilter<Filter>(jittered) };
}

/// ShapeViolations of a run's first line.
double Violations(const FilterRun& run)
{
  return CellArray(run.Output, "ShapeViolations")->GetTuple1(0);
}

/// Filter's default mode on points whose turns and twists are within the
/// rounding of their decimals: the fixed curve, no criterion failed. The
/// same values off their decimals (jittered), taken as exact: the fixed
/// curve fails criteria and the default mode bends the curve to keep them.
template <class Filter>
void ExpectRoundingIsNoShape(vtkPolyData* rounded, vtkPolyData* jittered)
{
  const RoundingRuns runs = RunRoundedAndExact<Filter>(rounded, jittered);
  EXPECT_EQ(Violations(runs.Fixed), 0.0);
  EXPECT_EQ(Violations(runs.Automatic), 0.0);
  vtkDataArray* fixedCurvature = PointArray(runs.Fixed.Output, "Curvature");
  vtkDataArray* automaticCurvature = PointArray(runs.Automatic.Output, "Curvature");
  ASSERT_EQ(automaticCurvature->GetNumberOfTuples(), fixedCurvature->GetNumberOfTuples());
  for (vtkIdType i = 0; i < fixedCurvature->GetNumberOfTuples(); ++i)
  {
    ASSERT_NEAR(automaticCurvature->GetTuple1(i), fixedCurvature->GetTuple1(i), 1e-12) << i;
  }
  EXPECT_GE(Violations(runs.ExactFixed), 3.0);
  EXPECT_GT(LargestCurvature(runs.ExactAutomatic), 1.3 * LargestCurvature(runs.ExactFixed));
}
} // namespace

TEST(AutomaticShapeFilters, ATwistWithinTheDecimalsOfTheCoordinatesIsNoShape)
{
  // Two periods of a sine wave in a tilted plane, written with three
  // decimals as a PDB file's or a CSV export's coordinates are: their
  // rounding twists the points either way by up to 1e-3 over segments of
  // 0.2. Taken as exact, every family's fixed curve failed 4-9 torsion signs
  // and its default mode bent the curve to 1.4-3.9 times the fixed curve's
  // largest curvature for them.
  const auto [rounded, jittered] =
    WrittenSineWave(80, [](double c) { return std::round(1e3 * c) / 1e3; }, 2e-10);
  const auto decimals = PolylinesData({ rounded });
  const auto exact = PolylinesData({ jittered });
  ASSERT_EQ(StepsOf(decimals), Each(1e-3));
  ASSERT_EQ(StepsOf(exact), Each(0.0));
  ForEveryFamily([&](auto family) {
    ExpectRoundingIsNoShape<typename decltype(family)::type>(decimals, exact);
  });
  // In one input with the exact line, the rounded line keeps its own digits
  // (the input's steps would be the exact line's: none).
  const FilterRun mixed = RunFilter<vtkGeneralizedCubicSplineFilter>(
    PolylinesData({ rounded, jittered }),
    [](vtkGeneralizedCubicSplineFilter* f) { f->AutomaticOff(); });
  EXPECT_EQ(CellArray(mixed.Output, "ShapeViolations")->GetTuple1(0), 0.0);
  EXPECT_GE(CellArray(mixed.Output, "ShapeViolations")->GetTuple1(1), 3.0);
}

namespace
{
/// Filter's default mode on points whose turns are within the rounding of
/// their significant digits: no violation left, the fixed curve's largest
/// curvature kept; few for the fixed curve. The same values jittered off
/// their digits, taken as exact: more for the fixed curve, and the default
/// mode bends the curve to keep them.
template <class Filter>
void ExpectSignificantDigitsAreNoShape(vtkPolyData* rounded, vtkPolyData* jittered)
{
  const RoundingRuns runs = RunRoundedAndExact<Filter>(rounded, jittered);
  EXPECT_LE(4.0 * Violations(runs.Fixed), Violations(runs.ExactFixed));
  EXPECT_EQ(Violations(runs.Automatic), 0.0);
  EXPECT_LT(LargestCurvature(runs.Automatic), 1.05 * LargestCurvature(runs.Fixed));
  EXPECT_GT(LargestCurvature(runs.ExactAutomatic), 3.0 * LargestCurvature(runs.ExactFixed));
}
} // namespace

TEST(AutomaticShapeFilters, ATurnWithinTheSignificantDigitsOfTheCoordinatesIsNoShape)
{
  // The tilted sine wave, 400 points across x = 3..15 (segments of 0.045),
  // written with six significant digits as ParaView's CSV export writes them
  // ("%.5e"): a step of 1e-5 below x = 10, 1e-4 above. Taken as exact, the
  // fixed curves failed 25-29 criteria and the default modes bent the curve
  // to 5-650 times the fixed curve's largest curvature for them.
  const auto [rounded, jittered] = WrittenSineWave(400, [](double c) { return WrittenWith(c, 6); }, 1e-12);
  const auto digits = PolylinesData({ rounded });
  const auto exact = PolylinesData({ jittered });
  ASSERT_EQ(StepsOf(digits), (Steps{ 1e-4, 1e-5, 1e-5 }));
  ASSERT_EQ(StepsOf(exact), Each(0.0));
  ForEveryFamily([&](auto family) {
    ExpectSignificantDigitsAreNoShape<typename decltype(family)::type>(digits, exact);
  });
}

TEST(AutomaticShapeFilters, TheCoordinatesDecimalsAreTheirRounding)
{
  const auto withPoints = [](const std::vector<double>& values, int type) {
    return StepsOf(PointsData(values, type));
  };
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-250.0, 250.0);
  std::vector<double> values(300);
  for (double& value : values)
  {
    value = coordinate(random);
  }
  const auto roundedTo = [&](double step) {
    std::vector<double> rounded = values;
    for (double& value : rounded)
    {
      value = std::round(value / step) * step;
    }
    return rounded;
  };
  EXPECT_EQ(withPoints(values, VTK_DOUBLE), Each(0.0));
  EXPECT_EQ(withPoints(values, VTK_FLOAT), Each(0.0));
  for (const double step : { 1e-2, 1e-3, 1e-4, 1e-6, 1e-9 })
  {
    EXPECT_EQ(withPoints(roundedTo(step), VTK_DOUBLE), Each(step)) << step;
  }
  // A PDB file read as floats (vtkPDBReader): 12.345f is 12.34500027.
  EXPECT_EQ(withPoints(roundedTo(1e-3), VTK_FLOAT), Each(1e-3));
  EXPECT_EQ(withPoints(roundedTo(1e-2), VTK_FLOAT), Each(1e-2));
  // Below float's rounding at 250 (3e-5) a float's decimals are not told.
  EXPECT_EQ(withPoints(roundedTo(1e-5), VTK_FLOAT), Each(0.0));
  // Integers and tenths are designed points, taken as exact.
  EXPECT_EQ(withPoints(roundedTo(1.0), VTK_DOUBLE), Each(0.0));
  EXPECT_EQ(withPoints(roundedTo(0.1), VTK_DOUBLE), Each(0.0));
  std::vector<double> oneOff = roundedTo(1e-3);
  oneOff[150] += 1e-7; // an x
  EXPECT_EQ(withPoints(oneOff, VTK_DOUBLE), (Steps{ 1e-7, 1e-3, 1e-3 }));
  oneOff[150] += Pi * 1e-11; // no decimal step above double's rounding at 250
  EXPECT_EQ(withPoints(oneOff, VTK_DOUBLE), (Steps{ 0.0, 1e-3, 1e-3 }));
  std::vector<double> notFinite = roundedTo(1e-3);
  notFinite[7] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(withPoints(notFinite, VTK_DOUBLE), Each(0.0));
  EXPECT_EQ(withPoints({}, VTK_DOUBLE), Each(0.0));
  vtkNew<vtkPolyData> noPoints;
  EXPECT_EQ(StepsOf(noPoints), Each(0.0));
  // The aorta's float coordinates, computed: no decimals.
  EXPECT_EQ(StepsOf(ReadData("aorta-centerline.vtp")), Each(0.0));
}

TEST(AutomaticShapeFilters, TheCoordinatesSignificantDigitsAreTheirRounding)
{
  // Values across five decades, written with s significant digits: each
  // coordinate's step is that of its largest values (50..100: 10^(1 - s + 1)).
  std::mt19937 random(12);
  std::uniform_real_distribution<double> decade(-3.0, 2.0);
  std::uniform_int_distribution<int> sign(0, 1);
  std::vector<double> values(300);
  for (double& value : values)
  {
    value = (sign(random) ? 1.0 : -1.0) * std::pow(10.0, decade(random));
  }
  values[0] = 99.0; // the largest values have two digits before the point
  for (const int digits : { 4, 6, 9, 12 })
  {
    std::vector<double> written = values;
    for (double& value : written)
    {
      value = WrittenWith(value, digits);
    }
    EXPECT_EQ(StepsOf(PointsData(written, VTK_DOUBLE)), Each(std::pow(10.0, 2 - digits)))
      << digits;
  }
  // Three decimals of numbers across decades also fit as many significant
  // digits as the largest values have, which fewer values use.
  std::vector<double> decimals = values;
  for (double& value : decimals)
  {
    value = std::round(value * 1e3) / 1e3;
  }
  EXPECT_EQ(StepsOf(PointsData(decimals, VTK_DOUBLE)), Each(1e-3));
  // A designed column beside a measured one (the titanium data: integer
  // temperatures, values to three decimals) and a constant one (a z-level,
  // whatever its decimals): each its own.
  std::vector<double> columns;
  for (int i = 0; i < 49; ++i)
  {
    columns.insert(columns.end(), { 595.0 + 10 * i, std::round(1e3 * std::abs(values[i])) / 1e3, 12.345 });
  }
  EXPECT_EQ(StepsOf(PointsData(columns, VTK_DOUBLE)), (Steps{ 0.0, 1e-3, 0.0 }));
}

TEST(AutomaticShapeFilters, FloatsWrittenAsTextAreFloats)
{
  // A float file's points written with the 9 significant digits that keep
  // each float ("%.9g") and read back as doubles have the floats' rounding.
  std::mt19937 random(13);
  std::uniform_real_distribution<double> coordinate(-250.0, 250.0);
  std::vector<double> floats(300), doubles(300);
  for (size_t i = 0; i < floats.size(); ++i)
  {
    const double value = coordinate(random);
    floats[i] = WrittenWith(static_cast<float>(value), 9);
    doubles[i] = WrittenWith(value, 9);
  }
  const auto precisionOf = [](const std::vector<double>& values) {
    return shapesplines::coordinatePrecision(PointsData(values, VTK_DOUBLE));
  };
  EXPECT_EQ(precisionOf(floats), std::numeric_limits<float>::epsilon());
  // Doubles written so fall within half a 9th digit of a float one time in ten.
  EXPECT_EQ(precisionOf(doubles), std::numeric_limits<double>::epsilon());
  // Below a float's 9 digits, or one value that is no float's: doubles.
  std::vector<double> longer = floats, oneOff = floats;
  for (size_t i = 0; i < longer.size(); ++i)
  {
    longer[i] = WrittenWith(doubles[i], 12);
  }
  EXPECT_EQ(precisionOf(longer), std::numeric_limits<double>::epsilon());
  oneOff[100] = doubles[100];
  EXPECT_EQ(precisionOf(oneOff), std::numeric_limits<double>::epsilon());
  EXPECT_EQ(precisionOf({}), std::numeric_limits<double>::epsilon());
}

TEST(QQRSplineFilter, FrenetContinuityAndItsWarnings)
{
  const auto data = ReadData("helix.vtp");
  const FilterRun frenet = RunFilter<QQR>(data, [](QQR* f) {
    f->SetModeToApproximate();
    f->AutomaticOff();
    f->SetContinuity(QQR::C2_FC);
    f->SetFrenetOrder(2);
  });
  ExpectNoMessages(frenet);
  EXPECT_EQ(CellArray(frenet.Output, "MaxAlpha")->GetTuple1(0), 5.0); // l + 3
  const FilterRun interpolation = RunFilter<QQR>(data, [](QQR* f) { f->SetContinuity(QQR::C2_FC); });
  EXPECT_EQ(CountMessages(interpolation.Warnings, { "C2_FC", "using C2" }), 1)
    << Joined(interpolation.Warnings);
  const FilterRun low = RunFilter<QQR>(data, [](QQR* f) {
    f->AutomaticOff();
    f->SetAlpha(2.5);
  });
  EXPECT_EQ(CountMessages(low.Warnings, { "at or below 3" }), 1) << Joined(low.Warnings);
}

TEST(QQRSplineFilter, LocalBiasPerPointFromAnInputArray)
{
  // z = 0.5 at every point but point 8, whose -1 falls back to the paper's
  // z; the local interpolation, where a z reaches four spans only.
  const auto data = DeepCopy(ReadData("akima.vtp"));
  vtkNew<vtkDoubleArray> given;
  given->SetName("bias");
  given->SetNumberOfTuples(data->GetNumberOfPoints());
  given->Fill(0.5);
  given->SetValue(8, -1.0);
  data->GetPointData()->AddArray(given);
  const FilterRun half = RunFilter<QQR>(data, [](QQR* f) {
    f->AutomaticOff();
    f->SetModeToLocalInterpolation();
    f->SetZArrayName("bias");
  });
  const FilterRun custom = RunFilter<QQR>(data, [](QQR* f) {
    f->AutomaticOff();
    f->SetModeToLocalInterpolation();
    f->SetLocalParameters(QQR::CUSTOM);
    f->SetZ(0.5);
  });
  ExpectNoMessages(half);
  // 0.5 everywhere but point 8: the same curve as Custom z = 0.5 away from
  // the spans point 8's z reaches, another one near it.
  const auto a = LinesOf(half.Output)[0];
  const auto b = LinesOf(custom.Output)[0];
  ASSERT_EQ(a.size(), b.size());
  double near = 0.0, far = 0.0;
  vtkDataArray* span = PointArray(half.Output, "SpanIndex");
  for (size_t i = 0; i < a.size(); ++i)
  {
    const double d = Norm(PointOf(half.Output, a[i]) - PointOf(custom.Output, b[i]));
    const int j = static_cast<int>(span->GetTuple1(a[i]));
    (j >= 5 && j <= 9 ? near : far) = std::max(j >= 5 && j <= 9 ? near : far, d);
  }
  Measure("Akima, z array with one fallback: largest difference to z = 0.5 near point 8", near);
  EXPECT_EQ(far, 0.0);
  EXPECT_GT(near, 1e-6);
}

TEST(Messages, SettingsTheCurveCannotTakeAreNamedInTheProjectsWords)
{
  const auto data = ReadData("helix.vtp");
  const vtkIdType count = data->GetNumberOfPoints();
  // A Degree Array of 1e300: capped at degree 1000, not refused as "below 5".
  vtkNew<vtkDoubleArray> huge;
  huge->SetName("Huge");
  huge->SetNumberOfTuples(count);
  huge->Fill(1e300);
  data->GetPointData()->AddArray(huge);
  const FilterRun capped = RunFilter<VariableDegree>(data, [](VariableDegree* f) {
    f->AutomaticOff();
    f->SetDegreeArrayName("Huge");
  });
  EXPECT_TRUE(capped.Errors.empty()) << Joined(capped.Errors);
  EXPECT_EQ(CellArray(capped.Output, "MaxDegree")->GetTuple1(0), 1000.0);
  // A string array named where numbers are read.
  vtkNew<vtkStringArray> labels;
  labels->SetName("Labels");
  labels->SetNumberOfValues(count);
  data->GetPointData()->AddArray(labels);
  const FilterRun named =
    RunFilter<VariableDegree>(data, [](VariableDegree* f) { f->SetDegreeArrayName("Labels"); });
  EXPECT_EQ(CountMessages(named.Warnings, { "'Labels' is not numeric" }), 1) << Joined(named.Warnings);
}
