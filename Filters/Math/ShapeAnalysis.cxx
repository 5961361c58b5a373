#include "ShapeAnalysis.h"

#include <algorithm>

namespace shapesplines
{
namespace
{
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

DiscreteShape discreteShape(const CleanPolyline& data, const ShapeTolerances& tolerances)
{
  const int n = static_cast<int>(data.Points.size());
  const int spans = data.numberOfSpans();
  DiscreteShape shape;
  shape.Binormal.assign(n, Vec3::Zero());
  shape.Curvature.assign(n, 0.0);
  shape.Collinear.assign(n, 0);
  shape.Convex.assign(n, 0);
  shape.Torsion.assign(std::max(spans, 0), 0.0);
  shape.Coplanar.assign(std::max(spans, 0), 0);
  shape.Twisted.assign(std::max(spans, 0), 0);
  auto interior = [&](int i) { return data.Closed || (i > 0 && i < n - 1); };

  // Unit segments and lengths by stableNorm: products of raw lengths under- or
  // overflow for coordinates of 1e-160 or 1e160.
  std::vector<Vec3> unit(std::max(spans, 0));
  std::vector<double> length(std::max(spans, 0));
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
    const bool straight = shape.Binormal[i].norm() <= tolerances.Data;
    shape.Collinear[i] = straight && unit[before].dot(unit[i]) > 0;
    shape.Convex[i] = !straight;
  }
  for (int i = 0; i < spans; ++i)
  {
    const int before = (i - 1 + n) % n;
    const int next = (i + 1) % n;
    if (!interior(i) || !interior(next))
    {
      continue;
    }
    // Delta_i = det(L_{i-1}, L_i, L_{i+1}) / (|L_{i-1} x L_i| |L_i x L_{i+1}|),
    // written with unit segments: det(a, b, c) / (|L_i| |a x b| |b x c|).
    const Vec3& a = unit[before];
    const Vec3& b = unit[i];
    const Vec3& c = unit[next];
    const double triple = a.dot(b.cross(c));
    const double crosses = a.cross(b).norm() * b.cross(c).norm();
    const bool flat = std::abs(triple) <= tolerances.Data || !(crosses > 0);
    shape.Torsion[i] = flat ? 0.0 : triple / (length[i] * crosses);
    shape.Coplanar[i] = flat;
    shape.Twisted[i] = !flat;
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
  int total = 0;
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
  this->Audit.SpanMask.assign(std::max(data.numberOfSpans(), 0), 0u);
}

void ShapeAuditor::fail(ShapeCriterion criterion, int where, int span)
{
  this->Failed.emplace(static_cast<int>(criterion), where);
  if (span >= 0 && span < static_cast<int>(this->Audit.SpanMask.size()))
  {
    this->Audit.SpanMask[span] |= 1u << static_cast<int>(criterion);
  }
}

double ShapeAuditor::signedCurvature(const FrenetFrame& f, int point) const
{
  return f.Curvature * f.Binormal.dot(this->Shape.Binormal[point].normalized()) * this->Scale;
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
    if (shape.Collinear[i] && (inside || onOwnKnot) &&
      f.Tangent.cross(data.segment(i).normalized()).norm() > tolerance)
    {
      this->fail(ShapeCriterion::Collinearity, i, j);
    }
  }

  // (iii) coplanarity on the closed span: the osculating plane is the data
  // plane, where the curve bends enough (scale-free) to have one.
  if (shape.Coplanar[j] && f.Curvature * this->Scale > tolerance)
  {
    const int planeAt = shape.Convex[j] ? j : (shape.Convex[next] ? next : -1);
    if (planeAt >= 0 &&
      f.Binormal.cross(shape.Binormal[planeAt].normalized()).norm() > tolerance)
    {
      this->fail(ShapeCriterion::Coplanarity, j, j);
    }
  }

  if (!inside)
  {
    const int i = s.Knot % n;
    const int spanBefore = data.Closed || i > 0 ? (i - 1 + spans) % spans : -1;
    const int spanAfter = data.Closed || i < n - 1 ? i % spans : -1;
    // (ii.1) convexity at the knot.
    if (shape.Convex[i] && this->signedCurvature(f, i) < -tolerance)
    {
      this->fail(ShapeCriterion::ConvexityAtKnot, i, spanBefore);
      this->fail(ShapeCriterion::ConvexityAtKnot, i, spanAfter);
    }
    // (iv.1) torsion sign at the knot where both neighbouring segments agree.
    if (spanBefore >= 0 && spanAfter >= 0 && shape.Twisted[spanBefore] &&
      shape.Twisted[spanAfter] && shape.Torsion[spanBefore] * shape.Torsion[spanAfter] > 0 &&
      f.Torsion * sign(shape.Torsion[spanAfter]) * this->Scale < -tolerance)
    {
      this->fail(ShapeCriterion::TorsionSignAtKnot, i, spanBefore);
      this->fail(ShapeCriterion::TorsionSignAtKnot, i, spanAfter);
    }
    return;
  }

  // (ii.2) convexity inside a span whose end binormals agree.
  if (shape.Convex[j] && shape.Convex[next] &&
    shape.Binormal[j].dot(shape.Binormal[next]) > 0 &&
    (this->signedCurvature(f, j) < -tolerance || this->signedCurvature(f, next) < -tolerance))
  {
    this->fail(ShapeCriterion::ConvexityOnSpan, j, j);
  }
  // (iv.2) torsion sign inside a twisted span.
  if (shape.Twisted[j] && f.Torsion * sign(shape.Torsion[j]) * this->Scale < -tolerance)
  {
    this->fail(ShapeCriterion::TorsionSignOnSpan, j, j);
  }
}

ShapeAudit ShapeAuditor::result() const
{
  ShapeAudit audit = this->Audit;
  for (const auto& [criterion, where] : this->Failed)
  {
    ++audit.Failures[criterion];
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
