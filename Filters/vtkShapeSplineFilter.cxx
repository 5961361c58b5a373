#include "vtkShapeSplineFilter.h"

#include "ArrayNames.h"
#include "FitPolyline.h"
#include "LineCells.h"
#include "OutputArrays.h"
#include "SparseSolve.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMP.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <chrono>
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <future>
#include <initializer_list>
#include <iterator>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

namespace names = shapesplines::names;

namespace
{
using shapesplines::Vec3;

/// One input line and what became of it.
struct LineWork
{
  vtkIdType CellId = 0; ///< the input cell, or the connected line's index
  std::string Name;     ///< how messages name it: "cell 3", "line id 7"
  std::vector<vtkIdType> PointIds;
  shapesplines::FittedPolyline Fit;
  double Length = 0.0; ///< of the sampled curve
  double Chord = 0.0;  ///< distance between its ends (0 when closed)
  double LargestCurvature = 0.0; ///< of the samples
  std::string Error;
};

/// How many points of an interpolated line run straight back
/// (DiscreteShape::Reversal): every smooth curve through them has a cusp.
std::ptrdiff_t Reversals(const LineWork& line)
{
  const shapesplines::FittedPolyline& fit = line.Fit;
  const std::vector<char>& reversal = fit.Shape.Reversal;
  return fit.Spline && fit.interpolates() ? std::count(reversal.begin(), reversal.end(), 1) : 0;
}

/// " Line (name): what." for the first few of the lines given, then how many more.
template <class Describe>
std::string DescribeLines(
  const std::vector<LineWork>& lines, const std::vector<size_t>& which, const Describe& describe)
{
  constexpr size_t DescribedLines = 3;
  std::ostringstream text;
  for (size_t j = 0; j < which.size() && j < DescribedLines; ++j)
  {
    const LineWork& line = lines[which[j]];
    text << " Line (" << line.Name << "): " << describe(line) << ".";
  }
  if (which.size() > DescribedLines)
  {
    text << " And " << which.size() - DescribedLines << " more line(s).";
  }
  return text.str();
}

vtkSmartPointer<vtkDoubleArray> NewArray(const char* name, int components, vtkIdType tuples)
{
  return shapesplines::newArray<vtkDoubleArray>(name, components, tuples);
}

/// Whether a setting's array name names an array: empty and "None" (what
/// ParaView's array list sends for no array) do not.
bool NamesAnArray(const char* name)
{
  return name && *name && std::string(name) != "None";
}

/// The input's line cells, named by their id.
std::vector<LineWork> CellLines(vtkPolyData* input)
{
  std::vector<LineWork> lines;
  for (auto& cell : shapesplines::lineCells(input))
  {
    LineWork line;
    line.CellId = cell.CellId;
    line.Name = "cell " + std::to_string(cell.CellId);
    line.PointIds = std::move(cell.PointIds);
    line.Error = std::move(cell.Error);
    lines.push_back(std::move(line));
  }
  return lines;
}

/// The point array that says which line each point belongs to: the one named,
/// or else the first whose name says line ids (line_id, track, ...); null for
/// one line of all the points.
vtkDataArray* LineIdArray(vtkPointData* pointData, const char* name)
{
  if (NamesAnArray(name))
  {
    return pointData->GetArray(name);
  }
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pointData->GetArray(a);
    if (array && array->GetName() && shapesplines::isLineIdName(array->GetName()))
    {
      return array;
    }
  }
  return nullptr;
}

/**
 * Field data TorsionColorRange: -m, m with m the 95th percentile of |torsion|,
 * a colour range centred on zero that a few noise spikes do not squash
 * (ParaView's client reads it; the data's own range is the default).
 */
vtkSmartPointer<vtkDoubleArray> TorsionColorRange(vtkDoubleArray* torsion)
{
  const double* values = torsion->GetPointer(0);
  const double typical =
    shapesplines::typicalMagnitude(values, values + torsion->GetNumberOfTuples());
  auto range = NewArray(names::TorsionColorRange, 1, 2);
  range->SetValue(0, -typical);
  range->SetValue(1, typical);
  return range;
}

/// The SMP configuration a run uses (see NumberOfThreads).
vtkSMPTools::Config ThreadsFor(int numberOfThreads)
{
  std::string backend = vtkSMPTools::GetBackend();
  if (numberOfThreads == 1)
  {
    backend = "Sequential";
  }
#if VTK_SMP_ENABLE_STDTHREAD
  else if (backend == "Sequential" && !std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    backend = "STDThread"; // the backend nobody chose: one thread would waste the cores
  }
#endif
  return vtkSMPTools::Config{ numberOfThreads, backend, false };
}

/// Lines of the input's points in order (Connect Points), named by their id.
std::vector<LineWork> ConnectedLines(vtkPolyData* input, vtkDataArray* lineIds)
{
  std::vector<LineWork> lines;
  for (auto& cell : shapesplines::connectedPoints(input->GetNumberOfPoints(), lineIds))
  {
    LineWork line;
    line.CellId = cell.CellId;
    std::ostringstream name;
    if (lineIds)
    {
      name << lineIds->GetName() << " " << lineIds->GetComponent(cell.PointIds[0], 0);
    }
    else
    {
      name << "points 0-" << cell.PointIds.size() - 1;
    }
    line.Name = name.str();
    line.PointIds = std::move(cell.PointIds);
    lines.push_back(std::move(line));
  }
  return lines;
}

/**
 * The input point arrays on the samples: floating-point arrays interpolated
 * linearly along each span; integer and other arrays (ids, labels, flags) taken
 * from the nearer data point, since a value between two ids means nothing.
 */
class PointArrayTransfer
{
public:
  /// input: the readable arrays (ReadableArrays), a tuple per input point each.
  PointArrayTransfer(vtkPointData* input, vtkIdType size)
  {
    for (int a = 0; a < input->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* source = input->GetAbstractArray(a);
      auto target = vtk::TakeSmartPointer(source->NewInstance());
      target->SetName(source->GetName());
      target->SetNumberOfComponents(source->GetNumberOfComponents());
      target->SetNumberOfTuples(size);
      const int type = source->GetDataType();
      this->Arrays.push_back({ source, target, type == VTK_FLOAT || type == VTK_DOUBLE });
    }
  }

  /// Sample `to` lies at fraction t in [0, 1] of the span between data points a and b.
  void Interpolate(vtkIdType to, vtkIdType a, vtkIdType b, double t)
  {
    for (const Transfer& x : this->Arrays)
    {
      if (x.Linear)
      {
        x.Target->InterpolateTuple(to, a, x.Source, b, x.Source, t);
      }
      else
      {
        x.Target->SetTuple(to, t < 0.5 ? a : b, x.Source);
      }
    }
  }

