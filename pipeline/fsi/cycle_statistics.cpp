#include "pipeline/fsi/cycle_statistics.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "pipeline/fsi/phase_analysis.hpp"

namespace flapsim::fsi {

int whole_cycles(double period, double t_end) {
  const double n = std::floor(t_end / period + 1e-6);
  return n >= 0.0 && n < 1e9 ? static_cast<int>(n) : 0;  // no period (0, NaN) or no time: none
}

CycleStatistics cycle_statistics(const std::vector<double>& t, const std::vector<double>& x, double period,
                                 double t_end, int first_cycle) {
  const int whole = whole_cycles(period, t_end);
  const int n = whole - first_cycle + 1;
  if (first_cycle < 1 || n < 2)
    throw std::invalid_argument("cycle_statistics: " + std::to_string(whole) + " whole cycles, from cycle " +
                                std::to_string(first_cycle) + " on fewer than two");
  CycleStatistics s;
  for (int k = first_cycle - 1; k < whole; ++k)
    s.cycle_means.push_back(window_mean(t, x, k * period, (k + 1) * period));
  for (double m : s.cycle_means) s.mean += m;
  s.mean /= n;
  double squares = 0.0, products = 0.0;
  for (int i = 0; i < n; ++i) {
    const double d = s.cycle_means[i] - s.mean;
    squares += d * d;
    if (i + 1 < n) products += d * (s.cycle_means[i + 1] - s.mean);
  }
  s.deviation = std::sqrt(squares / (n - 1));
  s.standard_error = s.deviation / std::sqrt(static_cast<double>(n));
  s.lag_one_correlation = squares > 0.0 ? products / squares : 0.0;
  // Least squares of cycle_means on i = 0 … n − 1 (mean index ī = (n − 1)/2).
  const double i_mean = 0.5 * (n - 1);
  double sxy = 0.0, sxx = 0.0;
  for (int i = 0; i < n; ++i) {
    sxy += (i - i_mean) * (s.cycle_means[i] - s.mean);
    sxx += (i - i_mean) * (i - i_mean);
  }
  s.drift = sxy / sxx * (n - 1);
  return s;
}

}  // namespace flapsim::fsi
