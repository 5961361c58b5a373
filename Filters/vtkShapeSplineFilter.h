/**
 * @class   vtkShapeSplineFilter
 * @brief   abstract base of the ShapeSplines curve filters: polylines in, sampled
 *          spline curves with Frenet frame, curvature, torsion and shape audit out
 *
 * vtkShapeSplineFilter does the VTK plumbing every spline family shares; a
 * subclass only builds its curve through the cleaned points of one line
 * (BuildCurve). For each polyline (or line) cell of the input it:
 * - merges consecutive repeated points (cell array MergedPoints counts them),
 * - closes the line if its last point repeats its first, or if Closed is on,
 * - computes the knots (Parameterization), builds the spline, samples it
 *   (NumberOfSubdivisions per span, or about SampleLength apart; the data
 *   points are always among the samples; a closed curve does not repeat its
 *   seam point, its cell does),
 * - computes the unit Frenet frame, curvature and signed torsion from the
 *   spline's exact derivatives, and audits the curve against the discrete
 *   shape of the data (Costantini & Manni, Definition 1).
 *
 * Output point arrays: Curvature, Torsion, Tangent, Normal, Binormal,
 * Parameter, ArcLength, SpanIndex, the family's shape parameters per span
 * (e.g. Degree, Tension; 0 on lines too short for the family's curve), and
 * the input point arrays interpolated between the data points around each
 * sample. Output cell arrays: ShapePreserving, ShapeViolations, Length,
 * Tortuosity (length / end-to-end distance, 0 for closed lines),
 * ConditionEstimate (of the linear systems solved for the line; a warning
 * names the lines where it is too large to trust, above 4.5e11), the
 * summary of each shape parameter (Max<Name> or Min<Name>), NumberOfKnots
 * (of the curve), MergedPoints (repeated points merged), NoiseLevel (an approximation's root-mean-square distance
 * from its points; 0 for an interpolation), PolygonDeviation (the largest
 * distance of the curve from its segment of the data, or of the
 * approximation's reference polygon, over the longest of that segment and its
 * neighbours: beyond 0.5 the line is not ShapePreserving, its straying spans
 * count among its ShapeViolations, and a warning names it), and the input
 * cell arrays. Field data TorsionColorRange holds -m and m, m the 95th
 * percentile of |torsion| over the samples: a colour range centred on zero
 * that a few noise spikes do not squash (the plugin colours by it in
 * ParaView).
 * Interpolated lines whose points look noisy (a least squares keeps far
 * fewer knots than points, and fewer than half the points sit on exactly
 * straight runs, as designed points do) get one warning per run: measured
 * points' curvature and torsion follow the noise, and Mode Approximate gives
 * the curve's own. Exact points that turn within a few points (a helix at
 * 3.6 points a turn, a protein's C-alpha trace) look the same to the test.
 * An approximating family audits its curve against the polygon whose shape
 * it keeps rather than against the data. With VMTKArrayNames on, the frame
 * is also written as FrenetTangent, FrenetNormal and FrenetBinormal.
 *
 * The shape-preserving families' automatic modes (their default) raise the
 * shape parameter only on failing spans and never beyond bounds that keep
 * the curve regular: the curvature within 1e3 times the data's largest
 * discrete curvature (1e4 with straight runs), the speed above 1e-3 of each
 * span's chord over its parameter length, no span farther than half a
 * segment from its data. The best curve met is kept; lines left with
 * violations are named, with the criterion and where, in one warning per
 * run.
 *
 * Lines with one distinct point are passed through unchanged (zero frame) and
 * lines with two distinct points become straight segments, each with a
 * warning; lines with NaN or Inf coordinates, or a coordinate beyond 1e300,
 * are skipped with an error naming the cell; vertices, polygons and strips are
 * ignored with a warning. An input of points without cells or with vertices
 * only is connected into lines (ConnectPoints). A line whose curvature goes beyond 1e6 over its
 * bounding box diagonal (a cusp or a kink) is named in a warning. The input
 * is never modified. Lines are processed in parallel with vtkSMPTools.
 *
 * @sa vtkCubicSplineFilter vtkPolylineShapeAnalysis vtkSplineFilter
 */
#ifndef vtkShapeSplineFilter_h
#define vtkShapeSplineFilter_h

#include "ShapeSplinesFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <utility> // for std::pair
#include <vector>  // for std::vector

#ifndef __VTK_WRAP__
namespace shapesplines
{
struct BuiltCurve;
struct FitContext;
struct FitOptions;
}
#endif

