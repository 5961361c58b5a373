/**
 * @class   vtkVariableDegreeSplineFilter
 * @brief   C3 variable degree splines through (or near) each polyline, with
 *          degrees raised automatically only where the curve breaks the
 *          shape of the data
 *
 * Costantini & Manni's quintic-like variable degree polynomial splines (VDPS): on
 * each span the curve lies in span{1 - v, v, (1 - v)^k_i, v (1 - v)^(k_i - 1),
 * v^(k_i+1 - 1) (1 - v), v^k_i+1} with a degree k_i >= 5 per knot, built by
 * corner cutting from one de Boor point per knot with a tension lambda_i per
 * knot. All degrees 5 and lambda 1 is the C4 quintic spline; otherwise the
 * curve is C3, and as degrees grow (and lambda falls) it tends to the data
 * polygon. Systems are banded (periodic for closed lines): O(n).
 *
 * Mode INTERPOLATE (default) passes through every point. With
 * Automatic on (default) the degrees start at Degree and are doubled
 * only at the knots of spans where the shape audit (Costantini & Manni (VDPS), Definition 1)
 * fails, until none fails or MaxDegree is reached, within the bounds of
 * every automatic mode (see vtkShapeSplineFilter). The APPROXIMATE modes
 * (lines with at least four points, six when closed; shorter ones are
 * interpolated with a warning) fit NumberOfKnots knots (0, the default:
 * chosen per line by cross-validation) uniform in the parameters (on
 * lines it smooths, weighted by the curvature of a first fit where that
 * scores better, or as well with fewer knots), which CorrectParameters
 * moves to where each point sits on the curve, in least squares, and keep the shape of psi, the best piecewise linear
 * least-squares fit, where it stands out of the noise (changing the
 * curvature by at most 2x): GLOBAL raises every degree together, LOCAL
 * raises degrees and pulls the curve towards psi (weighted least squares)
 * only at failing spans.
 *
 * Output: the contract of vtkShapeSplineFilter, plus the point array Degree
 * (the larger degree of each sample's span) and the cell array MaxDegree.
 *
 * @sa vtkShapeSplineFilter vtkTensionQuinticSplineFilter vtkGeneralizedCubicSplineFilter
 */
#ifndef vtkVariableDegreeSplineFilter_h
#define vtkVariableDegreeSplineFilter_h

#include "ShapeSplinesFiltersModule.h" // for export macro
#include "vtkDeprecation.h"           // for VTK_DEPRECATION
#include "vtkShapeSplineFilter.h"

