/**
 * @class   vtkCubicSplineFilter
 * @brief   the classical C2 cubic interpolating spline through each polyline,
 *          with exact curvature, torsion and Frenet frame
 *
 * The baseline of ShapeSplines: the C2 cubic spline through the points of
 * each line, solved globally (O(n) sparse solve) with not-a-knot (default),
 * natural or clamped ends; closed lines get the periodic spline. It is what
 * the shape-preserving families are compared with: it interpolates smoothly
 * but may overshoot and invent inflections, and its ShapeViolations cell
 * array says where. Everything else (sampling, arrays, bad input) is
 * described in vtkShapeSplineFilter.
 *
 * @sa vtkShapeSplineFilter vtkPolylineShapeAnalysis vtkSplineFilter vtkCardinalSpline
 */
#ifndef vtkCubicSplineFilter_h
#define vtkCubicSplineFilter_h

#include "ShapeSplinesFiltersModule.h" // for export macro
#include "vtkShapeSplineFilter.h"

class SHAPESPLINESFILTERS_EXPORT vtkCubicSplineFilter : public vtkShapeSplineFilter
{
public:
  static vtkCubicSplineFilter* New();
  vtkTypeMacro(vtkCubicSplineFilter, vtkShapeSplineFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum EndConditionType
  {
    NATURAL = 0,
    NOT_A_KNOT = 1,
    CLAMPED = 2
  };

  ///@{
  /**
   * End conditions of open lines: NATURAL (zero second derivative),
   * NOT_A_KNOT (default: third derivative continuous at the second and
   * last-but-one points, as SciPy's CubicSpline) or CLAMPED (end tangents of
   * the parabolas through the first and last three points). Closed lines are
   * periodic and ignore it.
   */
  vtkSetClampMacro(EndCondition, int, NATURAL, CLAMPED);
  vtkGetMacro(EndCondition, int);
  void SetEndConditionToNatural() { this->SetEndCondition(NATURAL); }
  void SetEndConditionToNotAKnot() { this->SetEndCondition(NOT_A_KNOT); }
  void SetEndConditionToClamped() { this->SetEndCondition(CLAMPED); }
  const char* GetEndConditionAsString();
  ///@}

protected:
  vtkCubicSplineFilter();
  ~vtkCubicSplineFilter() override;

#ifndef __VTK_WRAP__
  shapesplines::BuiltCurve BuildCurve(const shapesplines::FitContext& context) const override;
#endif

  int EndCondition = NOT_A_KNOT;

private:
  vtkCubicSplineFilter(const vtkCubicSplineFilter&) = delete;
  void operator=(const vtkCubicSplineFilter&) = delete;
};

#endif