class SHAPESPLINESFILTERS_EXPORT vtkShapeSplineFilter : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkShapeSplineFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ParameterizationType
  {
    UNIFORM = 0,
    CHORD_LENGTH = 1,
    CENTRIPETAL = 2
  };

  enum SamplingModeType
  {
    SUBDIVISIONS = 0,
    ARC_LENGTH = 1
  };

  ///@{
  /**
   * How the knots (data parameters) are spaced: uniform, chord length
   * (default) or centripetal (square root of the chord length).
   */
  vtkSetClampMacro(Parameterization, int, UNIFORM, CENTRIPETAL);
  vtkGetMacro(Parameterization, int);
  void SetParameterizationToUniform() { this->SetParameterization(UNIFORM); }
  void SetParameterizationToChordLength() { this->SetParameterization(CHORD_LENGTH); }
  void SetParameterizationToCentripetal() { this->SetParameterization(CENTRIPETAL); }
  const char* GetParameterizationAsString();
  ///@}

  ///@{
  /**
   * Close every line with at least three distinct points, even if its last
   * point does not repeat its first (lines that repeat it are always closed).
   * Off by default.
   */
  vtkSetMacro(Closed, bool);
  vtkGetMacro(Closed, bool);
  vtkBooleanMacro(Closed, bool);
  ///@}

  ///@{
  /**
   * Sample each span with NumberOfSubdivisions samples (default), or place
   * samples about SampleLength apart along the curve.
   */
  vtkSetClampMacro(SamplingMode, int, SUBDIVISIONS, ARC_LENGTH);
  vtkGetMacro(SamplingMode, int);
  void SetSamplingModeToSubdivisions() { this->SetSamplingMode(SUBDIVISIONS); }
  void SetSamplingModeToArcLength() { this->SetSamplingMode(ARC_LENGTH); }
  const char* GetSamplingModeAsString();
  ///@}

  ///@{
  /**
   * Samples per span in SUBDIVISIONS mode (default 10).
   */
  vtkSetClampMacro(NumberOfSubdivisions, int, 1, 100000);
  vtkGetMacro(NumberOfSubdivisions, int);
  ///@}

  ///@{
  /**
   * Target distance along the curve between samples in ARC_LENGTH mode
   * (default 1, in the units of the input). A line never gets more than
   * 1e7 samples: the spacing grows, with a warning, if it would. Zero,
   * negative or NaN lengths are refused with an error (nothing sampled), and
   * so is a run of more than MaximumRunSamples samples.
   */
  vtkSetClampMacro(SampleLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SampleLength, double);
  ///@}

  ///@{
  /**
   * Tolerance epsilon_1 of the shape audit on the data: points whose
   * discrete binormal is shorter (sine of the turning angle) are collinear,
   * segments whose normalised triple product is smaller are coplanar.
   * Default 1e-6.
   */
  vtkSetClampMacro(DataShapeTolerance, double, 0.0, 1.0);
  vtkGetMacro(DataShapeTolerance, double);
  ///@}

  ///@{
  /**
   * Tolerance epsilon_2 of the shape audit on the curve: the sine of the
   * angle by which its tangent (binormal) may leave a collinear (coplanar)
   * run, and how far its curvature and torsion, made scale-free with the
   * bounding-box diagonal, may fall below zero where the data ask for a sign.
   * Default 1e-3.
   */
  vtkSetClampMacro(CurveShapeTolerance, double, 0.0, 1.0);
  vtkGetMacro(CurveShapeTolerance, double);
  ///@}

  ///@{
  /**
   * Approximating families (Mode Approximate): correct each point's
   * parameter towards the curve (projected onto the fit, refitted, three
   * rounds, for every knot count cross-validation tries) rather than keep
   * the Parameterization's (default on). Chord lengths between noisy points
   * carry the noise, and a least squares on them asks for ever more knots.
   */
  vtkSetMacro(CorrectParameters, bool);
  vtkGetMacro(CorrectParameters, bool);
  vtkBooleanMacro(CorrectParameters, bool);
  ///@}

  ///@{
  /**
   * Also write the frame under VMTK's names FrenetTangent, FrenetNormal and
   * FrenetBinormal, so VMTK pipelines keep working. Off by default.
   */
  vtkSetMacro(VMTKArrayNames, bool);
  vtkGetMacro(VMTKArrayNames, bool);
  vtkBooleanMacro(VMTKArrayNames, bool);
  ///@}

  ///@{
  /**
   * The most threads the lines are fitted on. 0 (default): all the machine's
   * cores; and when the process runs VTK's Sequential backend (Debian's VTK,
   * pvpython and ParaView start with it) and the user has not chosen one with
   * VTK_SMP_BACKEND_IN_USE, the filter runs its lines on the STDThread
   * backend for the run (vtkSMPTools::LocalScope: nothing else in the
   * process changes). 1: one thread. The output is the same whatever the
   * count.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * What an input of points without cells, or with vertices only (a table's
   * rows from Table To Points), becomes. On (default): its points, in point order, make lines:
   * one line per value of the line id point array (see LineIdArrayName), in
   * the order of their first points, or one line of all points. Off: such an
   * input gives an empty output with a warning. Inputs with line cells are
   * unaffected.
   */
  vtkSetMacro(ConnectPoints, bool);
  vtkGetMacro(ConnectPoints, bool);
  vtkBooleanMacro(ConnectPoints, bool);
  ///@}

  ///@{
  /**
   * The point array whose values say which line each connected point belongs
   * to (ConnectPoints). Empty or "None" (default): the first point array named
   * line_id, line, lineid, id, cell, cell_id, track or streamline (any case),
   * or one line when there is none. The output cell array LineId keeps each
   * line's value. A name that is no numeric point array is an error.
   */
  vtkSetStringMacro(LineIdArrayName);
  vtkGetStringMacro(LineIdArrayName);
  ///@}

