// ShapeSplines math core: C3 variable degree splines (Costantini & Manni (VDPS)), quintic-like
// curves whose degrees k_i >= 5 and tensions lambda_i per knot pull them
// towards their control polygon, built by corner cutting from one de Boor
// point per knot.
#ifndef shapesplines_VariableDegreeSpline_h
#define shapesplines_VariableDegreeSpline_h

#include "FitPolyline.h"

#include <array>
#include <vector>

namespace shapesplines
{
/// The smallest degree of the space (k = 5 everywhere is the quintic spline).
constexpr double LowestVariableDegree = 5.0;
/// The highest degree a knot takes (the filters' Max Degree and Degree Array
/// values are capped here: beyond, powers (1 - v)^k underflow on most of a span).
constexpr double HighestVariableDegree = 1000.0;

/**
 * The pseudo Bernstein basis B_0..B_5 of VP_{k,m} (degree k at the interval's
 * left knot, m at its right one) at the local parameter v in [0, 1]: entry
 * [j][n] is the n-th derivative of B_j (n <= order; the others are left 0).
 * B0 = (1-v)^k, B1 = k v (1-v)^(k-1),
 * B4 = m v^(m-1) (1-v), B5 = v^m; B2, B3 complete the partition of unity
 * with linear precision at the abscissae 0, 1/k, 2/k, 1-2/m, 1-1/m, 1.
 * k = m = 5 is the quintic Bernstein basis. Powers of 1 - v go through
 * log1p, so no precision is lost near v = 0 for degrees in the hundreds.
 */
std::array<Jet, 6> pseudoBernstein(double k, double m, double v, int order = 4);

/// End conditions of an open interpolating curve.
enum class VariableDegreeEnds : int
{
  /// s'' = s''' = 0 at both ends: zero curvature and torsion there (the
  /// paper's natural-like ends, imposed directly). As the end degrees grow
  /// and lambda falls the ends stop depending on D_-2, D_-1 (Theorem 2) and
  /// the system becomes ill-conditioned (1e8 with all degrees 200), unless
  /// lambda falls slower at the two knots next to each end (the builder's
  /// choice: 5 / k there).
  Natural = 0,
  /// D_-2 = D_-1 = D_0 and D_m+2 = D_m+1 = D_m: the ends depend on the end
  /// data only (the paper's "very simple" ends); well-conditioned at any degree.
  Clamped = 1,
  /// s'' and s''' at each end are those of the quintic through the six end
  /// points, times (5 / k)^3 for the end knot's degree k: at degree 5 the
  /// curvature and torsion converge up to the ends (natural and clamped ends
  /// put an error of the size of the curvature there, at any density), and
  /// as the degree grows they fade to the natural ends of the straight
  /// limit. The same system as Natural, with a right-hand side.
  Polynomial = 2
};

/// Degrees k_i >= 5 and tensions lambda_i > 0, one per knot (closed curves:
/// one per distinct point).
struct VariableDegreeParameters
{
  std::vector<double> Degree;
  std::vector<double> Lambda;
};

/**
 * A C3 spline curve of VS_k with one de Boor point D_i per knot (Costantini & Manni (VDPS),
 * section 3): the first corner cutting step of the C4 quintic with a tension
 * lambda_i per knot, then the C3 variable degree step. On span i it is
 * sum_j b_ij B_j((u - u_i) / h_i) with the degrees k_i, k_i+1 of its knots.
 * For all k_i = 5, lambda_i = 1 it is the C4 quintic spline; as the degrees
 * grow and the tensions fall it tends to the de Boor (and data) polygon.
 * Beyond the ends of an open curve, spacings, degrees and tensions are
 * mirrored about the end knot, so reversing a curve reverses its construction.
 */
class VariableDegreeSpline final : public Curve
{
public:
  /**
   * The spline from its de Boor points: D_-2..D_m+2 (m + 5 points) for an
   * open curve on knots u_0..u_m, D_0..D_m-1 for a closed one.
   */
  static VariableDegreeSpline fromDeBoor(const std::vector<double>& knots, bool closed,
    const VariableDegreeParameters& parameters, const std::vector<Vec3>& deBoor);

  /// The spline through points at knots (closed: knots has the closing knot too).
  static VariableDegreeSpline interpolate(const std::vector<Vec3>& points,
    const std::vector<double>& knots, bool closed, const VariableDegreeParameters& parameters,
    VariableDegreeEnds ends = VariableDegreeEnds::Natural);

