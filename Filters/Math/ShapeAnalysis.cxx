#include "ShapeAnalysis.h"

#include "ExtendedIndex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace shapesplines
{
namespace
{
/// Four points are coplanar where the planes at the two ends of their middle
/// segment turn by at most this fraction of epsilon_2 (and their triple
/// product is below epsilon_1): 400 exact points at random places along a
/// helix had spans whose planes turned by 0.6-0.9 epsilon_2, and the
/// automatic modes bent the curve to 900 times the helix' curvature to keep
/// a planar span there.
constexpr double CoplanarPlaneTurn = 0.1;

/// A segment twisting under this fraction of its neighbours' torsion is
/// near a zero of the torsion: one it crosses where the neighbours twist
/// opposite ways (DiscreteShape::TorsionCrossing), one it touches where they
/// twist its way (ShapeAuditor::twistTolerances).
constexpr double NearZeroTorsionFraction = 1.0 / 3.0;

double sign(double x)
{
  return (x > 0) - (x < 0);
}
} // namespace

const char* shapeCriterionName(ShapeCriterion criterion)
{
  switch (criterion)
  {
    case ShapeCriterion::Collinearity:
      return "collinearity";
    case ShapeCriterion::ConvexityAtKnot:
      return "convexity at knot";
    case ShapeCriterion::ConvexityOnSpan:
      return "convexity on span";
    case ShapeCriterion::Coplanarity:
      return "coplanarity";
    case ShapeCriterion::TorsionSignAtKnot:
      return "torsion sign at knot";
    case ShapeCriterion::TorsionSignOnSpan:
      return "torsion sign on span";
    default:
      return "unknown";
  }
}

namespace
{
/// A turning sine or triple product of unit segments within this of zero is
/// zero but for the rounding of its own arithmetic.
constexpr double ExactlyStraight = 64.0 * std::numeric_limits<double>::epsilon();

/// 10^k, from a table: coordinateSteps asks several per coordinate value.
double powerOfTen(int k)
{
  constexpr int Reach = 400; // beyond a double's exponents either way
  static const std::array<double, 2 * Reach + 1> powers = [] {
    std::array<double, 2 * Reach + 1> table{};
    for (int i = 0; i < static_cast<int>(table.size()); ++i)
    {
      table[i] = std::pow(10.0, i - Reach);
    }
    return table;
  }();
  return powers[std::clamp(k, -Reach, Reach) + Reach];
}

/// The digits a value needs, to within its type's rounding: after the decimal
/// point, and significant ones; -1 where more than were tried.
struct Digits
{
  int Decimals = -1;
  int Significant = -1;
  int Exponent = 0; ///< of its leading digit
};

/// True when value * scale is an integer but for the type's rounding.
bool wholeSteps(double value, double scale, double precision)
{
  const double steps = value * scale;
  return std::abs(steps - std::round(steps)) <= 2.0 * precision * (std::abs(steps) + 1.0);
}

/// The digits value needs, of at most mostDecimals and mostSignificant.
Digits digitsOf(double value, int mostDecimals, int mostSignificant, double precision)
{
  Digits digits;
  if (value == 0.0)
  {
    digits.Decimals = digits.Significant = 0;
    return digits;
  }
  for (int d = 0; d <= mostDecimals && digits.Decimals < 0; ++d)
  {
    if (wholeSteps(value, powerOfTen(d), precision))
    {
      digits.Decimals = d;
    }
  }
  int exponent = static_cast<int>(std::floor(std::log10(std::abs(value))));
  exponent += std::abs(value) >= powerOfTen(exponent + 1) ? 1 : 0;
  exponent -= std::abs(value) < powerOfTen(exponent) ? 1 : 0;
  digits.Exponent = exponent;
  for (int s = 1; s <= mostSignificant && digits.Significant < 0; ++s)
  {
    if (wholeSteps(value, powerOfTen(s - 1 - exponent), precision))
    {
      digits.Significant = s;
    }
  }
  return digits;
}

/// The step one coordinate's values were written with (see coordinateSteps).
double columnStep(const std::vector<double>& values, double precision)
{
  // One value all along (a z-level of a tool path, z = 0 of a planar
  // track) is the line's design, not a measurement's rounding.
  if (std::all_of(values.begin(), values.end(), [&](double value) { return value == values[0]; }))
  {
    return 0.0;
  }
  double largest = 0.0;
  for (const double value : values)
  {
    largest = std::max(largest, std::abs(value));
  }
  // A step is tested only well above the type's rounding, so that a value
  // off the step by that rounding is told from one off by chance (at most an
  // eighth of the step either way: a quarter of random values pass each).
  constexpr double StepOverRounding = 16.0;
  int decimalsTried = static_cast<int>(std::floor(-std::log10(StepOverRounding * precision *
    std::max(largest, std::numeric_limits<double>::min()))));
  int significantTried = static_cast<int>(std::floor(-std::log10(StepOverRounding * precision)));
  std::vector<Digits> digits;
  digits.reserve(values.size());
  for (const double value : values)
  {
    digits.push_back(digitsOf(value, decimalsTried, significantTried, precision));
    // A way one value does not fit is out: not tried on the others.
    decimalsTried = digits.back().Decimals < 0 ? -1 : decimalsTried;
    significantTried = digits.back().Significant < 0 ? 0 : significantTried;
    if (decimalsTried < 0 && significantTried == 0)
    {
      return 0.0;
    }
  }
  // Two ways to write numbers: a fixed number of decimals ("%.3f": the step
  // is the same everywhere) or of significant digits ("%.5e", ParaView's CSV
  // default: the step grows with the value). Either fits the other's
  // numbers with more digits than they show, which few values use: random
  // last digits leave a tenth of the values short of a way's digits, and a
  // way is plausible where at least a quarter use them all.
  struct Way
  {
    int Count = -1; ///< the fewest digits that fit every value, -1: none
    int Full = 0;   ///< nonzero values that use them all
  };
  int nonzero = 0;
  for (const Digits& d : digits)
  {
    nonzero += d.Significant != 0;
  }
  auto fewest = [&](int Digits::*count) {
    Way way;
    for (const Digits& d : digits)
    {
      if (d.*count < 0)
      {
        return Way{};
      }
      way.Count = std::max(way.Count, d.*count);
    }
    for (const Digits& d : digits)
    {
      way.Full += d.Significant != 0 && d.*count == way.Count;
    }
    return way;
  };
  const Way decimals = fewest(&Digits::Decimals);
  const Way significant = fewest(&Digits::Significant);
  constexpr int FewestDecimals = 2, FewestSignificant = 3;
  if (decimals.Count >= 0 && decimals.Count < FewestDecimals)
  {
    return 0.0; // integers, tenths: designed values
  }
  const double decimalStep = decimals.Count >= 0 ? powerOfTen(-decimals.Count) : 0.0;
  if (significant.Count < FewestSignificant || 4 * significant.Full < nonzero ||
    (decimalStep > 0 && significant.Full < decimals.Full))
  {
    return decimalStep;
  }
  int exponent = std::numeric_limits<int>::min();
  for (const Digits& d : digits)
  {
    exponent = d.Significant != 0 ? std::max(exponent, d.Exponent) : exponent;
  }
  // The largest values' step bounds every value's.
  const double significantStep = powerOfTen(exponent - significant.Count + 1);
  // Equally plausible (all values within one decade): the finer step.
  return decimalStep > 0 && significant.Full == decimals.Full
    ? std::min(decimalStep, significantStep)
    : significantStep;
}
} // namespace

Vec3 coordinateSteps(const std::vector<Vec3>& points, double precision)
{
  Vec3 steps = Vec3::Zero();
  std::vector<double> column(points.size());
  for (int axis = 0; axis < 3; ++axis)
  {
    for (size_t i = 0; i < points.size(); ++i)
    {
      column[i] = points[i][axis];
      if (!std::isfinite(column[i]))
      {
        return Vec3::Zero();
      }
    }
    steps[axis] = column.empty() ? 0.0 : columnStep(column, precision);
  }
  return steps;
}

DiscreteShape discreteShape(const CleanPolyline& data, const ShapeTolerances& tolerances,
  const std::vector<double>& vertexNoise, double coordinateNoise, const Vec3& roundingSteps)
{
  // Each coordinate rounded by up to half its step.
  const double roundingReach = 0.5 * roundingSteps.norm();
  const int n = static_cast<int>(data.Points.size());
  // How far segment i's direction turns with its vertices' noise, times its length.
  auto noise = [&](int i) { return std::max(vertexNoise.empty() ? 0.0 : vertexNoise[i], coordinateNoise); };
  auto segmentNoise = [&](int i) { return noise(i) + noise((i + 1) % n); };
  const int spans = data.numberOfSpans();
  DiscreteShape shape;
  shape.Binormal.assign(n, Vec3::Zero());
  shape.Curvature.assign(n, 0.0);
  shape.Collinear.assign(n, 0);
  shape.Convex.assign(n, 0);
  shape.Reversal.assign(n, 0);
  shape.Torsion.assign(std::max(spans, 0), 0.0);
  shape.Coplanar.assign(std::max(spans, 0), 0);
  shape.Twisted.assign(std::max(spans, 0), 0);
  std::vector<char> latticePlane(std::max(spans, 0), 0); // coplanar only by being exactly so
  auto interior = [&](int i) { return data.Closed || (i > 0 && i < n - 1); };

  // Unit segments and lengths by stableNorm: products of raw lengths under- or
  // overflow for coordinates of 1e-160 or 1e160.
  std::vector<Vec3> unit(std::max(spans, 0));
  std::vector<double> length(std::max(spans, 0));
  std::vector<char> straightAt(n, 0); // B_i = 0 within epsilon_1: no plane at point i
  for (int i = 0; i < spans; ++i)
  {
    const Vec3 segment = data.segment(i);
    length[i] = segment.stableNorm();
    unit[i] = length[i] > 0 ? Vec3(segment / length[i]) : Vec3::Zero();
  }
  for (int i = 0; i < n; ++i)
  {
    const int before = (i - 1 + n) % n;
    if (!interior(i) || !(length[before] > 0 && length[i] > 0))
    {
      continue;
    }
    shape.Binormal[i] = unit[before].cross(unit[i]);
    // Menger curvature: 1 / radius of the circle through the three points.
    const double chord = (data.segment(before) + data.segment(i)).stableNorm();
    // A line that doubles back exactly (I_{i+1} = I_{i-1}) has no circle: 0, not 0/0.
    shape.Curvature[i] = chord > 0 ? 2.0 * shape.Binormal[i].norm() / chord : 0.0;
    const double turn = shape.Binormal[i].norm();
    const bool straight = turn <= tolerances.Data;
    straightAt[i] = straight;
    // What the vertices' noise can do to the turning sine: both directions turn.
    const double noiseTurn = segmentNoise(before) / length[before] + segmentNoise(i) / length[i];
    // The most the written digits' rounding can do to it (a bound, not a spread).
    const double roundingTurn = 2.0 * roundingReach * (1.0 / length[before] + 1.0 / length[i]);
    const bool significant = turn > NoiseSignificance * noiseTurn && turn > roundingTurn;
    // Straight within epsilon_1 by the rounding's chance is no straight run
    // either; exactly straight is (a run along the digits' lattice).
    const bool byChance = roundingTurn > tolerances.Data && turn > ExactlyStraight;
    shape.Collinear[i] = straight && !byChance && unit[before].dot(unit[i]) > 0;
    shape.Reversal[i] = straight && unit[before].dot(unit[i]) < 0;
    shape.Convex[i] = !straight && significant;
  }
  // Between points that turn opposite ways the curve has an inflection. A
  // lone collinear point there is one sampled symmetrically (points of a
  // smooth curve evenly spaced around it): the curve is not straight on its
  // two spans, so (i) does not apply; a straight run has two collinear
  // points in a row, or turns the same way at both ends. A point whose
  // curvature is under half that of its neighbour turning the other way
  // (Menger curvatures, free of the spacing) has the inflection within about
  // a third of a span, and a spline (or the Menger curvature of unevenly
  // spaced points) puts it up to a span off: no convexity criterion at it or
  // on its two spans, the curvature may change sign anywhere on them.
  // Decided on the flags as measured, so that the data's order does not matter.
  const std::vector<char> convex = shape.Convex;
  for (int i = 0; i < n; ++i)
  {
    const int before = i - 1, after = i + 1;
    if (!data.Closed && (before < 1 || after > n - 2))
    {
      continue;
    }
    const int b = (before + n) % n, a = after % n;
    // Opposite beyond rounding: the corners of a 3D staircase turn in
    // perpendicular planes, whose binormals' product is 0 or +-1e-17 by orientation.
    const Vec3& turnBefore = shape.Binormal[b];
    const Vec3& turnAfter = shape.Binormal[a];
    if (!convex[b] || !convex[a] ||
      turnBefore.dot(turnAfter) >= -tolerances.Data * turnBefore.norm() * turnAfter.norm())
    {
      continue;
    }
    if (shape.Collinear[i])
    {
      shape.Collinear[i] = 0;
      continue;
    }
    // The neighbour turning most against it (in 3D a point can turn partly
    // with both, or against both): chosen by angle, whatever the data's order.
    auto cosine = [&](int k) {
      const double norms = shape.Binormal[i].norm() * shape.Binormal[k].norm();
      return norms > 0.0 ? shape.Binormal[i].dot(shape.Binormal[k]) / norms : 0.0;
    };
    const int opposite = cosine(b) < cosine(a) ? b : a;
    if (convex[i] && 2.0 * shape.Curvature[i] < shape.Curvature[opposite])
    {
      shape.Convex[i] = 0;
    }
  }
  for (int i = 0; i < spans; ++i)
  {
    const int before = (i - 1 + n) % n;
    const int next = (i + 1) % n;
    // A segment with no plane at an end (a straight run, a line running
    // back) gets no coplanarity or torsion criterion: (i) asks the curve to be
    // straight there, and its triple product is rounding over rounding, 0 on
    // axis-aligned points and a torsion of any size and sign once rotated.
    if (!interior(i) || !interior(next) || straightAt[i] || straightAt[next])
    {
      continue;
    }
    // Delta_i = det(L_{i-1}, L_i, L_{i+1}) / (|L_{i-1} x L_i| |L_i x L_{i+1}|),
    // written with unit segments: det(a, b, c) / (|L_i| |a x b| |b x c|).
    const Vec3& a = unit[before];
    const Vec3& b = unit[i];
    const Vec3& c = unit[next];
    const double triple = a.dot(b.cross(c));
    const Vec3 ab = a.cross(b), bc = b.cross(c);
    const double abNorm = ab.norm(), bcNorm = bc.norm();
    const double crosses = abNorm * bcNorm;
    // Close points on a twisting curve have a tiny triple product (third
    // order in their spacing) while the planes at their ends turn by more
    // than the audit lets a curve's binormal turn (epsilon_2): such data are
    // not coplanar at the audit's resolution. Nor where the planes turn by
    // a little less: the binormal of a curve through them turns by as much
    // along the span, and the audit would fail it.
    const double flatness =
      std::min(tolerances.Data, CoplanarPlaneTurn * tolerances.Curve * crosses);
    const bool flat = std::abs(triple) <= flatness || !(crosses > 0);
    // What the vertices' noise can do to the triple product: each of the
    // three directions turns by about noise / length out of the others' plane.
    auto twistBy = [&](const auto& moved) {
      return bcNorm * moved(before) / length[before] + (abNorm + bcNorm) * moved(i) / length[i] +
        abNorm * moved(next) / length[next];
    };
    const double noiseTwist = twistBy(segmentNoise);
    // Rounding twists the segments by moving points out of their plane: by
    // up to half of each axis's step along the plane's normal (none out of a
    // plane z = 0 whose z are designed).
    const Vec3 normal = (abNorm >= bcNorm ? ab : bc).normalized();
    const double outOfPlane = 0.5 * normal.cwiseAbs().dot(roundingSteps);
    const double roundingTwist = twistBy([&](int) { return 2.0 * outOfPlane; });
    const bool significant =
      std::abs(triple) > NoiseSignificance * noiseTwist && std::abs(triple) > roundingTwist;
    // Planar within the flatness by chance where the rounding (of the
    // decimals, or of floats: short segments far from the origin) can move
    // the triple product beyond it.
    const double floatTwist = twistBy([&](int) { return 2.0 * coordinateNoise; });
    const bool roundingCanTwist = std::max(roundingTwist, floatTwist) > flatness;
    shape.Torsion[i] = flat ? 0.0 : triple / (length[i] * crosses);
    shape.Coplanar[i] = flat && (!roundingCanTwist || std::abs(triple) <= ExactlyStraight);
    latticePlane[i] = shape.Coplanar[i] && roundingTwist > flatness;
    shape.Twisted[i] = !flat && significant;
  }
  // Rounded points are exactly coplanar by the rounding too: where one
  // coordinate rounds to the same value over a few points (near its
  // extremum) or their second differences round alike. On smooth curves
  // written with six significant digits one segment in twenty was, in runs
  // of up to 7; a designed plane (a z-level of a tool path) holds more.
  constexpr int DesignedPlaneSegments = 8;
  for (int i = 0; i < spans;)
  {
    int end = i;
    while (end < spans && latticePlane[end])
    {
      ++end;
    }
    if (end - i < DesignedPlaneSegments)
    {
      std::fill(shape.Coplanar.begin() + i, shape.Coplanar.begin() + end, 0);
    }
    i = std::max(end, i + 1);
  }
  // Where the segments on either side of one twist opposite ways, the
  // torsion passes through zero near it: by the discrete torsions (a curve's
  // torsion at the segments' middles), within a quarter segment of its
  // middle when the segment's torsion is under a third of the neighbour's
  // of the other sign, or when its points are coplanar (evenly spaced about
  // the zero: no curve twisting on either side is planar along it). There
  // the sign change may happen anywhere from the segment before to the one
  // after (TorsionCrossing): a spline's torsion, one derivative above its
  // curvature, puts its zero up to a segment off (a cubic's torsion steps at
  // every knot).
  // Decided on the flags as measured (two such segments are never next to
  // each other), so that the data's order does not matter.
  shape.TorsionCrossing.assign(std::max(spans, 0), 0);
  const std::vector<char> twisted = shape.Twisted;
  for (int i = 0; i < spans; ++i)
  {
    const int before = i - 1, after = i + 1;
    if (!data.Closed && (before < 0 || after >= spans))
    {
      continue;
    }
    const int b = (before + spans) % spans, a = after % spans;
    if (!twisted[b] || !twisted[a] || shape.Torsion[b] * shape.Torsion[a] >= 0)
    {
      continue;
    }
    // The neighbour twisting the other way, and on this segment's own side
    // its neighbour and the one after it where they twist its way: on
    // unevenly spaced points the zero can lie a segment further on than
    // the opposite neighbour says, while the own side's torsion grows.
    const bool oppositeBefore = shape.Torsion[i] * shape.Torsion[b] < 0;
    double scale = std::abs(shape.Torsion[oppositeBefore ? b : a]);
    const int step = oppositeBefore ? 1 : -1;
    for (const int own : { i + step, i + 2 * step })
    {
      const int k = wrapIndex(own, spans);
      if ((data.Closed || (own >= 0 && own < spans)) && twisted[k] &&
        shape.Torsion[k] * shape.Torsion[i] > 0)
      {
        scale = std::max(scale, std::abs(shape.Torsion[k]));
      }
    }
    if (shape.Coplanar[i] ||
      (twisted[i] && std::abs(shape.Torsion[i]) < NearZeroTorsionFraction * scale))
    {
      shape.Coplanar[i] = shape.Twisted[i] = 0;
      shape.TorsionCrossing[i] = 1;
    }
  }
  return shape;
}

void markKnots(std::vector<AuditSample>& samples, bool closed)
{
  for (size_t k = 0; k < samples.size(); ++k)
  {
    const bool startsSpan = k == 0 || samples[k].Span != samples[k - 1].Span;
    samples[k].Knot = startsSpan ? samples[k].Span : -1;
  }
  if (!closed && samples.size() > 1)
  {
    samples.back().Knot = samples.back().Span + 1;
  }
}

int ShapeAudit::violations() const
{
  int total = this->StrayingSpans;
  for (const int count : this->Failures)
  {
    total += count;
  }
  return total;
}

ShapeAuditor::ShapeAuditor(
  const CleanPolyline& data, const DiscreteShape& shape, const ShapeTolerances& tolerances)
  : Data(data)
  , Shape(shape)
  , Tolerances(tolerances)
{
  const double diagonal = boundingBoxDiagonal(data.Points);
  this->Scale = diagonal > 0 ? diagonal : 1.0;
  this->Findings.resize(std::max(data.numberOfSpans(), 0));
  this->TransitionTwist.resize(this->Findings.size());
  for (const Vec3& b : shape.Binormal)
  {
    this->UnitBinormal.push_back(b.normalized());
  }
  const int spans = data.numberOfSpans();
  for (int i = 0; i <= spans; ++i)
  {
    this->TwistReverses.push_back(this->twistReversesAt(i));
  }
  this->TwistTolerance = this->twistTolerances();
}

std::vector<double> ShapeAuditor::twistTolerances() const
{
  // Near the torsion's zero a converging curve's torsion wavers about it by
  // its own error: a cubic's, first order, steps at every knot, and on
  // unevenly spaced points the discrete torsion is off by its own size there
  // (a clean trefoil at random places: a segment's -0.011 where the curve's
  // is -0.003; the cubic's zero two knots from the data's, and the automatic
  // modes moved it by bending the curve, by up to 5.6 times the curve's
  // largest curvature). Both show in the steps of the discrete torsion from
  // segment to segment: within two spans of a knot where the data's torsion
  // reverses, a sign counts only beyond half the largest step there.
  const CleanPolyline& data = this->Data;
  const DiscreteShape& shape = this->Shape;
  const int spans = data.numberOfSpans();
  std::vector<double> tolerance(std::max(spans, 0), this->Tolerances.Curve);
  constexpr int Reach = 2;
  constexpr double StepFraction = 0.5;
  auto exists = [&](int k) { return data.Closed || (k >= 0 && k < spans); };
  auto twisting = [&](int k) { return shape.Twisted[k] || shape.TorsionCrossing[k]; };
  // Only where the torsion passes through zero once among the five twisted
  // segments on either side, not where noise flips its sign back and forth
  // (there the audit keeps every sign; with three on either side the aorta's
  // second line kept one more violation with qqr's default, its search led
  // elsewhere).
  constexpr int ReversalWindow = 5;
  auto reversesOnce = [&](int i) {
    int changes = 0, last = 0;
    for (int k = i - ReversalWindow; k < i + ReversalWindow; ++k)
    {
      const int here = wrapIndex(k, spans);
      if (exists(k) && shape.Twisted[here])
      {
        const int current = static_cast<int>(sign(shape.Torsion[here]));
        changes += last != 0 && current != last;
        last = current;
      }
    }
    return changes == 1;
  };
  for (int i = 0; i <= spans; ++i)
  {
    if (!this->TwistReverses[i] || !reversesOnce(i))
    {
      continue;
    }
    double step = 0.0;
    for (int k = i - Reach + 1; k < i + Reach; ++k)
    {
      const int here = wrapIndex(k, spans), before = wrapIndex(k - 1, spans);
      if (exists(k) && exists(k - 1) && twisting(here) && twisting(before))
      {
        step = std::max(step, std::abs(shape.Torsion[here] - shape.Torsion[before]) * this->Scale);
      }
    }
    for (int k = i - Reach; k < i + Reach; ++k)
    {
      if (exists(k))
      {
        double& allowed = tolerance[wrapIndex(k, spans)];
        allowed = std::max(allowed, StepFraction * step);
      }
    }
  }
  // A segment twisting its neighbours' way by under a third of the less
  // twisted one is a near-zero of the torsion that does not cross it (a helix
  // at 16 points a turn with 0.1% noise: 0.001 between 0.042 and 0.045).
  // There too a converging curve's torsion wavers about zero by its own
  // error, and the sign counts only beyond half the step down to the segment.
  for (int j = 0; j < spans; ++j)
  {
    if (!exists(j - 1) || !exists(j + 1) || !shape.Twisted[j])
    {
      continue;
    }
    const int before = wrapIndex(j - 1, spans), after = wrapIndex(j + 1, spans);
    const double torsion = shape.Torsion[j];
    if (!shape.Twisted[before] || !shape.Twisted[after] || torsion * shape.Torsion[before] <= 0 ||
      torsion * shape.Torsion[after] <= 0)
    {
      continue;
    }
    const double weaker = std::min(std::abs(shape.Torsion[before]), std::abs(shape.Torsion[after]));
    if (std::abs(torsion) < NearZeroTorsionFraction * weaker)
    {
      const double step = (weaker - std::abs(torsion)) * this->Scale;
      tolerance[j] = std::max(tolerance[j], StepFraction * step);
    }
  }
  return tolerance;
}

void ShapeAuditor::fail(const AuditSample& sample, ShapeCriterion criterion, int where, int spanA,
  int spanB, double deficiency)
{
  this->Findings[sample.Span].push_back({ { criterion, where }, { spanA, spanB }, deficiency });
}

void ShapeAuditor::forget(int span)
{
  this->Findings[span].clear();
  this->TransitionTwist[span].clear();
}

bool ShapeAuditor::twistReversesAt(int i) const
{
  const int spans = this->Data.numberOfSpans();
  if (!this->Data.Closed && (i <= 0 || i >= spans))
  {
    return false;
  }
  const int before = (i - 1 + spans) % spans, after = i % spans;
  const DiscreteShape& shape = this->Shape;
  // An open line's end spans have no discrete torsion (it takes a segment
  // on each side): whether the torsion reverses at the knot next to an end
  // the data cannot say, so the curve may change sign there once, as where
  // they reverse (a trefoil's torsion changes sign a third of a span in).
  if (!this->Data.Closed && (i == 1 || i == spans - 1))
  {
    return shape.Twisted[i == 1 ? after : before]; // the inner span
  }
  return (shape.Twisted[before] && shape.Twisted[after] &&
           shape.Torsion[before] * shape.Torsion[after] < 0) ||
    shape.TorsionCrossing[before] || shape.TorsionCrossing[after];
}

double ShapeAuditor::transitionDeficiency(int span) const
{
  const std::vector<double>& twist = this->TransitionTwist[span];
  const auto right = [](double deficiency) { return deficiency == 0.0; };
  const auto first = std::find_if(twist.begin(), twist.end(), right);
  if (first == twist.end())
  {
    // Never the data's sign: the sign change is not where the data's is.
    return std::accumulate(twist.begin(), twist.end(), 0.0);
  }
  const auto last = std::find_if(twist.rbegin(), twist.rend(), right).base();
  const double leading = std::accumulate(twist.begin(), first, 0.0);
  const double trailing = std::accumulate(last, twist.end(), 0.0);
  return (this->TwistReverses[span] ? 0.0 : leading) + std::accumulate(first, last, 0.0) +
    (this->TwistReverses[span + 1] ? 0.0 : trailing);
}

double ShapeAuditor::signedCurvature(const FrenetFrame& f, int point) const
{
  return f.Curvature * f.Binormal.dot(this->UnitBinormal[point]) * this->Scale;
}

void ShapeAuditor::add(const AuditSample& s)
{
  const CleanPolyline& data = this->Data;
  const DiscreteShape& shape = this->Shape;
  const double tolerance = this->Tolerances.Curve;
  const int n = static_cast<int>(data.Points.size());
  const int spans = data.numberOfSpans();
  const int j = s.Span;
  if (j < 0 || j >= spans)
  {
    return;
  }
  const int next = (j + 1) % n;
  const FrenetFrame& f = s.Frame;
  const bool inside = s.Knot < 0;

  // (i) collinearity: at I_i and inside the spans on both sides of it.
  for (const int i : { j, next })
  {
    const bool onOwnKnot = s.Knot == i;
    if (shape.Collinear[i] && (inside || onOwnKnot))
    {
      const double sine = f.Tangent.cross(data.segment(i).normalized()).norm();
      if (sine > tolerance)
      {
        this->fail(s, ShapeCriterion::Collinearity, i, j, j, sine - tolerance);
      }
    }
  }

  // (iii) coplanarity on the closed span: the osculating plane is the data
  // plane, where the curve bends enough (scale-free) to have one.
  const bool bends = !s.Flat && f.Curvature * this->Scale > tolerance;
  if (shape.Coplanar[j] && bends)
  {
    const int planeAt = shape.Convex[j] ? j : (shape.Convex[next] ? next : -1);
    const double sine =
      planeAt >= 0 ? f.Binormal.cross(this->UnitBinormal[planeAt]).norm() : 0.0;
    if (sine > tolerance)
    {
      this->fail(s, ShapeCriterion::Coplanarity, j, j, j, sine - tolerance);
    }
  }

  if (!inside)
  {
    const int i = s.Knot % n;
    const int spanBefore = data.Closed || i > 0 ? (i - 1 + spans) % spans : -1;
    const int spanAfter = data.Closed || i < n - 1 ? i % spans : -1;
    // (ii.1) convexity at the knot.
    const double bend = shape.Convex[i] && !s.Flat ? this->signedCurvature(f, i) : 0.0;
    if (bend < -tolerance)
    {
      this->fail(s, ShapeCriterion::ConvexityAtKnot, i, spanBefore, spanAfter, -bend - tolerance);
    }
    // (iv.1) torsion sign at the knot where both neighbouring segments agree,
    // where the curve bends enough to have an osculating plane (as (iii)):
    // as the curvature vanishes the torsion is a ratio of vanishing numbers.
    if (bends && spanBefore >= 0 && spanAfter >= 0 && shape.Twisted[spanBefore] &&
      shape.Twisted[spanAfter] && shape.Torsion[spanBefore] * shape.Torsion[spanAfter] > 0)
    {
      const double twist = f.Torsion * sign(shape.Torsion[spanAfter]) * this->Scale;
      const double allowed =
        std::max(this->TwistTolerance[spanBefore], this->TwistTolerance[spanAfter]);
      if (twist < -allowed)
      {
        this->fail(
          s, ShapeCriterion::TorsionSignAtKnot, i, spanBefore, spanAfter, -twist - allowed);
      }
    }
    return;
  }

  // (ii.2) convexity inside a span whose end binormals agree.
  if (!s.Flat && shape.Convex[j] && shape.Convex[next] &&
    shape.Binormal[j].dot(shape.Binormal[next]) > 0)
  {
    const double bend = std::min(this->signedCurvature(f, j), this->signedCurvature(f, next));
    if (bend < -tolerance)
    {
      this->fail(s, ShapeCriterion::ConvexityOnSpan, j, j, j, -bend - tolerance);
    }
  }
  // (iv.2) torsion sign inside a twisted span, where the curve bends.
  if (shape.Twisted[j])
  {
    const double twist = bends ? f.Torsion * sign(shape.Torsion[j]) * this->Scale : 0.0;
    const double allowed = this->TwistTolerance[j];
    const double deficiency = twist < -allowed ? -twist - allowed : 0.0;
    if (this->TwistReverses[j] || this->TwistReverses[j + 1])
    {
      this->TransitionTwist[j].push_back(deficiency);
    }
    else if (deficiency > 0.0)
    {
      this->fail(s, ShapeCriterion::TorsionSignOnSpan, j, j, j, deficiency);
    }
  }
}

ShapeAudit ShapeAuditor::result() const
{
  ShapeAudit audit;
  const size_t spans = this->Findings.size();
  audit.SpanMask.assign(spans, 0u);
  audit.SpanDeficiency.assign(spans, 0.0);
  auto record = [&](const Finding& f) {
    for (const int span : f.Spans)
    {
      if (span >= 0 && span < static_cast<int>(spans))
      {
        audit.SpanMask[span] |= criterionBit(f.Failure.Criterion);
        audit.SpanDeficiency[span] += f.Deficiency;
      }
    }
    audit.Where.push_back(f.Failure);
  };
  // Each span's findings, then its torsion sign's transition (not a copy of
  // the findings with it appended: the automatic modes ask for tens of
  // thousands of results).
  for (size_t j = 0; j < spans; ++j)
  {
    for (const Finding& f : this->Findings[j])
    {
      record(f);
    }
    const double deficiency = this->transitionDeficiency(static_cast<int>(j));
    if (deficiency > 0.0)
    {
      const int span = static_cast<int>(j);
      record({ { ShapeCriterion::TorsionSignOnSpan, span }, { span, span }, deficiency });
    }
  }
  auto key = [](const ShapeFailure& f) { return std::make_pair(static_cast<int>(f.Criterion), f.Where); };
  std::sort(audit.Where.begin(), audit.Where.end(),
    [&](const ShapeFailure& a, const ShapeFailure& b) { return key(a) < key(b); });
  audit.Where.erase(std::unique(audit.Where.begin(), audit.Where.end(),
                      [&](const ShapeFailure& a, const ShapeFailure& b) { return key(a) == key(b); }),
    audit.Where.end());
  for (const ShapeFailure& f : audit.Where)
  {
    ++audit.Failures[static_cast<int>(f.Criterion)];
  }
  return audit;
}

ShapeAudit auditShape(const CleanPolyline& data, const DiscreteShape& shape,
  const std::vector<AuditSample>& samples, const ShapeTolerances& tolerances)
{
  ShapeAuditor auditor(data, shape, tolerances);
  for (const AuditSample& s : samples)
  {
    auditor.add(s);
  }
  return auditor.result();
}
} // namespace shapesplines
