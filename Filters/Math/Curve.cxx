#include "Curve.h"

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
} // namespace shapesplines