  void AddTo(vtkPointData* output) const
  {
    for (const Transfer& x : this->Arrays)
    {
      output->AddArray(x.Target);
    }
  }

private:
  struct Transfer
  {
    vtkAbstractArray* Source;
    vtkSmartPointer<vtkAbstractArray> Target;
    bool Linear;
  };
  std::vector<Transfer> Arrays;
};

/**
 * The data points around sample s and its fraction of the way between them:
 * its span for an interpolation, whose knots are the data's; for an
 * approximation, whose knots are its own, found from its parameter.
 */
std::pair<int, double> DataInterval(
  const shapesplines::FittedPolyline& fit, const shapesplines::CurveSamples& samples, int s)
{
  if (fit.interpolates())
  {
    return { samples.Span[s], samples.SpanFraction[s] };
  }
  const std::vector<double>& knots = fit.Knots;
  const double t = samples.Parameter[s] / fit.ParameterScale;
  const auto after = std::upper_bound(knots.begin() + 1, knots.end() - 1, t);
  const int interval = static_cast<int>(after - knots.begin()) - 1;
  const double width = knots[interval + 1] - knots[interval];
  // Corrected parameters can tie (points projecting onto one place, the
  // curve's end among them): no width to interpolate over, the nearer point.
  if (!(width > 0.0))
  {
    return { interval, t < knots[interval] ? 0.0 : 1.0 };
  }
  return { interval, std::clamp((t - knots[interval]) / width, 0.0, 1.0) };
}

/**
 * Progress by lines done, weighted by their points, and inside a long line by
 * the math core's ProgressCallback. Reported by publish() on the thread that
 * runs RequestData only (VTK's events and ParaView's progress bar are not
 * thread-safe), once per 1% of the phase [From, To] and at least once per
 * Heartbeat (the same value again), never backwards: as the lines are done
 * with the Sequential backend (they run on this thread), every 50 ms with a
 * threaded one (WhilePublishing).
 */
class LineProgress
{
public:
  LineProgress(vtkAlgorithm* algorithm, vtkIdType totalPoints, double from, double to)
    : Algorithm(algorithm)
    , From(from)
    , To(to)
    , Total(totalPoints)
  {
  }

  void lineDone(const LineWork& line)
  {
    this->Done += static_cast<vtkIdType>(line.PointIds.size());
    if (this->Inline)
    {
      this->publish();
    }
  }

  /// Inside a line not yet done: a fraction of its points. False once aborted.
  bool within(const LineWork& line, double fraction)
  {
    this->Partial = this->Done + fraction * static_cast<double>(line.PointIds.size());
    if (this->Inline)
    {
      this->publish();
    }
    return !this->Algorithm->GetAbortExecute();
  }

  void publish()
  {
    const double done = std::max(static_cast<double>(this->Done), this->Partial.load());
    const double fraction = this->Total > 0 ? std::min(done / this->Total, 1.0) : 1.0;
    const auto now = std::chrono::steady_clock::now();
    // A long line's automatic search can hold its fraction for seconds (a
    // noisy 1e5-point line: 7-10 s without an event); ParaView's progress bar
    // and its Cancel act from the events, so they keep coming.
    const bool moved = fraction - this->Reported >= 0.01;
    if ((moved || now - this->LastEvent >= Heartbeat) && !this->Algorithm->GetAbortExecute())
    {
      this->Reported = std::max(this->Reported, fraction);
      this->LastEvent = now;
      this->Algorithm->UpdateProgress(this->From + (this->To - this->From) * this->Reported);
    }
  }

private:
  static constexpr std::chrono::milliseconds Heartbeat{ 250 };
  vtkAlgorithm* Algorithm;
  double From, To;
  vtkIdType Total;
  std::atomic<vtkIdType> Done{ 0 };
  std::atomic<double> Partial{ 0.0 };
  double Reported = 0.0; ///< only read and written by publish(), as LastEvent
  std::chrono::steady_clock::time_point LastEvent = std::chrono::steady_clock::now();

public:
  /// The Sequential backend runs the lines on this thread: it publishes as it goes.
  const bool Inline = std::string(vtkSMPTools::GetBackend()) == "Sequential";
};

/**
 * Runs work (a vtkSMPTools::For over the lines) on a thread of its own while
 * this thread publishes its progress every 50 ms: with the threaded backend
 * the caller would otherwise wait without a word (and ParaView's Cancel,
 * which acts from a progress event, could not stop it).
 */
template <typename Work>
void WhilePublishing(LineProgress& progress, Work&& work)
{
  if (progress.Inline)
  {
    work();
    return;
  }
  auto running = std::async(std::launch::async, std::forward<Work>(work));
  while (running.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready)
  {
    progress.publish();
  }
  running.get(); // rethrows what the work threw
  progress.publish();
}

template <typename Array>
vtkSmartPointer<Array> Renamed(Array* source, const char* name)
{
  auto copy = vtkSmartPointer<Array>::New();
  copy->ShallowCopy(source);
  copy->SetName(name);
  return copy;
}

/// Where an audit fails, criterion by criterion: "torsion sign on span at
/// spans 3, 7, ...; convexity at knot 5" (at most a few places each).
std::string DescribeFailures(const shapesplines::ShapeAudit& audit)
{
  constexpr int ShownPlaces = 4;
  std::ostringstream text;
  for (size_t k = 0; k < audit.Where.size();)
  {
    const auto criterion = audit.Where[k].Criterion;
    size_t end = k;
    while (end < audit.Where.size() && audit.Where[end].Criterion == criterion)
    {
      ++end;
    }
    // "convexity at knot" and "torsion sign at knot" already say where.
    const bool namedAtKnot = criterion == shapesplines::ShapeCriterion::ConvexityAtKnot ||
      criterion == shapesplines::ShapeCriterion::TorsionSignAtKnot;
    const char* place = namedAtKnot ? ""
      : criterion == shapesplines::ShapeCriterion::Collinearity ? " at knot"
                                                                 : " at span";
    text << (k > 0 ? "; " : "") << shapesplines::shapeCriterionName(criterion) << place
         << (end - k > 1 ? "s " : " ");
    for (size_t j = k; j < end && j < k + ShownPlaces; ++j)
    {
      text << (j > k ? ", " : "") << audit.Where[j].Where;
    }
    text << (end - k > ShownPlaces ? ", ..." : "");
    k = end;
  }
  // Straying spans count as violations too; a line failing only that way
  // would otherwise be named with nothing after it.
  if (audit.StrayingSpans > 0)
  {
    text << (audit.Where.empty() ? "" : "; ") << "straying from its data at "
         << (audit.StrayingSpans > 1 ? std::to_string(audit.StrayingSpans) + " spans, the farthest " : "")
         << "span " << audit.DeviationSpan;
  }
  return text.str();
}

