/**
 * @class   vtkQQRSplineFilter
 * @brief   C2 cubic B-spline-like curves on the quartic qqr basis (two
 *          exponential shape parameters, three local ones) through or near
 *          each polyline
 *
 * Wang and Zhang's qqr curves ("Curve construction based on quartic
 * Bernstein-like basis", AIMS Mathematics 2020): every span is a quartic
 * Bernstein-like curve with exponents alpha, beta; joined, they form cubic
 * B-spline-like curves with local shape parameters x, y, z. With
 * alpha = beta = 4 and the paper's local parameters they are the classical
 * cubic B-splines.
 *
 * Mode INTERPOLATE (default) solves for the control points so that the
 * curve passes through every point: at the defaults it is the classical
 * cubic spline interpolant with not-a-knot ends, and its curvature and
 * torsion converge at second order. Mode LOCAL_INTERPOLATION is the paper's
 * section 3.6: every point is passed through with tangents and second
 * derivatives from its two neighbours only, no system solved, so editing a
 * point changes four spans at most; a shape design tool, not an estimator:
 * its second derivative at a point is 4 (alpha - 1) / alpha times the second
 * difference (3 times at alpha = 4), so curvature at the points is about
 * three times too large and does not converge as points are added. Mode
 * APPROXIMATE takes the points as the control polygon (the classical cubic
 * B-spline curve at the defaults; shape violations are counted against the
 * polygon).
 *
 * With Automatic on (default), the spans where the shape audit (Costantini
 * and Manni, Definition 1) fails are moved towards their chords, step by
 * step, through the local parameters around them (straightness 1: on the
 * chord, the joins still C2), and the exponent is raised where a straight
 * run of the points ends in a turn; where violations remain, the curve is
 * flattened at the knots of the spans that fail only torsion signs
 * (flattening 1: no curvature at the knot, the joins still C2) and
 * straightened again from the flattened curve; the curve with the fewest
 * violations is kept, within the bounds of the automatic modes (no cusp,
 * no span far from its data); what that cannot remove is reported (two
 * neighbouring spans cannot both be straight where the points turn). Continuity C2_FC
 * (approximation) sets x = y = 0 and alpha = beta >= FrenetOrder + 3: C2 and
 * Frenet frame continuous to order 2 FrenetOrder + 3 (Theorem 13).
 *
 * Output: the contract of vtkShapeSplineFilter, plus the point arrays Alpha
 * (the larger exponent of each sample's span), Straightness (how far the
 * automatic mode moved the span towards its chord, 0 to 1) and Flattening
 * (how far it flattened the curve at the span's knots, 0 to 1) and the cell
 * arrays MaxAlpha, MaxStraightness and MaxFlattening.
 *
 * @sa vtkShapeSplineFilter vtkCubicSplineFilter
 */
#ifndef vtkQQRSplineFilter_h
#define vtkQQRSplineFilter_h

#include "ShapeSplinesFiltersModule.h" // for export macro
#include "vtkShapeSplineFilter.h"

