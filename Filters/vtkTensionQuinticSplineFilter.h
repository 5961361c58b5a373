/**
 * @class   vtkTensionQuinticSplineFilter
 * @brief   C3 or C4 tensioned quintic parametric B-spline through each
 *          polyline, with shape parameters chosen automatically where the
 *          shape of the data asks for them
 *
 * The spline of Cravero, Manni and Sampoli (Cravero, Manni & Sampoli): quintic B-spline-like
 * functions with six-interval support built by a geometric construction of
 * their Bezier points. Continuity C4 (default) has one tension parameter gamma
 * in (0,1] per knot; C3 has gamma in (0,2) and lambda > 0 per knot. With all
 * parameters 1 both are the classical quintic interpolating spline; as they
 * go to 0 the curve goes to the polyline through the points. The knots
 * (Parameterization) stay where they are for any parameters (knot system (34)
 * of the paper).
 *
 * In Automatic mode (default) every knot starts at gamma = lambda = 1 and
 * the parameters of the two knots of every span that breaks the shape of the
 * data (Costantini & Manni (VDPS), Definition 1: collinearity, convexity, coplanarity,
 * torsion sign) are lowered, by sqrt(2) a step, until no span breaks it or they reach 1/256,
 * within the bounds every automatic mode keeps (no cusp, no runaway
 * curvature; see vtkShapeSplineFilter); what is left is reported.
 * Otherwise Gamma and Lambda are used at every knot (C4 uses min(Gamma, 1)).
 * The point arrays Gamma (and Lambda for C3) and the cell arrays MinGamma
 * (and MinLambda) report the parameters used, per span the smaller of its
 * two knots'.
 *
 * Mode APPROXIMATE (lines with at least six points, open or closed; shorter
 * ones are interpolated with a warning) fits the spline with NumberOfKnots
 * knots (0, the default: chosen per line by cross-validation), uniform in
 * the parameters (on lines it smooths, weighted by the curvature of a
 * first fit where that scores better), which CorrectParameters moves to where each point sits on
 * the curve, in least squares (Cravero, Manni & Sampoli, section 5); its shape reference is
 * L*, the least-squares polygon on the same knots, whose shape the automatic
 * mode keeps where it stands out of the noise, changing the curvature by at
 * most 2x. ShapeViolations then counts every Definition 1 criterion against
 * L*; the cell arrays NumberOfKnots and NoiseLevel report the knots and the
 * points' RMS distance from the curve.
 * Everything else (sampling, arrays, bad input) is described in
 * vtkShapeSplineFilter.
 *
 * @sa vtkShapeSplineFilter vtkCubicSplineFilter vtkPolylineShapeAnalysis
 */
#ifndef vtkTensionQuinticSplineFilter_h
#define vtkTensionQuinticSplineFilter_h

#include "ShapeSplinesFiltersModule.h" // for export macro
#include "vtkShapeSplineFilter.h"

class SHAPESPLINESFILTERS_EXPORT vtkTensionQuinticSplineFilter : public vtkShapeSplineFilter
{
public:
  static vtkTensionQuinticSplineFilter* New();
  vtkTypeMacro(vtkTensionQuinticSplineFilter, vtkShapeSplineFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ContinuityType
  {
    C3 = 0,
    C4 = 1
  };

  enum ModeType
  {
    INTERPOLATE = 0,
    APPROXIMATE = 1
  };

  ///@{
  /**
   * C4 (default: one parameter gamma per knot) or C3 (gamma and lambda per
   * knot, more freedom, fourth derivative jumps at the knots).
   */
  vtkSetClampMacro(Continuity, int, C3, C4);
  vtkGetMacro(Continuity, int);
  void SetContinuityToC3() { this->SetContinuity(C3); }
  void SetContinuityToC4() { this->SetContinuity(C4); }
  const char* GetContinuityAsString();
  ///@}

  ///@{
  /**
   * INTERPOLATE (default): through every point. APPROXIMATE: least squares
   * with NumberOfKnots knots.
   */
  vtkSetClampMacro(Mode, int, INTERPOLATE, APPROXIMATE);
  vtkGetMacro(Mode, int);
  void SetModeToInterpolate() { this->SetMode(INTERPOLATE); }
  void SetModeToApproximate() { this->SetMode(APPROXIMATE); }
  const char* GetModeAsString();
  ///@}

  ///@{
  /**
   * Knots of the approximation (1 counts as 2), or 0 (default): chosen per
   * line from the data by generalized cross-validation on parameters
   * corrected towards the curve, the fewest within half a standard error of
   * the best score (CorrectParameters); lines that this smooths are
   * planned again on parameters weighted by a first fit's curvature, and
   * the better-scoring plan kept (the one with fewer knots where both score
   * within half a standard error of the better's best). At most half the points and
   * points - 4 (lines of fewer than 6 points are interpolated).
   */
  vtkSetClampMacro(NumberOfKnots, int, 0, 1000000);
  vtkGetMacro(NumberOfKnots, int);
  ///@}

  ///@{
  /**
   * Choose the shape parameters per knot, only where the shape audit fails
   * (default on); off: use Gamma and Lambda everywhere.
   */
  vtkSetMacro(Automatic, bool);
  vtkGetMacro(Automatic, bool);
  vtkBooleanMacro(Automatic, bool);
  ///@}

  ///@{
  /**
   * Tension gamma at every knot when Automatic is off (default 1, the
   * classical quintic spline; smaller is tighter). C3 takes it in
   * [1e-6, 1.999], C4 in [1e-6, 1] (larger values count as 1, with a warning).
   */
  vtkSetClampMacro(Gamma, double, 1e-6, 1.999);
  vtkGetMacro(Gamma, double);
  ///@}

  ///@{
  /**
   * Tension lambda of the C3 continuity at every knot when Automatic is off
   * (default 1; smaller is tighter), in [1e-6, 1e6].
   */
  vtkSetClampMacro(Lambda, double, 1e-6, 1e6);
  vtkGetMacro(Lambda, double);
  ///@}

protected:
  vtkTensionQuinticSplineFilter();
  ~vtkTensionQuinticSplineFilter() override;
  bool Approximates() const override { return this->Mode == APPROXIMATE; }
  bool AdjustsShape() const override { return this->Automatic; }
  bool GathersBendsAtKnots() const override { return false; }

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

#ifndef __VTK_WRAP__
  shapesplines::BuiltCurve BuildCurve(const shapesplines::FitContext& context) const override;
#endif
  std::vector<std::pair<const char*, double>> GetNumericSettings() const override
  {
    return { { "Gamma", this->Gamma }, { "Lambda", this->Lambda } };
  }

  int Continuity = C4;
  int Mode = INTERPOLATE;
  int NumberOfKnots = 0;
  bool Automatic = true;
  double Gamma = 1.0;
  double Lambda = 1.0;

private:
  vtkTensionQuinticSplineFilter(const vtkTensionQuinticSplineFilter&) = delete;
  void operator=(const vtkTensionQuinticSplineFilter&) = delete;
};

#endif