vtkIdType PointsOnLines(const std::vector<LineWork>& lines)
{
  vtkIdType points = 0;
  for (const LineWork& line : lines)
  {
    points += static_cast<vtkIdType>(line.PointIds.size());
  }
  return points;
}

/// The lines of one run, gathered serially.
struct InputLines
{
  std::vector<LineWork> Lines;
  bool Connected = false;          ///< the input's points in order (Connect Points), no cells
  vtkDataArray* LineIds = nullptr; ///< which connected line each point is on, if any
};

/**
 * The input's line cells, or with ConnectPoints its points in order (line ids
 * from pointData, the input's readable arrays). None (reported) when the run
 * ends there with an empty output.
 */
std::optional<InputLines> GatherInputLines(vtkAlgorithm* self, vtkPolyData* input,
  vtkPointData* pointData, bool connectPoints, const char* lineIdArrayName)
{
  // Points without cells, or with vertices only (a table's rows), become lines
  // in point order when ConnectPoints is on; polygons' points do not.
  const bool onlyPoints = input->GetNumberOfCells() == input->GetNumberOfVerts();
  InputLines gathered;
  gathered.Connected = onlyPoints && connectPoints;
  if (input->GetNumberOfPoints() == 0 || (input->GetNumberOfLines() == 0 && !gathered.Connected))
  {
    vtkWarningWithObjectMacro(self, "Input has no lines: the output is empty."
      << (input->GetNumberOfPoints() > 0 && onlyPoints
             ? " Connect Points makes lines of its points in order."
             : ""));
    return std::nullopt;
  }
  if (gathered.Connected)
  {
    gathered.LineIds = LineIdArray(pointData, lineIdArrayName);
    if (!gathered.LineIds && NamesAnArray(lineIdArrayName))
    {
      vtkErrorWithObjectMacro(self, "No numeric point array named '"
          << lineIdArrayName << "' with one tuple per point for the line ids: nothing fitted.");
      return std::nullopt;
    }
  }
  const vtkIdType otherCells = input->GetNumberOfCells() - input->GetNumberOfLines();
  if (otherCells > 0 && !gathered.Connected)
  {
    vtkWarningWithObjectMacro(
      self, << otherCells << " non-line cells (vertices, polygons, strips) ignored.");
  }
  if (!gathered.Connected)
  {
    gathered.Lines = CellLines(input);
    return gathered;
  }
  gathered.Lines = ConnectedLines(input, gathered.LineIds);
  const vtkIdType onLines = PointsOnLines(gathered.Lines);
  if (onLines < input->GetNumberOfPoints())
  {
    vtkWarningWithObjectMacro(self, << input->GetNumberOfPoints() - onLines
                                    << " point(s) with a NaN or infinite "
                                    << gathered.LineIds->GetName()
                                    << " belong to no line: ignored.");
  }
  return gathered;
}

/// The point array of this name the family reads per point, or null; a
/// warning when the name names no numeric array.
vtkDataArray* PointValuesArray(vtkAlgorithm* self, vtkPointData* pointData, const char* name)
{
  if (!name)
  {
    return nullptr;
  }
  vtkDataArray* values = pointData->GetArray(name);
  if (!values && pointData->GetAbstractArray(name))
  {
    vtkWarningWithObjectMacro(self, "The point array '" << name << "' is not numeric: ignored.");
  }
  else if (!values)
  {
    vtkWarningWithObjectMacro(self, "No point array named '"
        << name << "' with one tuple per point in the input: ignored.");
  }
  return values;
}

/**
 * The input's point and cell arrays the filter reads: shallow copies without
 * those lacking a tuple per point (cell), a damaged file's, which a warning
 * names.
 */
struct ReadableArrays
{
  ReadableArrays(vtkAlgorithm* self, vtkPolyData* input)
  {
    this->Points->ShallowCopy(input->GetPointData());
    this->Cells->ShallowCopy(input->GetCellData());
    const std::string points =
      shapesplines::removeMisfitArrays(this->Points, input->GetNumberOfPoints());
    const std::string cells =
      shapesplines::removeMisfitArrays(this->Cells, input->GetNumberOfCells());
    if (!points.empty())
    {
      vtkWarningWithObjectMacro(self, "Point arrays without one tuple per point ("
          << input->GetNumberOfPoints() << "), as a damaged file holds, are left out: " << points
          << ".");
    }
    if (!cells.empty())
    {
      vtkWarningWithObjectMacro(self, "Cell arrays without one tuple per cell ("
          << input->GetNumberOfCells() << ") are left out: " << cells << ".");
    }
  }

  vtkNew<vtkPointData> Points;
  vtkNew<vtkCellData> Cells;
};

/// Fits the lines in parallel (curve, audit, sampling plan); a line that
/// fails keeps why in its Error. Progress from 0 to 0.8.
void FitInParallel(vtkAlgorithm* self, std::vector<LineWork>& lines, vtkPoints* inPoints,
  vtkDataArray* pointValues, const shapesplines::FitOptions& options,
  const shapesplines::CurveBuilder& build)
{
  LineProgress fitting(self, PointsOnLines(lines), 0.0, 0.8);
  const auto fitRange = [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType k = begin; k < end && !self->GetAbortExecute(); ++k)
    {
      LineWork& line = lines[k];
      if (!line.Error.empty())
      {
        continue; // a damaged cell, reported by ReportFits
      }
      std::vector<Vec3> points(line.PointIds.size());
      for (size_t i = 0; i < points.size(); ++i)
      {
        inPoints->GetPoint(line.PointIds[i], points[i].data());
      }
      std::vector<double> values;
      for (size_t i = 0; pointValues && i < points.size(); ++i)
      {
        values.push_back(pointValues->GetComponent(line.PointIds[i], 0));
      }
      shapesplines::FitOptions lineOptions = options;
      lineOptions.Progress = [&](double fraction) { return fitting.within(line, fraction); };
      try
      {
        line.Fit = shapesplines::fitPolyline(points, lineOptions, build, values);
      }
      catch (const std::exception& e)
      {
        line.Error = e.what();
      }
      fitting.lineDone(line);
    }
  };
  WhilePublishing(
    fitting, [&] { vtkSMPTools::For(0, static_cast<vtkIdType>(lines.size()), fitRange); });
}

