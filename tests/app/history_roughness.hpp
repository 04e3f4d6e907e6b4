#pragma once
// The roughness of a per-step history (a column of history.csv): the root mean square of its
// second difference, the measure of docs/uvlm.md's shed-leading-edge tables.

#include <cmath>
#include <cstddef>
#include <vector>

namespace flapsim::test {

/// Root mean square of v[k+1] − 2 v[k] + v[k−1] over k in [first, last) (first ≥ 1, last <
/// v.size()): small for a history that is smooth against its own step-to-step change.
inline double second_difference_rms(const std::vector<double>& v, std::size_t first, std::size_t last) {
  double sum = 0.0;
  for (std::size_t k = first; k < last; ++k) {
    const double d2 = v[k + 1] - 2.0 * v[k] + v[k - 1];
    sum += d2 * d2;
  }
  return std::sqrt(sum / static_cast<double>(last - first));
}

}  // namespace flapsim::test
