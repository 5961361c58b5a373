#include "OutputArrays.h"

#include "vtkAbstractArray.h"
#include "vtkFieldData.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <numeric>

namespace shapesplines
{
void addArrays(vtkFieldData* data, std::initializer_list<vtkAbstractArray*> arrays)
{
  for (vtkAbstractArray* array : arrays)
  {
    data->AddArray(array);
  }
}

double typicalMagnitude(const double* first, const double* last)
{
  // Selected by the bits of |v|, which order non-negative doubles as their
  // values: a count per 16 bits, from the top ones down, among the values
  // whose bits above agree with the one holding the rank, until few enough
  // are left to select among. The value a selection over all of them gives,
  // without copying the samples (a copy and a full selection took ~50 ms on
  // 2e6 samples) and in bounded memory (a crowded bucket is refined, not
  // gathered: 1e7 samples of about one torsion would be).
  constexpr int Digit = 16;
  constexpr size_t FewValues = size_t(1) << 16;
  const auto bitsOf = [](double value) {
    std::uint64_t bits;
    const double magnitude = std::abs(value);
    std::memcpy(&bits, &magnitude, sizeof bits);
    return bits;
  };
  std::uint64_t prefix = 0; // the top `decided` bits of the value sought
  int decided = 0;
  const auto agrees = [&](double value) {
    return std::isfinite(value) && (decided == 0 || bitsOf(value) >> (64 - decided) == prefix);
  };
  // A short line's samples are selected among directly: the counts' 512 kB
  // would cost more than the selection.
  size_t holding = static_cast<size_t>(last - first); // at least the values left
  size_t rank = 0;
  std::vector<size_t> counts(holding > FewValues ? size_t(1) << Digit : 0);
  while (holding > FewValues && decided < 64)
  {
    const int shift = 64 - decided - Digit;
    std::fill(counts.begin(), counts.end(), 0);
    for (const double* v = first; v != last; ++v)
    {
      if (agrees(*v))
      {
        ++counts[(bitsOf(*v) >> shift) & (counts.size() - 1)];
      }
    }
    if (decided == 0)
    {
      const size_t finite = std::accumulate(counts.begin(), counts.end(), size_t(0));
      if (finite == 0)
      {
        return 0.0;
      }
      rank = static_cast<size_t>(0.95 * (finite - 1));
    }
    size_t bucket = 0;
    while (rank >= counts[bucket])
    {
      rank -= counts[bucket++];
    }
    prefix = (prefix << Digit) | bucket;
    decided += Digit;
    holding = counts[bucket];
  }
  if (decided == 64)
  {
    double value; // every bit decided: the values left are all this one
    std::memcpy(&value, &prefix, sizeof value);
    return value;
  }
  std::vector<double> candidates;
  candidates.reserve(holding);
  for (const double* v = first; v != last; ++v)
  {
    if (agrees(*v))
    {
      candidates.push_back(std::abs(*v));
    }
  }
  if (candidates.empty())
  {
    return 0.0;
  }
  rank = decided == 0 ? static_cast<size_t>(0.95 * (candidates.size() - 1)) : rank;
  const auto nth = candidates.begin() + static_cast<std::ptrdiff_t>(rank);
  std::nth_element(candidates.begin(), nth, candidates.end());
  return *nth;
}

double typicalMagnitude(const std::vector<double>& values)
{
  return typicalMagnitude(values.data(), values.data() + values.size());
}
} // namespace shapesplines