/// The warnings about one fitted line, in the order a user reads them.
void ReportFit(vtkAlgorithm* self, const LineWork& line, bool approximates)
{
  const auto& fit = line.Fit;
  if (!fit.Spline)
  {
    vtkWarningWithObjectMacro(self, "Line (" << line.Name
                                    << ") has fewer than two distinct points: passed through.");
  }
  else if (fit.Data.Points.size() == 2)
  {
    vtkWarningWithObjectMacro(self, "Line (" << line.Name
                                    << ") has two distinct points: output is a straight segment.");
  }
  if (approximates && fit.Spline && fit.interpolates())
  {
    vtkWarningWithObjectMacro(self, "Line (" << line.Name
                                    << ") interpolated, not approximated: too few points for an approximation.");
  }
  if (fit.Spline && fit.StarvedSpan)
  {
    vtkWarningWithObjectMacro(self, "Line (" << line.Name
                                    << "): its knots leave a span with too few points to decide it "
                                    << "(unevenly spaced points): the curve there follows its "
                                    << "neighbours, the points' parameters are not corrected and "
                                    << "NoiseLevel is not estimated (0). Fewer knots, or Number Of "
                                    << "Knots 0 (chosen per line), avoid it.");
  }
  if (fit.Spline && fit.Spline->conditionEstimate() > shapesplines::UntrustedCondition)
  {
    vtkWarningWithObjectMacro(self, "Line (" << line.Name
                                    << "): the spline's linear system is ill-conditioned"
                                    << " (condition estimate " << fit.Spline->conditionEstimate()
                                    << "): its curvature and torsion may be inaccurate. Very uneven"
                                    << " point spacing causes this; try Centripetal parameterization"
                                    << " or resample the line.");
  }
  if (fit.Spline && fit.Audit.StrayingSpans > 0 && Reversals(line) == 0)
  {
    vtkWarningWithObjectMacro(self, "Line (" << line.Name << "): the curve strays "
                                    << fit.Audit.PolygonDeviation << " local segment lengths from "
                                    << (fit.interpolates() ? "its data" : "its reference polygon")
                                    << " (span " << fit.Audit.DeviationSpan << ", "
                                    << fit.Audit.StrayingSpans
                                    << " span(s) beyond 0.5): not shape-preserving. Very uneven "
                                    << "spacing does this; try Centripetal parameterization or "
                                    << "the generalized cubic.");
  }
  if (fit.Plan.LengthIncreased)
  {
    vtkWarningWithObjectMacro(self, "Line (" << line.Name
                                    << "): sample spacing widened beyond SampleLength: a line "
                                    << "takes at most 1e7 samples, and no more than its polyline "
                                    << "100 times over would (a longer curve has left its data).");
  }
}

/// One message a run for the lines whose curves are the best met within the
/// automatic mode's bounds (no cusp, no runaway curvature).
void ReportShapeViolations(vtkAlgorithm* self, const std::vector<LineWork>& lines,
  const std::vector<size_t>& violatingLines, bool gathersBends)
{
  const std::string lineText = DescribeLines(lines, violatingLines,
    [](const LineWork& line) { return DescribeFailures(line.Fit.Audit); });
  // Families that gather each bend at its knot leave fewer (densely sampled
  // noisy helices: 0 where the quintic keeps 0.7-2.2%, qqr 1.5-19%;
  // staircases: 0 where the quintic keeps two a corner).
  const bool interpolated = std::all_of(violatingLines.begin(), violatingLines.end(),
    [&](size_t k) { return lines[k].Fit.interpolates(); });
  const std::string advice = interpolated && !gathersBends
    ? " To interpolate such points, the Generalized Cubic Spline and the Variable Degree Spline "
      "keep their shape more often."
    : "";
  vtkWarningWithObjectMacro(self, << violatingLines.size() << " line(s) keep shape violations "
                                  << "the automatic mode could not remove without a cusp or a "
                                  << "curvature beyond its bounds; each keeps the best curve found "
                                  << "(cell array ShapeViolations). Knots and spans count the "
                                  << "line's distinct points (approximations: the vertices of the "
                                  << "reference polygon) from 0." << advice << lineText);
}

/// One message a run for the interpolated lines that run straight back on
/// themselves, where every smooth curve through the points has a cusp and
/// leaves them (the curvature spike's and the straying span's warnings, which
/// would blame the family or the spacing, are not given for those lines).
void ReportReversals(
  vtkAlgorithm* self, const std::vector<LineWork>& lines, const std::vector<size_t>& kept)
{
  std::vector<size_t> reversing;
  std::copy_if(kept.begin(), kept.end(), std::back_inserter(reversing),
    [&](size_t k) { return Reversals(lines[k]) > 0; });
  if (reversing.empty())
  {
    return;
  }
  const std::string lineText = DescribeLines(lines, reversing, [](const LineWork& line) {
    const shapesplines::FittedPolyline& fit = line.Fit;
    const auto first = std::find(fit.Shape.Reversal.begin(), fit.Shape.Reversal.end(), 1);
    return std::to_string(Reversals(line)) + " point(s), the first its point " +
      std::to_string(fit.Data.SourceIndex[first - fit.Shape.Reversal.begin()]);
  });
  vtkWarningWithObjectMacro(self, << reversing.size() << " line(s) run straight back on "
                                  << "themselves: a smooth curve through a point where the line "
                                  << "turns by 180 degrees stops there and turns (a cusp, "
                                  << "curvature without bound), in every family, and may stray "
                                  << "from the points there. Remove the back-and-forth points (a "
                                  << "streamline oscillating about a critical point: fewer Maximum "
                                  << "Steps, or a larger Terminal Speed), split the line there, or "
                                  << "approximate it (Mode Approximate of the tension quintic or "
                                  << "the variable degree spline)." << lineText);
}

/**
 * The messages about the fits, serially (VTK's messages are not
 * thread-safe): an error for each line that failed, the warnings about each
 * other line, then one about the noisy lines, one about the lines that run
 * back on themselves and one about the violations left. Returns the lines
 * that go to the output, in input order.
 */