class SHAPESPLINESFILTERS_EXPORT vtkVariableDegreeSplineFilter : public vtkShapeSplineFilter
{
public:
  static vtkVariableDegreeSplineFilter* New();
  vtkTypeMacro(vtkVariableDegreeSplineFilter, vtkShapeSplineFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ModeType
  {
    INTERPOLATE = 0,
    APPROXIMATE_GLOBAL = 1,
    APPROXIMATE_LOCAL = 2
  };

  enum EndConditionType
  {
    NATURAL = 0,
    CLAMPED = 1,
    POLYNOMIAL = 2
  };

  ///@{
  /**
   * INTERPOLATE (default), APPROXIMATE_GLOBAL or APPROXIMATE_LOCAL (least
   * squares with NumberOfKnots knots; section 4.2 of the paper).
   */
  vtkSetClampMacro(Mode, int, INTERPOLATE, APPROXIMATE_LOCAL);
  vtkGetMacro(Mode, int);
  void SetModeToInterpolate() { this->SetMode(INTERPOLATE); }
  void SetModeToApproximateGlobal() { this->SetMode(APPROXIMATE_GLOBAL); }
  void SetModeToApproximateLocal() { this->SetMode(APPROXIMATE_LOCAL); }
  const char* GetModeAsString();
  ///@}

  ///@{
  /**
   * Knots of the approximation (1 counts as 2), or 0 (default): chosen per
   * line from the data by generalized cross-validation (Craven and Wahba) on
   * parameters corrected towards the curve, the fewest within half a
   * standard error of the best score (CorrectParameters); lines that this
   * smooths are planned again on parameters weighted by a first fit's
   * curvature, and the better-scoring plan kept (the one with fewer knots
   * where both score within half a standard error of the better's best).
   * Either way at most half the points. The cell arrays NumberOfKnots and
   * NoiseLevel report what each line got.
   */
  vtkSetClampMacro(NumberOfKnots, int, 0, 1000000);
  vtkGetMacro(NumberOfKnots, int);
  ///@}

  ///@{
  /**
   * Raise degrees only at knots of spans where the shape audit fails
   * (default on); off, every knot gets Degree.
   */
  vtkSetMacro(Automatic, bool);
  vtkGetMacro(Automatic, bool);
  vtkBooleanMacro(Automatic, bool);
  ///@}

  ///@{
  /**
   * Deprecated: the old name of Automatic (each family named its switch after
   * its parameter until they shared one); forwards to it, so that older code
   * and pvpython scripts keep working.
   */
  VTK_DEPRECATION("AutomaticDegrees is deprecated: use Automatic")
  void SetAutomaticDegrees(bool value) { this->SetAutomatic(value); }
  VTK_DEPRECATION("AutomaticDegrees is deprecated: use Automatic")
  bool GetAutomaticDegrees() { return this->GetAutomatic(); }
  VTK_DEPRECATION("AutomaticDegrees is deprecated: use Automatic")
  void AutomaticDegreesOn() { this->AutomaticOn(); }
  VTK_DEPRECATION("AutomaticDegrees is deprecated: use Automatic")
  void AutomaticDegreesOff() { this->AutomaticOff(); }
  ///@}

  ///@{
  /**
   * The degree of every knot (fixed) or the starting degree (automatic);
   * default 5, the quintic.
   */
  vtkSetClampMacro(Degree, double, 5.0, 1000.0);
  vtkGetMacro(Degree, double);
  ///@}

  ///@{
  /**
   * The largest degree the automatic mode may reach (default 200: the
   * polygon limit is slow, and Akima's flat run needs 200 to stay straight).
   */
  vtkSetClampMacro(MaxDegree, double, 5.0, 1000.0);
  vtkGetMacro(MaxDegree, double);
  ///@}

  ///@{
  /**
   * The tension lambda of the first corner cutting step (default 1). With
   * ScaleLambdaWithDegree on (default) knot i gets Lambda (5 / k_i)^3, so
   * degree 5 is the quintic and lambda falls as the degree rises, which the
   * polygon limit needs (the paper's Figure 5 uses 1/k; the cube reaches the
   * data's shape at lower degrees); off, every knot gets Lambda.
   */
  vtkSetClampMacro(Lambda, double, 0.001, 10.0);
  vtkGetMacro(Lambda, double);
  vtkSetMacro(ScaleLambdaWithDegree, bool);
  vtkGetMacro(ScaleLambdaWithDegree, bool);
  vtkBooleanMacro(ScaleLambdaWithDegree, bool);
  ///@}

  ///@{
  /**
   * Ends of open interpolating lines: POLYNOMIAL (default; s'' and s''' at
   * each end are those of the quintic through the six end points, faded by
   * (5 / k)^3 as the end degree k grows: curvature and torsion converge up to
   * the ends), NATURAL (zero curvature and torsion at both ends, an error of
   * the size of the curvature there at any density) or CLAMPED (the first
   * and last three de Boor points coincide, so the ends depend on the end
   * points only; neither converges at the ends). With Polynomial and Natural
   * lambda falls as Lambda (5 / k), not (5 / k)^3, at the two knots next to
   * each end, which keeps the system well-conditioned at high degrees.
   * Approximations are always clamped.
   */
  vtkSetClampMacro(EndCondition, int, NATURAL, POLYNOMIAL);
  vtkGetMacro(EndCondition, int);
  void SetEndConditionToNatural() { this->SetEndCondition(NATURAL); }
  void SetEndConditionToClamped() { this->SetEndCondition(CLAMPED); }
  void SetEndConditionToPolynomial() { this->SetEndCondition(POLYNOMIAL); }
  ///@}

  ///@{
  /**
   * The name of an input point array giving a degree per point (empty or
   * "None", the default: none). Interpolation only; values below 5 or not
   * finite fall back to Degree.
   */
  vtkSetStringMacro(DegreeArrayName);
  vtkGetStringMacro(DegreeArrayName);
  ///@}

protected:
  vtkVariableDegreeSplineFilter();
  ~vtkVariableDegreeSplineFilter() override;
  bool Approximates() const override { return this->Mode != INTERPOLATE; }
  bool AdjustsShape() const override { return this->Automatic; }

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

#ifndef __VTK_WRAP__
  shapesplines::BuiltCurve BuildCurve(const shapesplines::FitContext& context) const override;
#endif
  std::vector<std::pair<const char*, double>> GetNumericSettings() const override
  {
    return { { "Degree", this->Degree }, { "MaxDegree", this->MaxDegree }, { "Lambda", this->Lambda } };
  }
  const char* GetPointValuesArrayName() override;

  int Mode = INTERPOLATE;
  int NumberOfKnots = 0;
  bool Automatic = true;
  double Degree = 5.0;
  double MaxDegree = 1000.0;
  double Lambda = 1.0;
  bool ScaleLambdaWithDegree = true;
  int EndCondition = POLYNOMIAL;
  char* DegreeArrayName = nullptr;

private:
  vtkVariableDegreeSplineFilter(const vtkVariableDegreeSplineFilter&) = delete;
  void operator=(const vtkVariableDegreeSplineFilter&) = delete;
};

#endif
