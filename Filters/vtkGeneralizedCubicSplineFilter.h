/**
 * @class   vtkGeneralizedCubicSplineFilter
 * @brief   C2 generalized cubic splines (exponential, trigonometric or
 *          variable-degree tension per span) through each polyline, with
 *          tension raised automatically only where the curve breaks the
 *          shape of the data
 *
 * Each span of the curve lies in span{1, t, u(t), v(t)} (Costantini & Manni,
 * Costantini & Manni (generalized cubics)) with a kind (SpaceKind) and a tension of its own: Polynomial is
 * the classical cubic; Exponential (hyperbolic, tension p >= 0),
 * Trigonometric (0 <= p < pi) and VariableDegree ((1 - t)^k, k >= 3) tend to
 * the cubic at zero tension (degree 3) and to the straight segment as the
 * tension grows. The spline is C2 everywhere, interpolates every point,
 * has natural ends (closed lines are periodic), and is solved in O(n).
 *
 * With Automatic on (default) the tension starts at Tension and is
 * raised, span by span, only where the shape audit (Costantini & Manni (VDPS), Definition 1)
 * fails, until no criterion fails or MaxTension is reached (within the
 * bounds of every automatic mode, see vtkShapeSplineFilter): collinear data
 * stay straight, convex data convex, planar data planar, without flattening
 * the rest of the curve. Off, every span gets Tension.
 *
 * Output: the contract of vtkShapeSplineFilter, plus the point array Tension
 * (the tension of each sample's span; the degree for VariableDegree) and the
 * cell array MaxTension.
 *
 * @sa vtkShapeSplineFilter vtkCubicSplineFilter vtkPolylineShapeAnalysis
 */
#ifndef vtkGeneralizedCubicSplineFilter_h
#define vtkGeneralizedCubicSplineFilter_h

#include "ShapeSplinesFiltersModule.h" // for export macro
#include "vtkDeprecation.h"           // for VTK_DEPRECATION
#include "vtkShapeSplineFilter.h"

class SHAPESPLINESFILTERS_EXPORT vtkGeneralizedCubicSplineFilter : public vtkShapeSplineFilter
{
public:
  static vtkGeneralizedCubicSplineFilter* New();
  vtkTypeMacro(vtkGeneralizedCubicSplineFilter, vtkShapeSplineFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SpaceKindType
  {
    POLYNOMIAL = 0,
    EXPONENTIAL = 1,
    TRIGONOMETRIC = 2,
    VARIABLE_DEGREE = 3
  };

  ///@{
  /**
   * The kind of every span's space: POLYNOMIAL (the classical cubic, no
   * tension), EXPONENTIAL (default), TRIGONOMETRIC or VARIABLE_DEGREE.
   */
  vtkSetClampMacro(SpaceKind, int, POLYNOMIAL, VARIABLE_DEGREE);
  vtkGetMacro(SpaceKind, int);
  void SetSpaceKindToPolynomial() { this->SetSpaceKind(POLYNOMIAL); }
  void SetSpaceKindToExponential() { this->SetSpaceKind(EXPONENTIAL); }
  void SetSpaceKindToTrigonometric() { this->SetSpaceKind(TRIGONOMETRIC); }
  void SetSpaceKindToVariableDegree() { this->SetSpaceKind(VARIABLE_DEGREE); }
  const char* GetSpaceKindAsString();
  ///@}

  ///@{
  /**
   * Raise the tension only on spans where the shape audit fails (default
   * on); off, every span gets Tension.
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
  VTK_DEPRECATION("AutomaticTension is deprecated: use Automatic")
  void SetAutomaticTension(bool value) { this->SetAutomatic(value); }
  VTK_DEPRECATION("AutomaticTension is deprecated: use Automatic")
  bool GetAutomaticTension() { return this->GetAutomatic(); }
  VTK_DEPRECATION("AutomaticTension is deprecated: use Automatic")
  void AutomaticTensionOn() { this->AutomaticOn(); }
  VTK_DEPRECATION("AutomaticTension is deprecated: use Automatic")
  void AutomaticTensionOff() { this->AutomaticOff(); }
  ///@}

  ///@{
  /**
   * The tension of every span (fixed) or the starting tension (automatic);
   * default 0, the cubic. For VARIABLE_DEGREE it is the degree (values below
   * 3 mean 3); for TRIGONOMETRIC it is limited to 0.99 pi.
   */
  vtkSetClampMacro(Tension, double, 0.0, 1000.0);
  vtkGetMacro(Tension, double);
  ///@}

  ///@{
  /**
   * The largest tension the automatic mode may reach (default 1000, where
   * an exponential span is within 1e-4 of its chord).
   */
  vtkSetClampMacro(MaxTension, double, 0.0, 1000.0);
  vtkGetMacro(MaxTension, double);
  ///@}

  enum EndConditionType
  {
    NATURAL_ENDS = 0,
    POLYNOMIAL_ENDS = 1
  };

  ///@{
  /**
   * Ends of open lines: POLYNOMIAL_ENDS (default; the second derivative at each
   * end is that of the cubic through the four end points, so the curvature
   * converges up to the ends) or NATURAL_ENDS (zero curvature at both ends, the
   * paper's: an error of the size of the curvature there at any density).
   * Closed lines have no ends.
   */
  vtkSetClampMacro(EndCondition, int, NATURAL_ENDS, POLYNOMIAL_ENDS);
  vtkGetMacro(EndCondition, int);
  void SetEndConditionToNatural() { this->SetEndCondition(NATURAL_ENDS); }
  void SetEndConditionToPolynomial() { this->SetEndCondition(POLYNOMIAL_ENDS); }
  ///@}

  ///@{
  /**
   * The name of an input point array giving a tension per point (empty or
   * "None", the default: none; "None" is what ParaView's panel sends). A span then gets the larger of its two points' tensions
   * (fixed) or starts from it (automatic), instead of Tension; negative or
   * non-finite values fall back to Tension.
   */
  vtkSetStringMacro(TensionArrayName);
  vtkGetStringMacro(TensionArrayName);
  ///@}

protected:
  vtkGeneralizedCubicSplineFilter();
  ~vtkGeneralizedCubicSplineFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

#ifndef __VTK_WRAP__
  shapesplines::BuiltCurve BuildCurve(const shapesplines::FitContext& context) const override;
#endif
  std::vector<std::pair<const char*, double>> GetNumericSettings() const override
  {
    return { { "Tension", this->Tension }, { "MaxTension", this->MaxTension } };
  }
  const char* GetPointValuesArrayName() override;
  bool AdjustsShape() const override { return this->Automatic; }

  int SpaceKind = EXPONENTIAL;
  bool Automatic = true;
  double Tension = 0.0;
  double MaxTension = 1000.0;
  int EndCondition = POLYNOMIAL_ENDS;
  char* TensionArrayName = nullptr;

private:
  vtkGeneralizedCubicSplineFilter(const vtkGeneralizedCubicSplineFilter&) = delete;
  void operator=(const vtkGeneralizedCubicSplineFilter&) = delete;
};

#endif