std::vector<size_t> ReportFits(vtkAlgorithm* self, const std::vector<LineWork>& lines,
  bool approximates, bool adjustsShape, bool gathersBends)
{
  std::vector<size_t> kept;
  int noisyLines = 0;
  std::vector<size_t> violatingLines;
  for (size_t k = 0; k < lines.size(); ++k)
  {
    const LineWork& line = lines[k];
    if (!line.Error.empty())
    {
      vtkErrorWithObjectMacro(self, "Line (" << line.Name << ") skipped: " << line.Error << ".");
      continue;
    }
    ReportFit(self, line, approximates);
    noisyLines += line.Fit.LooksNoisy ? 1 : 0;
    if (adjustsShape && line.Fit.Spline && !line.Fit.Audit.preserving())
    {
      violatingLines.push_back(k);
    }
    kept.push_back(k);
  }
  if (noisyLines > 0)
  {
    vtkWarningWithObjectMacro(self, << noisyLines << " line(s) interpolated through points that "
                                    << "look noisy, or turn within a few points (a least squares "
                                    << "keeps far fewer knots than points): measured points' "
                                    << "curvature and torsion then follow the noise, and Mode "
                                    << "Approximate gives the curve's own.");
  }
  ReportReversals(self, lines, kept);
  if (!violatingLines.empty())
  {
    ReportShapeViolations(self, lines, violatingLines, gathersBends);
  }
  return kept;
}

/// Where each kept line's samples start in the output, then their total.
std::vector<vtkIdType> FirstSamples(
  const std::vector<LineWork>& lines, const std::vector<size_t>& kept)
{
  std::vector<vtkIdType> firstSample(1, 0);
  for (const size_t k : kept)
  {
    const LineWork& line = lines[k];
    const size_t count = line.Fit.Spline ? line.Fit.Plan.size() : line.PointIds.size();
    firstSample.push_back(firstSample.back() + static_cast<vtkIdType>(count));
  }
  return firstSample;
}

/// The families' shape parameters (the same names on every line of a family;
/// lines too short for the family's curve have none).
std::vector<shapesplines::SpanParameter> ShapeParameterNames(
  const std::vector<LineWork>& lines, const std::vector<size_t>& kept)
{
  std::vector<shapesplines::SpanParameter> parameterNames;
  for (const size_t k : kept)
  {
    if (lines[k].Fit.Spline && parameterNames.empty())
    {
      parameterNames = lines[k].Fit.Spline->spanParameters();
    }
  }
  return parameterNames;
}

/**
 * The output's samples: their points, point arrays and line cells, each kept
 * line's from its first sample on. Lines are written in parallel, each into
 * its own tuples.
 */
struct SampleOutput
{
  SampleOutput(vtkPointData* input, const std::vector<LineWork>& lines,
    const std::vector<size_t>& kept, std::vector<vtkIdType> firstSample,
    const std::vector<shapesplines::SpanParameter>& parameterNames)
    : FirstSample(std::move(firstSample))
    , Size(FirstSample.back())
    , Carried(input, Size)
    , Curvature(NewArray(names::Curvature, 1, Size))
    , Torsion(NewArray(names::Torsion, 1, Size))
    , Tangent(NewArray(names::Tangent, 3, Size))
    , Normal(NewArray(names::Normal, 3, Size))
    , Binormal(NewArray(names::Binormal, 3, Size))
    , Parameter(NewArray(names::Parameter, 1, Size))
    , ArcLength(NewArray(names::ArcLength, 1, Size))
    , SpanIndex(shapesplines::newArray<vtkIntArray>(names::SpanIndex, 1, Size))
  {
    this->Points->SetDataTypeToDouble();
    this->Points->SetNumberOfPoints(this->Size);
    this->Xyz = vtkDoubleArray::SafeDownCast(this->Points->GetData())->GetPointer(0);
    for (const auto& p : parameterNames)
    {
      this->ShapeParameters.push_back(NewArray(p.Name.c_str(), 1, this->Size));
    }
    this->AllocateCells(lines, kept);
  }

  /// The connectivity of the c-th kept line's cell.
  vtkIdType* CellOf(vtkIdType c)
  {
    return this->Connectivity->GetPointer(this->Offsets->GetValue(c));
  }

  /// Sets the output's points, lines, point arrays and TorsionColorRange.
  void AddTo(vtkPolyData* output, bool vmtkArrayNames) const
  {
    vtkNew<vtkCellArray> outLines;
    outLines->SetData(this->Offsets, this->Connectivity);
    output->SetPoints(this->Points);
    output->SetLines(outLines);
    vtkPointData* outPD = output->GetPointData();
    // Input arrays first: ours replace any of the same name.
    this->Carried.AddTo(outPD);
    shapesplines::addArrays(outPD, { this->Curvature, this->Torsion, this->Tangent, this->Normal,
                                     this->Binormal, this->Parameter, this->ArcLength,
                                     this->SpanIndex });
    for (const auto& a : this->ShapeParameters)
    {
      outPD->AddArray(a);
    }
    outPD->SetActiveScalars(names::Torsion);
    output->GetFieldData()->AddArray(TorsionColorRange(this->Torsion));
    if (vmtkArrayNames)
    {
      outPD->AddArray(Renamed(this->Tangent.Get(), "FrenetTangent"));
      outPD->AddArray(Renamed(this->Normal.Get(), "FrenetNormal"));
      outPD->AddArray(Renamed(this->Binormal.Get(), "FrenetBinormal"));
    }
  }

  std::vector<vtkIdType> FirstSample; ///< of each kept line, then the total
  vtkIdType Size;
  PointArrayTransfer Carried;
  vtkNew<vtkPoints> Points;
  double* Xyz = nullptr; ///< the points' coordinates
  vtkSmartPointer<vtkDoubleArray> Curvature, Torsion, Tangent, Normal, Binormal, Parameter,
    ArcLength;
  vtkSmartPointer<vtkIntArray> SpanIndex;
  std::vector<vtkSmartPointer<vtkDoubleArray>> ShapeParameters; ///< 0 where a line has none
  vtkNew<vtkIdTypeArray> Offsets;
  vtkNew<vtkIdTypeArray> Connectivity;

private:
  void AllocateCells(const std::vector<LineWork>& lines, const std::vector<size_t>& kept)
  {
    // Closed lines repeat their first sample id at the end of their cell.
    const auto lineCount = static_cast<vtkIdType>(kept.size());
    this->Offsets->SetNumberOfTuples(lineCount + 1);
    this->Offsets->SetValue(0, 0);
    for (vtkIdType c = 0; c < lineCount; ++c)
    {
      const auto& fit = lines[kept[c]].Fit;
      const vtkIdType closing = fit.Spline && fit.Data.Closed ? 1 : 0;
      this->Offsets->SetValue(c + 1,
        this->Offsets->GetValue(c) + this->FirstSample[c + 1] - this->FirstSample[c] + closing);
    }
    this->Connectivity->SetNumberOfTuples(this->Offsets->GetValue(lineCount));
  }
};