protected:
  vtkShapeSplineFilter();
  ~vtkShapeSplineFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// The most samples one run writes (all lines together): beyond, an error
  /// and an empty output rather than memory the machine may not have.
  static constexpr vtkIdType MaximumRunSamples = 20000000;

#ifndef __VTK_WRAP__
  /**
   * The family's curve for one line's cleaned data (at least three distinct
   * points) and knots, in the normalised frame of the context. Called
   * concurrently for different lines: must not modify the filter. Throws
   * std::exception with a message on failure.
   */
  virtual shapesplines::BuiltCurve BuildCurve(const shapesplines::FitContext& context) const = 0;
#endif

  /**
   * The name of an input point array whose values the family reads per point
   * (FitContext::PointValues), or null (default). Empty and "None" (what
   * ParaView's array list sends for no array) mean none too. A missing array
   * is ignored with a warning; of a multi-component array the first
   * component is used.
   */
  virtual const char* GetPointValuesArrayName() { return nullptr; }

  /// GetPointValuesArrayName(), or null when it names no array.
  const char* GetPointValuesArrayInUse();

  /// Whether the family is set to approximate (least squares) rather than
  /// interpolate: lines it cannot approximate are reported.
  virtual bool Approximates() const { return false; }

  /// The family's numeric settings by name, checked for NaN (which would pass
  /// the clamping setters) before a run.
  virtual std::vector<std::pair<const char*, double>> GetNumericSettings() const { return {}; }

  /// Whether the family's automatic shape mode is on: violations it leaves
  /// (it could not remove them within its bounds) are reported.
  virtual bool AdjustsShape() const { return false; }

  /// Whether the automatic mode's parameter can gather a bend at its knot
  /// (the generalized cubic's tension, the variable degree spline's degrees):
  /// where one that cannot (the quintic's gamma, qqr's straightness) leaves
  /// violations on interpolated lines, the warning points to those that can.
  virtual bool GathersBendsAtKnots() const { return true; }

  /// An approximating family's NumberOfKnots for the math core: 0 is
  /// shapesplines::CrossValidatedKnots, 1 counts as 2.
  static int ApproximationKnotCount(int numberOfKnots);

  int Parameterization = CHORD_LENGTH;
  bool Closed = false;
  int SamplingMode = SUBDIVISIONS;
  int NumberOfSubdivisions = 10;
  double SampleLength = 1.0;
  double DataShapeTolerance = 1e-6;
  double CurveShapeTolerance = 1e-3;
  bool CorrectParameters = true;
  bool VMTKArrayNames = false;
  bool ConnectPoints = true;
  int NumberOfThreads = 0;
  char* LineIdArrayName = nullptr;

private:
  /// RequestData's work once its input is checked; std::bad_alloc escapes.
  int FitLines(vtkPolyData* input, vtkPolyData* output);

#ifndef __VTK_WRAP__
  /// The math core's options from the settings and the input's point type.
  shapesplines::FitOptions BuildFitOptions(vtkPolyData* input) const;
#endif

  /// Whether a run may write this many samples (MaximumRunSamples); an error
  /// says what to change when not.
  bool WithinSampleBudget(vtkIdType samples);

  vtkShapeSplineFilter(const vtkShapeSplineFilter&) = delete;
  void operator=(const vtkShapeSplineFilter&) = delete;
};

#endif
