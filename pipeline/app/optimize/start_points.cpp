#include "pipeline/app/optimize/start_points.hpp"

#include <array>
#include <stdexcept>

namespace flapsim::optimize {

double radical_inverse(std::size_t index, unsigned base) {
  double result = 0.0;
  double digit_value = 1.0 / base;
  for (std::size_t i = index; i > 0; i /= base, digit_value /= base) result += static_cast<double>(i % base) * digit_value;
  return result;
}

std::vector<std::vector<double>> start_points(const std::vector<double>& first, const std::vector<double>& lo,
                                              const std::vector<double>& hi, std::size_t count) {
  static constexpr std::array<unsigned, 20> kPrimes{2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71};
  if (lo.size() > kPrimes.size()) throw std::invalid_argument("start_points: at most 20 keys");
  std::vector<std::vector<double>> starts;
  if (count > 0) starts.push_back(first);
  for (std::size_t k = 1; k < count; ++k) {
    std::vector<double> x(lo.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = lo[i] + radical_inverse(k, kPrimes[i]) * (hi[i] - lo[i]);
    starts.push_back(std::move(x));
  }
  return starts;
}

}  // namespace flapsim::optimize