/// A line without a curve, passed through unchanged with a zero frame.
void WritePassedThrough(
  const LineWork& line, vtkPoints* inPoints, vtkIdType first, vtkIdType* cell, SampleOutput& out)
{
  vtkIdType next = first;
  for (const vtkIdType id : line.PointIds)
  {
    inPoints->GetPoint(id, out.Xyz + 3 * next);
    out.Carried.Interpolate(next, id, id, 0.0);
    out.Curvature->SetValue(next, 0.0);
    out.Torsion->SetValue(next, 0.0);
    out.Parameter->SetValue(next, 0.0);
    out.ArcLength->SetValue(next, 0.0);
    for (vtkDoubleArray* frame : { out.Tangent.Get(), out.Normal.Get(), out.Binormal.Get() })
    {
      frame->SetTuple3(next, 0.0, 0.0, 0.0);
    }
    out.SpanIndex->SetValue(next, 0);
    for (vtkDoubleArray* parameter : out.ShapeParameters)
    {
      parameter->SetValue(next, 0.0);
    }
    *cell++ = next++;
  }
}

/// The samples a line is sampled in a block of (FitSampler): about 270 bytes
/// each while held, so a thread holds 2 MB whatever its lines' length, and a
/// block's own cost vanishes among its samples'.
constexpr long SamplesPerBlock = 8192;

/// A line's curve, sampled here a block at a time, each block written straight
/// into the output; also its Length, Chord and LargestCurvature. False when
/// the run was aborted.
bool WriteSampledLine(
  LineWork& line, vtkIdType first, vtkIdType* cell, SampleOutput& out, LineProgress& progress)
{
  const auto& fit = line.Fit;
  shapesplines::FitSampler sampler(fit, SamplesPerBlock);
  const shapesplines::ProgressCallback report = [&](double fraction) {
    return progress.within(line, fraction);
  };
  const auto& samples = sampler.Block.Samples;
  const std::vector<shapesplines::SpanParameter> lineParameters = fit.Spline->spanParameters();
  const int knotCount = static_cast<int>(fit.Data.Points.size());
  Vec3 start = Vec3::Zero();
  vtkIdType next = first;
  try
  {
    while (sampler.next(report))
    {
      start = samples.First == 0 ? samples.Values.front()[0] : start;
      for (int s = 0; s < samples.size(); ++s)
      {
        const int span = samples.Span[s];
        const auto [interval, fraction] = DataInterval(fit, samples, s);
        const vtkIdType from = line.PointIds[fit.Data.SourceIndex[interval]];
        const vtkIdType to = line.PointIds[fit.Data.SourceIndex[(interval + 1) % knotCount]];
        out.Carried.Interpolate(next, from, to, fraction);
        for (size_t p = 0; p < out.ShapeParameters.size(); ++p)
        {
          out.ShapeParameters[p]->SetValue(
            next, p < lineParameters.size() ? lineParameters[p].Values[span] : 0.0);
        }
        std::copy_n(samples.Values[s][0].data(), 3, out.Xyz + 3 * next);
        const auto& frame = sampler.Block.Frames[s];
        out.Curvature->SetValue(next, frame.Curvature);
        line.LargestCurvature = std::max(line.LargestCurvature, frame.Curvature);
        out.Torsion->SetValue(next, frame.Torsion);
        std::copy_n(frame.Tangent.data(), 3, out.Tangent->GetPointer(3 * next));
        std::copy_n(frame.Normal.data(), 3, out.Normal->GetPointer(3 * next));
        std::copy_n(frame.Binormal.data(), 3, out.Binormal->GetPointer(3 * next));
        out.Parameter->SetValue(next, samples.Parameter[s]);
        out.ArcLength->SetValue(next, samples.ArcLength[s]);
        out.SpanIndex->SetValue(next, span);
        *cell++ = next++;
      }
    }
  }
  catch (const shapesplines::FitAborted&)
  {
    return false;
  }
  line.Length = samples.Length;
  line.Chord = fit.Data.Closed ? 0.0 : (samples.Values.back()[0] - start).norm();
  if (fit.Data.Closed)
  {
    *cell = first;
  }
  return true;
}

/// Writes the kept lines into the output in parallel, a line per task.
/// Progress from 0.8 to 0.95.
void WriteSamplesInParallel(vtkAlgorithm* self, std::vector<LineWork>& lines,
  const std::vector<size_t>& kept, vtkPoints* inPoints, SampleOutput& out)
{
  vtkIdType keptLinePoints = 0;
  for (const size_t k : kept)
  {
    keptLinePoints += static_cast<vtkIdType>(lines[k].PointIds.size());
  }
  LineProgress sampling(self, keptLinePoints, 0.8, 0.95);
  const auto writeRange = [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType c = begin; c < end && !self->GetAbortExecute(); ++c)
    {
      LineWork& line = lines[kept[c]];
      if (!line.Fit.Spline)
      {
        WritePassedThrough(line, inPoints, out.FirstSample[c], out.CellOf(c), out);
      }
      else if (!WriteSampledLine(line, out.FirstSample[c], out.CellOf(c), out, sampling))
      {
        break; // the abort flag is set: the output is dropped
      }
      sampling.lineDone(line);
    }
  };
  WhilePublishing(
    sampling, [&] { vtkSMPTools::For(0, static_cast<vtkIdType>(kept.size()), writeRange); });
}

/// A curvature a million times the line's size is a cusp or a kink, not the
/// shape of the data (where the line runs back on itself, ReportReversals
/// has said why).
void ReportCurvatureSpikes(
  vtkAlgorithm* self, const std::vector<LineWork>& lines, const std::vector<size_t>& kept)
{
  for (const size_t k : kept)
  {
    const LineWork& line = lines[k];
    if (Reversals(line) > 0)
    {
      continue;
    }
    const double diagonal =
      line.Fit.Spline ? line.Fit.Scale * shapesplines::boundingBoxDiagonal(line.Fit.Data.Points) : 0.0;
    if (line.LargestCurvature * diagonal > shapesplines::CuspCurvature)
    {
      vtkWarningWithObjectMacro(self, "Line (" << line.Name << "): curvature up to "
                                      << line.LargestCurvature << ", "
                                      << line.LargestCurvature * diagonal
                                      << " over its bounding box diagonal: a cusp or a kink, not "
                                      << "the data's shape (an automatic mode keeps one only "
                                      << "where the curve of its fixed parameters has it). Mode "
                                      << "Approximate, or the Generalized Cubic Spline's automatic "
                                      << "mode, avoid it.");
    }
  }
}

