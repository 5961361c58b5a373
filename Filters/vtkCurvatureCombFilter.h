/**
 * @class   vtkCurvatureCombFilter
 * @brief   the curvature comb (porcupine) or torsion comb of curves made by
 *          the ShapeSplines filters: how designers judge a curve's fairness
 *
 * For every StrideTH sample of each input line, a tooth: a segment from the
 * sample along -Normal (away from the centre of curvature) of length
 * scale * Curvature, or, for the torsion comb, along Binormal of length
 * scale * Torsion (negative torsion points the other way). With Envelope on,
 * a polyline joins the tips of each line's teeth: a fair curve has a smooth
 * envelope, an inflection shows as the comb changing sides, a wiggle as a
 * ripple of the envelope.
 *
 * The input needs the point arrays Curvature and Normal (curvature comb) or
 * Torsion and Binormal (torsion comb), as every ShapeSplines curve filter
 * writes them. With ScaleMode AUTOMATIC the 95th percentile tooth (in length)
 * is RelativeToothLength times the bounding-box diagonal of the input, so one
 * spike does not shrink the rest of the comb; the few teeth beyond are longer.
 *
 * Output: the sample points and the tooth tips; cells: the teeth (two-point
 * lines), then the envelopes. Point array CombValue (the curvature or
 * torsion), cell array CombPart (0 tooth, 1 envelope), and field data
 * CombScale (the scale used).
 *
 * @sa vtkShapeSplineFilter
 */
#ifndef vtkCurvatureCombFilter_h
#define vtkCurvatureCombFilter_h

#include "ShapeSplinesFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class SHAPESPLINESFILTERS_EXPORT vtkCurvatureCombFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkCurvatureCombFilter* New();
  vtkTypeMacro(vtkCurvatureCombFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum CombTypes
  {
    CURVATURE = 0,
    TORSION = 1
  };

  enum ScaleModes
  {
    AUTOMATIC = 0,
    FIXED = 1
  };

  ///@{
  /**
   * Curvature comb along -Normal (default) or torsion comb along Binormal.
   */
  vtkSetClampMacro(CombType, int, CURVATURE, TORSION);
  vtkGetMacro(CombType, int);
  void SetCombTypeToCurvature() { this->SetCombType(CURVATURE); }
  void SetCombTypeToTorsion() { this->SetCombType(TORSION); }
  ///@}

  ///@{
  /**
   * AUTOMATIC (default): the 95th percentile tooth is RelativeToothLength
   * times the input's bounding-box diagonal. FIXED: tooth length =
   * ScaleFactor * value.
   */
  vtkSetClampMacro(ScaleMode, int, AUTOMATIC, FIXED);
  vtkGetMacro(ScaleMode, int);
  void SetScaleModeToAutomatic() { this->SetScaleMode(AUTOMATIC); }
  void SetScaleModeToFixed() { this->SetScaleMode(FIXED); }
  ///@}

  ///@{
  /**
   * The 95th percentile tooth over the bounding-box diagonal in AUTOMATIC
   * mode. Default 0.15.
   */
  vtkSetClampMacro(RelativeToothLength, double, 1e-6, 100.0);
  vtkGetMacro(RelativeToothLength, double);
  ///@}

  ///@{
  /**
   * Tooth length per unit of curvature (or torsion) in FIXED mode, in squared
   * input units. Default 1.
   */
  vtkSetClampMacro(ScaleFactor, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ScaleFactor, double);
  ///@}

  ///@{
  /**
   * A tooth at every Stride-th sample of a line (and at its last). Default 1.
   */
  vtkSetClampMacro(Stride, int, 1, 1000000);
  vtkGetMacro(Stride, int);
  ///@}

  ///@{
  /**
   * Join the tips of each line's teeth by a polyline. On by default.
   */
  vtkSetMacro(Envelope, bool);
  vtkGetMacro(Envelope, bool);
  vtkBooleanMacro(Envelope, bool);
  ///@}

protected:
  vtkCurvatureCombFilter();
  ~vtkCurvatureCombFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int CombType = CURVATURE;
  int ScaleMode = AUTOMATIC;
  double RelativeToothLength = 0.15;
  double ScaleFactor = 1.0;
  int Stride = 1;
  bool Envelope = true;

private:
  /// Tooth length per unit of value: ScaleFactor, or in AUTOMATIC mode the one
  /// that makes the typical value's tooth RelativeToothLength of the diagonal.
  double ToothScale(double typicalValue, double diagonal) const;

  vtkCurvatureCombFilter(const vtkCurvatureCombFilter&) = delete;
  void operator=(const vtkCurvatureCombFilter&) = delete;
};

#endif
