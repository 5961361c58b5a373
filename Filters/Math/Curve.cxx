#include "Curve.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace shapesplines
{
Curve::Curve(std::vector<double> knots, bool closed)
  : Knots(std::move(knots))
  , Closed(closed)
{
  if (this->Knots.size() < 2)
  {
    throw std::invalid_argument("a curve needs at least two knots");
  }
}

int Curve::findSpan(double t) const
{
  const auto it = std::upper_bound(this->Knots.begin(), this->Knots.end(), t);
  const int span = static_cast<int>(it - this->Knots.begin()) - 1;
  return std::clamp(span, 0, this->numberOfSpans() - 1);
}

Derivatives Curve::evaluate(double t, int order) const
{
  if (this->Closed)
  {
    // The parameter of a closed curve is periodic: t_n is t_0 again.
    const double period = this->lastParameter() - this->firstParameter();
    t = this->firstParameter() + std::fmod(t - this->firstParameter(), period);
    if (t < this->firstParameter())
    {
      t += period;
    }
  }
  return this->evaluateOnSpan(this->findSpan(t), t, order);
}

double Curve::arcLengthOnSpan(int span, double a, double b) const
{
  return gaussLegendre([&](double t) { return this->evaluateOnSpan(span, t, 1)[1].norm(); }, a, b);
}

TrimmedCurve::TrimmedCurve(std::unique_ptr<Curve> whole, int first, int spans)
  : Curve(std::vector<double>(whole->knots().begin() + first, whole->knots().begin() + first + spans + 1),
      false)
  , Whole(std::move(whole))
  , First(first)
{
}

Derivatives TrimmedCurve::evaluateOnSpan(int span, double t, int order) const
{
  return this->Whole->evaluateOnSpan(span + this->First, t, order);
}

double TrimmedCurve::arcLengthOnSpan(int span, double a, double b) const
{
  return this->Whole->arcLengthOnSpan(span + this->First, a, b);
}

double TrimmedCurve::conditionEstimate() const
{
  return this->Whole->conditionEstimate();
}

std::vector<SpanParameter> TrimmedCurve::spanParameters() const
{
  std::vector<SpanParameter> parameters = this->Whole->spanParameters();
  for (SpanParameter& p : parameters)
  {
    p.Values = std::vector<double>(
      p.Values.begin() + this->First, p.Values.begin() + this->First + this->numberOfSpans());
  }
  return parameters;
}
std::vector<double> knotSpacings(const std::vector<double>& knots, const std::string& family)
{
  std::vector<double> h(knots.size() > 1 ? knots.size() - 1 : 0);
  for (size_t i = 0; i < h.size(); ++i)
  {
    h[i] = knots[i + 1] - knots[i];
    if (!(h[i] > 0.0) || !std::isfinite(h[i]))
    {
      throw std::invalid_argument(family + ": knots must increase strictly");
    }
  }
  return h;
}

std::array<Vec3, 3> polynomialEndDerivatives(
  const std::vector<Vec3>& points, const std::vector<double>& knots, bool start, int count)
{
  const int n = static_cast<int>(points.size());
  const int m = std::min(n, count);
  Eigen::MatrixXd vandermonde(m, m);
  Eigen::MatrixXd values(m, 3);
  const int end = start ? 0 : n - 1;
  // In u = (x - x_end) / scale, within [-1, 1]: a well-conditioned Vandermonde matrix.
  const double scale = knots[start ? m - 1 : n - m] - knots[end];
  for (int r = 0; r < m; ++r)
  {
    const int i = start ? r : n - 1 - r;
    const double u = (knots[i] - knots[end]) / scale;
    for (int c = 0; c < m; ++c)
    {
      vandermonde(r, c) = std::pow(u, c);
    }
    values.row(r) = points[i].transpose();
  }
  const Eigen::MatrixXd c = vandermonde.colPivHouseholderQr().solve(values);
  std::array<Vec3, 3> derivatives{ Vec3::Zero(), Vec3::Zero(), Vec3::Zero() };
  double factorial = 1.0;
  for (int order = 1; order <= 3 && order < m; ++order)
  {
    factorial *= order;
    derivatives[order - 1] = factorial * c.row(order).transpose() / std::pow(scale, order);
  }
  return derivatives;
}
} // namespace shapesplines