/// The output's cell arrays of each kept line (after the input cells' own).
struct LineArrays
{
  LineArrays(vtkIdType lineCount, const std::vector<shapesplines::SpanParameter>& parameterNames,
    vtkDataArray* lineIds)
    : Preserving(shapesplines::newArray<vtkUnsignedCharArray>(names::ShapePreserving, 1, lineCount))
    , Violations(shapesplines::newArray<vtkIntArray>(names::ShapeViolations, 1, lineCount))
    , Length(NewArray(names::Length, 1, lineCount))
    , KnotCount(shapesplines::newArray<vtkIntArray>(names::NumberOfKnots, 1, lineCount))
    , NoiseLevel(NewArray(names::NoiseLevel, 1, lineCount))
    , Deviation(NewArray(names::PolygonDeviation, 1, lineCount))
    , Tortuosity(NewArray(names::Tortuosity, 1, lineCount))
    , Condition(NewArray(names::ConditionEstimate, 1, lineCount))
    , Merged(shapesplines::newArray<vtkIntArray>(names::MergedPoints, 1, lineCount))
    , LineIds(lineIds)
  {
    for (const auto& p : parameterNames)
    {
      const std::string summary = (p.CellSummaryIsMaximum ? "Max" : "Min") + p.Name;
      this->ShapeParameterSummaries.push_back(NewArray(summary.c_str(), 1, lineCount));
      this->ShapeParameterSummaries.back()->FillValue(0.0);
    }
    // Connected points keep their line ids, in the ids' own type.
    if (lineIds)
    {
      this->LineIdValues = vtk::TakeSmartPointer(lineIds->NewInstance());
      this->LineIdValues->SetName(names::LineId);
      this->LineIdValues->SetNumberOfTuples(lineCount);
    }
  }

  void Write(vtkIdType c, const LineWork& line)
  {
    const auto& fit = line.Fit;
    const int count = fit.Spline ? fit.Audit.violations() : 0;
    this->Preserving->SetValue(c, count == 0 ? 1 : 0);
    this->Violations->SetValue(c, count);
    const double total = line.Length;
    this->Length->SetValue(c, total);
    this->Tortuosity->SetValue(c, line.Chord > 0 ? total / line.Chord : 0.0);
    this->Condition->SetValue(c, fit.Spline ? fit.Spline->conditionEstimate() : 1.0);
    this->KnotCount->SetValue(c, fit.Spline ? static_cast<int>(fit.Spline->knots().size()) : 0);
    this->NoiseLevel->SetValue(c, fit.NoiseLevel);
    this->Merged->SetValue(c, fit.Data.MergedPoints);
    if (this->LineIdValues)
    {
      this->LineIdValues->SetTuple1(c, this->LineIds->GetComponent(line.PointIds[0], 0));
    }
    this->Deviation->SetValue(c, fit.Spline ? fit.Audit.PolygonDeviation : 0.0);
    const auto lineParameters =
      fit.Spline ? fit.Spline->spanParameters() : std::vector<shapesplines::SpanParameter>{};
    for (size_t p = 0; p < lineParameters.size() && p < this->ShapeParameterSummaries.size(); ++p)
    {
      const auto& values = lineParameters[p].Values;
      if (!values.empty())
      {
        this->ShapeParameterSummaries[p]->SetValue(c, lineParameters[p].CellSummaryIsMaximum
            ? *std::max_element(values.begin(), values.end())
            : *std::min_element(values.begin(), values.end()));
      }
    }
  }

  void AddTo(vtkCellData* cellData) const
  {
    shapesplines::addArrays(cellData, { this->Preserving, this->Violations, this->Length,
                                        this->Tortuosity, this->Condition, this->KnotCount,
                                        this->NoiseLevel, this->Deviation, this->Merged });
    if (this->LineIdValues)
    {
      cellData->AddArray(this->LineIdValues);
    }
    for (const auto& a : this->ShapeParameterSummaries)
    {
      cellData->AddArray(a);
    }
  }

  vtkSmartPointer<vtkUnsignedCharArray> Preserving;
  vtkSmartPointer<vtkIntArray> Violations;
  vtkSmartPointer<vtkDoubleArray> Length;
  vtkSmartPointer<vtkIntArray> KnotCount;
  vtkSmartPointer<vtkDoubleArray> NoiseLevel, Deviation, Tortuosity, Condition;
  vtkSmartPointer<vtkIntArray> Merged;
  vtkDataArray* LineIds;                      ///< the connected points' line ids, or null
  vtkSmartPointer<vtkDataArray> LineIdValues; ///< LineId, when there are line ids
  std::vector<vtkSmartPointer<vtkDoubleArray>> ShapeParameterSummaries;
};

/// Per-line cell data: the input cells' (connected points have none), then ours.
void WriteCellData(vtkCellData* inCD, vtkPolyData* output, const InputLines& gathered,
  const std::vector<size_t>& kept, const std::vector<shapesplines::SpanParameter>& parameterNames)
{
  const auto lineCount = static_cast<vtkIdType>(kept.size());
  vtkCellData* outCD = output->GetCellData();
  if (!gathered.Connected)
  {
    outCD->CopyAllocate(inCD, lineCount);
  }
  LineArrays arrays(lineCount, parameterNames, gathered.LineIds);
  for (vtkIdType c = 0; c < lineCount; ++c)
  {
    const LineWork& line = gathered.Lines[kept[c]];
    if (!gathered.Connected)
    {
      outCD->CopyData(inCD, line.CellId, c);
    }
    arrays.Write(c, line);
  }
  arrays.AddTo(outCD);
}
} // namespace

vtkShapeSplineFilter::vtkShapeSplineFilter() = default;
vtkShapeSplineFilter::~vtkShapeSplineFilter()
{
  this->SetLineIdArrayName(nullptr);
}

const char* vtkShapeSplineFilter::GetParameterizationAsString()
{
  switch (this->Parameterization)
  {
    case UNIFORM:
      return "Uniform";
    case CENTRIPETAL:
      return "Centripetal";
    default:
      return "ChordLength";
  }
}

const char* vtkShapeSplineFilter::GetSamplingModeAsString()
{
  return this->SamplingMode == ARC_LENGTH ? names::ArcLength : "Subdivisions";
}

int vtkShapeSplineFilter::ApproximationKnotCount(int numberOfKnots)
{
  return numberOfKnots == 0 ? shapesplines::CrossValidatedKnots : std::max(2, numberOfKnots);
}