  /**
   * Section 4.2: the spline on knots closest in least squares to points at
   * parameters u, plus weight_i |s(knot_i) - anchors_i|^2 per knot (the
   * weighted local scheme; all weights 0 is the global one). Open: a weight
   * and an anchor per knot, and clamped ends (D_-2 = D_-1 = D_0: Theorem 4's
   * polygon limit ends at psi's ends) or free ones (the classical quintic's
   * space at degree 5: clamping straightens the ends of the few spans noisy
   * points take; the builder's choice, with knots beyond the data's ends,
   * see extendForApproximation). Closed: knots end with the closing
   * one, a weight and an anchor per distinct knot, and u may hold the closing
   * parameter after the points'.
   */
  static VariableDegreeSpline approximate(const std::vector<Vec3>& points,
    const std::vector<double>& u, const std::vector<double>& knots, bool closed,
    const VariableDegreeParameters& parameters, const std::vector<double>& weights,
    const std::vector<Vec3>& anchors, bool clampedEnds = true);

  Derivatives evaluateOnSpan(int span, double u, int order) const override;
  /// "Degree" per span: the larger degree of its two knots (cell summary MaxDegree).
  std::vector<SpanParameter> spanParameters() const override;

  const VariableDegreeParameters& parameters() const { return this->Parameters; }
  const std::vector<Vec3>& deBoorPoints() const { return this->DeBoor; }

private:
  VariableDegreeSpline(std::vector<double> knots, bool closed);
  void setNet();

  VariableDegreeParameters Parameters;
  std::vector<Vec3> DeBoor;
  std::vector<std::array<Vec3, 6>> Net; ///< per span, the pseudo Bezier points b_i0..b_i5
  /// Per span of degree 5 at both knots, a quintic Bezier span: its power
  /// form (bezierToPower), evaluated without the pseudo Bernstein basis.
  std::vector<std::array<Vec3, 6>> QuinticPower;
  std::vector<char> Quintic;
};

enum class VariableDegreeMode : int
{
  Interpolate = 0,
  ApproximateGlobal = 1, ///< least squares; automatic mode raises every degree together
  ApproximateLocal = 2   ///< weighted least squares; automatic mode works span by span
};

struct VariableDegreeOptions
{
  VariableDegreeMode Mode = VariableDegreeMode::Interpolate;
  VariableDegreeEnds Ends = VariableDegreeEnds::Polynomial;
  /// Raise degrees only at knots of spans that fail the shape audit, from
  /// Degree, until none fails or MaxDegree is reached.
  bool Automatic = true;
  double Degree = 5.0; ///< starting (automatic) or fixed degree
  /// The polygon limit is slow (distance ~ 1/k): Akima's flat run needs
  /// degree 200 at the knots where it ends to stay straight within 1e-3.
  double MaxDegree = 1000.0;
  /// lambda_i = Lambda (5 / k_i)^3 when ScaleLambdaWithDegree, else Lambda;
  /// with natural or polynomial ends the two knots next to each end take Lambda (5 / k_i),
  /// so that s'' = s''' = 0 there stays well-posed (condition 770 instead of
  /// 1.7e8 with all degrees 200) while the end spans still tend to their
  /// chords (with Lambda kept there, a random polyline's span 2 kept a
  /// convexity violation at any degree).
  /// k = 5, Lambda = 1 is the quintic, and the polygon limit needs lambda -> 0
  /// as k grows (Theorem 2; with lambda fixed the curve moves away from the
  /// data polygon). Measured on Akima, RPN 15A, titanium and a helix running
  /// into a line, the cube removes every shape violation at the lowest
  /// degrees of the powers 1, 1.5, 2, 3 (the paper's Figure 5 uses 1/k).
  double Lambda = 1.0;
  bool ScaleLambdaWithDegree = true;
  /// Approximation modes: the number of knots (at least 2, at most half the
  /// points), or CrossValidatedKnots: as many as generalized cross-validation
  /// chooses for the start degree.
  int ApproximationKnots = 0;
  /// Approximations: correct the points' parameters towards the curve
  /// (planApproximation) rather than keep the given ones.
  bool CorrectParameters = true;
  int MaxRounds = 64;
};

/// The degree after one automatic step: x 2^(1/3), rounded up (a whole
/// degree), within MaxDegree. Doubling overshot: random polylines kept 27
/// violations on 200 (19 now), whose next step bent a knot beyond the
/// curvature bound, and noisy helices took 1.2x the time (higher degrees,
/// steeper speeds) and 20x the curvature.
double raisedDegree(double degree, double maxDegree);

/**
 * Builder of variable degree splines, fixed or automatic. The context's
 * PointValues, if any, are starting degrees per point (values below 5 or
 * not finite count as Degree).
 */
CurveBuilder variableDegreeBuilder(const VariableDegreeOptions& options);
} // namespace shapesplines

#endif
