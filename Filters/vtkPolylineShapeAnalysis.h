/**
 * @class   vtkPolylineShapeAnalysis
 * @brief   the discrete shape of polylines (Costantini & Manni, Def. 1) and,
 *          given a curve fitted to them, where the curve breaks that shape
 *
 * Input 0: polylines (the data). For each line, after merging consecutive
 * repeated points, the output (a shallow copy of input 0) gets point arrays:
 * - DiscreteCurvature: Menger curvature (1 / radius of the circle through a
 *   point and its neighbours), 0 at the ends of open lines;
 * - DiscreteBinormal: B_i = L_{i-1} x L_i / (|L_{i-1}| |L_i|);
 * - DiscreteTorsion: the signed discrete torsion Delta_i of the segment
 *   from this point to the next (0 for coplanar segments and at the ends);
 * - Collinear, Convex, Coplanar: 0/1 flags saying which criterion of
 *   Definition 1 applies at the point (Coplanar: on the segment it starts).
 *
 * Optional input 1: curves made by any ShapeSplines filter from the same
 * lines (matched in order), with their SpanIndex, Tangent, Binormal,
 * Curvature and Torsion arrays. Then the output also gets the audit: a point
 * array ViolationMask on each segment's start point (bit 0 collinearity,
 * 1 convexity at knot, 2 convexity on span, 3 coplanarity, 4 torsion sign at
 * knot, 5 torsion sign on span) and cell arrays ShapeViolations,
 * ShapePreserving and one count per criterion (-1 and 0 for a line that could
 * not be audited: a curve line missing, non-finite data, or a curve whose spans
 * or closure do not match the data). The audit sees the curve only at its
 * samples: sample densely enough.
 *
 * Composite inputs (multiblock, partitioned, partitioned collection) on
 * either port: the output has input 0's structure, each poly data block is
 * analysed against the curve's block at the same place (a single poly data
 * curve serves a single block); blocks that are not poly data are left out
 * with a warning naming them.
 *
 * @sa vtkShapeSplineFilter vtkCubicSplineFilter
 */
#ifndef vtkPolylineShapeAnalysis_h
#define vtkPolylineShapeAnalysis_h

#include "ShapeSplinesFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkDataObjectTree;

class SHAPESPLINESFILTERS_EXPORT vtkPolylineShapeAnalysis : public vtkPolyDataAlgorithm
{
public:
  static vtkPolylineShapeAnalysis* New();
  vtkTypeMacro(vtkPolylineShapeAnalysis, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The curve to audit (optional second input).
  void SetCurveConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  ///@{
  /**
   * Treat every line with at least three distinct points as closed (lines
   * whose last point repeats their first always are). Use the same value as
   * the filter that made the curve. Off by default.
   */
  vtkSetMacro(Closed, bool);
  vtkGetMacro(Closed, bool);
  vtkBooleanMacro(Closed, bool);
  ///@}

  ///@{
  /**
   * Tolerance epsilon_1 on the data (see vtkShapeSplineFilter). Default 1e-6.
   */
  vtkSetClampMacro(DataShapeTolerance, double, 0.0, 1.0);
  vtkGetMacro(DataShapeTolerance, double);
  ///@}

  ///@{
  /**
   * Tolerance epsilon_2 on the curve (see vtkShapeSplineFilter). Default 1e-3.
   */
  vtkSetClampMacro(CurveShapeTolerance, double, 0.0, 1.0);
  vtkGetMacro(CurveShapeTolerance, double);
  ///@}

protected:
  vtkPolylineShapeAnalysis();
  ~vtkPolylineShapeAnalysis() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  /// The output is of input 0's type (poly data, or its composite structure).
  int RequestDataObject(vtkInformationVector** inputVector, vtkInformationVector* outputVector);
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool Closed = false;
  double DataShapeTolerance = 1e-6;
  double CurveShapeTolerance = 1e-3;

private:
  /// One poly data block against its curve (null: no audit).
  void Analyse(vtkPolyData* input, vtkPolyData* curve, vtkPolyData* output);

  /// Each poly data block of a composite input against the curve's block at
  /// the same place (or the one curve for a single data block).
  void AnalyseBlocks(
    vtkDataObjectTree* inputTree, vtkDataObject* curveObject, vtkDataObjectTree* outputTree);

  vtkPolylineShapeAnalysis(const vtkPolylineShapeAnalysis&) = delete;
  void operator=(const vtkPolylineShapeAnalysis&) = delete;
};

#endif