const char* vtkShapeSplineFilter::GetPointValuesArrayInUse()
{
  const char* name = this->GetPointValuesArrayName();
  return NamesAnArray(name) ? name : nullptr;
}

int vtkShapeSplineFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  int status = 1;
  vtkPolyData* input = shapesplines::polyDataInput(this, inputVector[0], output, status);
  if (!input)
  {
    return status;
  }
  auto settings = this->GetNumericSettings();
  settings.insert(settings.end(), { { "DataShapeTolerance", this->DataShapeTolerance },
                                    { "CurveShapeTolerance", this->CurveShapeTolerance } });
  for (const auto& [name, value] : settings)
  {
    if (std::isnan(value))
    {
      vtkErrorMacro(<< name << " is NaN: nothing fitted.");
      return 1;
    }
  }
  if (this->SamplingMode == ARC_LENGTH &&
    !(this->SampleLength > 0.0 && this->SampleLength <= VTK_DOUBLE_MAX))
  {
    vtkErrorMacro("SampleLength must be positive and finite, not " << this->SampleLength
                                                                  << ": nothing sampled.");
    return 1;
  }
  try
  {
    int status = 1;
    vtkSMPTools::LocalScope(
      ThreadsFor(this->NumberOfThreads), [&] { status = this->FitLines(input, output); });
    return status;
  }
  catch (const std::bad_alloc&)
  {
    output->Initialize();
    vtkErrorMacro("Out of memory: the output is empty. Fewer samples (NumberOfSubdivisions, "
                  "SampleLength) or fewer lines per run need less.");
    return 1;
  }
}

int vtkShapeSplineFilter::FitLines(vtkPolyData* input, vtkPolyData* output)
{
  // Gather the lines serially; fit them in parallel (curve, audit, sampling plan).
  const ReadableArrays readable(this, input);
  std::optional<InputLines> gathered = GatherInputLines(
    this, input, readable.Points, this->ConnectPoints, this->LineIdArrayName);
  if (!gathered)
  {
    return 1; // reported: the output is empty
  }
  std::vector<LineWork>& lines = gathered->Lines;

  const shapesplines::CurveBuilder build = [this](const shapesplines::FitContext& context) {
    return this->BuildCurve(context);
  };
  vtkDataArray* pointValues =
    PointValuesArray(this, readable.Points, this->GetPointValuesArrayInUse());
  FitInParallel(this, lines, input->GetPoints(), pointValues, this->BuildFitOptions(input), build);
  if (this->GetAbortExecute())
  {
    return 1; // an aborted run leaves the output empty
  }
  this->UpdateProgress(0.8);

  // Messages and where each line's samples go, serially (VTK's messages are not
  // thread-safe); then the arrays are written in parallel, a line per task.
  const std::vector<size_t> kept = ReportFits(
    this, lines, this->Approximates(), this->AdjustsShape(), this->GathersBendsAtKnots());
  std::vector<vtkIdType> firstSample = FirstSamples(lines, kept);
  if (!this->WithinSampleBudget(firstSample.back()))
  {
    return 1;
  }
  const auto parameterNames = ShapeParameterNames(lines, kept);
  SampleOutput samples(readable.Points, lines, kept, std::move(firstSample), parameterNames);
  WriteSamplesInParallel(this, lines, kept, input->GetPoints(), samples);
  if (this->GetAbortExecute())
  {
    return 1; // an aborted run leaves the output empty
  }
  this->UpdateProgress(0.95);
  ReportCurvatureSpikes(this, lines, kept);
  samples.AddTo(output, this->VMTKArrayNames);
  WriteCellData(readable.Cells, output, *gathered, kept, parameterNames);
  // The fits freed in parallel, not one after another when the lines go
  // (4000 quintic fits of 50 points: ~30 ms on one thread).
  vtkSMPTools::For(0, static_cast<vtkIdType>(lines.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType c = begin; c < end; ++c)
    {
      lines[c].Fit = shapesplines::FittedPolyline();
    }
  });
  return 1;
}

shapesplines::FitOptions vtkShapeSplineFilter::BuildFitOptions(vtkPolyData* input) const
{
  shapesplines::FitOptions options;
  options.Knots = static_cast<shapesplines::Parameterization>(this->Parameterization);
  options.Closed = this->Closed;
  options.Sampling.SampleMode = this->SamplingMode == ARC_LENGTH
    ? shapesplines::SamplingOptions::Mode::ArcLength
    : shapesplines::SamplingOptions::Mode::Subdivisions;
  options.Sampling.Subdivisions = this->NumberOfSubdivisions;
  options.Sampling.TargetLength = this->SampleLength;
  options.Tolerances.Data = this->DataShapeTolerance;
  options.Tolerances.Curve = this->CurveShapeTolerance;
  options.CoordinatePrecision = shapesplines::coordinatePrecision(input);
  return options;
}

bool vtkShapeSplineFilter::WithinSampleBudget(vtkIdType samples)
{
  if (samples <= MaximumRunSamples)
  {
    return true;
  }
  vtkErrorMacro("The output would hold " << samples << " samples, more than the "
                << MaximumRunSamples << " a run may make (about 170 bytes each while it is "
                << "made): "
                << (this->SamplingMode == ARC_LENGTH
                       ? "raise SampleLength (now " + std::to_string(this->SampleLength) + ")"
                       : "lower NumberOfSubdivisions (now " +
                         std::to_string(this->NumberOfSubdivisions) + ")")
                << ", or split the input. The output is empty.");
  return false;
}

void vtkShapeSplineFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Parameterization: " << this->GetParameterizationAsString() << "\n";
  os << indent << "Closed: " << (this->Closed ? "On" : "Off") << "\n";
  os << indent << "SamplingMode: " << this->GetSamplingModeAsString() << "\n";
  os << indent << "NumberOfSubdivisions: " << this->NumberOfSubdivisions << "\n";
  os << indent << "SampleLength: " << this->SampleLength << "\n";
  os << indent << "DataShapeTolerance: " << this->DataShapeTolerance << "\n";
  os << indent << "CurveShapeTolerance: " << this->CurveShapeTolerance << "\n";
  os << indent << "CorrectParameters: " << (this->CorrectParameters ? "On" : "Off") << "\n";
  os << indent << "VMTKArrayNames: " << (this->VMTKArrayNames ? "On" : "Off") << "\n";
  os << indent << "ConnectPoints: " << (this->ConnectPoints ? "On" : "Off") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "LineIdArrayName: " << (this->LineIdArrayName ? this->LineIdArrayName : "(none)")
     << "\n";
}