class SHAPESPLINESFILTERS_EXPORT vtkQQRSplineFilter : public vtkShapeSplineFilter
{
public:
  static vtkQQRSplineFilter* New();
  vtkTypeMacro(vtkQQRSplineFilter, vtkShapeSplineFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ModeType
  {
    INTERPOLATE = 0,
    APPROXIMATE = 1,
    LOCAL_INTERPOLATION = 2
  };

  enum LocalParametersType
  {
    PAPER = 0,
    CUSTOM = 1
  };

  enum ContinuityType
  {
    C2 = 0,
    C2_FC = 1
  };

  ///@{
  /**
   * INTERPOLATE (default; the curve through the points, control points
   * solved), APPROXIMATE (the points are the control polygon) or
   * LOCAL_INTERPOLATION (section 3.6: no solve, curvature 3x off).
   */
  vtkSetClampMacro(Mode, int, INTERPOLATE, LOCAL_INTERPOLATION);
  vtkGetMacro(Mode, int);
  void SetModeToInterpolate() { this->SetMode(INTERPOLATE); }
  void SetModeToApproximate() { this->SetMode(APPROXIMATE); }
  void SetModeToLocalInterpolation() { this->SetMode(LOCAL_INTERPOLATION); }
  const char* GetModeAsString();
  ///@}

  ///@{
  /**
   * Move the spans where the shape audit fails towards their chords (and
   * raise the exponent where a straight run ends in a turn) and, where that
   * leaves violations, flatten the curve at the knots of spans whose torsion
   * sign fails, within the automatic modes' bounds (default on); off, Alpha
   * and Beta everywhere with the local parameters as given.
   */
  vtkSetMacro(Automatic, bool);
  vtkGetMacro(Automatic, bool);
  vtkBooleanMacro(Automatic, bool);
  ///@}

  ///@{
  /**
   * The exponents of the qqr basis (default 4 and 4, at least 2; above 3 for
   * a positive basis and C2 joins, at least 4 for a torsion bounded at the
   * knots). Automatic mode starts from the larger.
   */
  vtkSetClampMacro(Alpha, double, 2.0, 200.0);
  vtkGetMacro(Alpha, double);
  vtkSetClampMacro(Beta, double, 2.0, 200.0);
  vtkGetMacro(Beta, double);
  ///@}

  ///@{
  /**
   * The largest exponent the automatic mode may reach (default 200), at
   * the turns that end straight runs of the points.
   */
  vtkSetClampMacro(MaxAlpha, double, 2.0, 200.0);
  vtkGetMacro(MaxAlpha, double);
  ///@}

  ///@{
  /**
   * PAPER (default): the local parameters given before the paper's Figure 5
   * (the classical cubic B-spline at alpha = beta = 4); CUSTOM: X, Y, Z at
   * every knot, each in [0, 1] (NaN is refused when the filter runs). X and
   * Y shape the control polygon's curve (APPROXIMATE); the interpolations
   * use Z only (LOCAL_INTERPOLATION takes x and y from (3.18), INTERPOLATE
   * keeps the paper's).
   */
  vtkSetClampMacro(LocalParameters, int, PAPER, CUSTOM);
  vtkGetMacro(LocalParameters, int);
  void SetLocalParametersToPaper() { this->SetLocalParameters(PAPER); }
  void SetLocalParametersToCustom() { this->SetLocalParameters(CUSTOM); }
  vtkSetClampMacro(X, double, 0.0, 1.0);
  vtkGetMacro(X, double);
  vtkSetClampMacro(Y, double, 0.0, 1.0);
  vtkGetMacro(Y, double);
  vtkSetClampMacro(Z, double, 0.0, 1.0);
  vtkGetMacro(Z, double);
  ///@}

  ///@{
  /**
   * The name of an input point array giving the local bias z per point
   * (empty or "None", the default: none), used instead of the Local
   * Parameters' z (fixed) or as the automatic search's start; values
   * outside [0, 1] or not finite fall back to them.
   */
  vtkSetStringMacro(ZArrayName);
  vtkGetStringMacro(ZArrayName);
  ///@}

  ///@{
  /**
   * C2 (default) or C2_FC: in APPROXIMATE mode x = y = 0 and
   * alpha = beta >= FrenetOrder + 3, so the curve is C2 and Frenet frame
   * continuous of order 2 FrenetOrder + 3 (Theorem 13). FrenetOrder is l >= 1.
   */
  vtkSetClampMacro(Continuity, int, C2, C2_FC);
  vtkGetMacro(Continuity, int);
  void SetContinuityToC2() { this->SetContinuity(C2); }
  void SetContinuityToC2FC() { this->SetContinuity(C2_FC); }
  vtkSetClampMacro(FrenetOrder, int, 1, 100);
  vtkGetMacro(FrenetOrder, int);
  ///@}

protected:
  vtkQQRSplineFilter();
  ~vtkQQRSplineFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

#ifndef __VTK_WRAP__
  shapesplines::BuiltCurve BuildCurve(const shapesplines::FitContext& context) const override;
#endif
  std::vector<std::pair<const char*, double>> GetNumericSettings() const override
  {
    return { { "Alpha", this->Alpha }, { "Beta", this->Beta }, { "MaxAlpha", this->MaxAlpha }, { "X", this->X }, { "Y", this->Y }, { "Z", this->Z } };
  }
  const char* GetPointValuesArrayName() override;
  bool AdjustsShape() const override { return this->Automatic; }
  bool GathersBendsAtKnots() const override { return false; }

  int Mode = INTERPOLATE;
  bool Automatic = true;
  double Alpha = 4.0;
  double Beta = 4.0;
  double MaxAlpha = 200.0;
  int LocalParameters = PAPER;
  double X = 0.0;
  double Y = 0.0;
  double Z = 0.5;
  int Continuity = C2;
  int FrenetOrder = 1;
  char* ZArrayName = nullptr;

private:
  vtkQQRSplineFilter(const vtkQQRSplineFilter&) = delete;
  void operator=(const vtkQQRSplineFilter&) = delete;
};

#endif
