#include "mbd/table_scatter.hpp"

#include "mbd/fourier_fit.hpp"
#include "mbd/periodic_signal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace flapsim::mbd {

double spline_rms_acceleration(const std::vector<double>& phases, const std::vector<double>& values) {
  const PeriodicSignal spline = PeriodicSignal::tabulated(phases, values);
  const std::size_t n = phases.size();
  double integral = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double left = phases[i], right = i + 1 < n ? phases[i + 1] : phases[0] + 1.0;
    const double a = spline.at_phase(left).acceleration;
    const double c = spline.at_phase(i + 1 < n ? right : phases[0]).acceleration;
    integral += (right - left) * (a * a + a * c + c * c) / 3.0;  // ∫ of a linear function squared
  }
  return std::sqrt(integral);
}

std::optional<TableScatter> measure_table_scatter(const std::vector<double>& phases,
                                                  const std::vector<double>& values) {
  const std::size_t n = phases.size();
  if (n < kScatterMinPoints || values.size() != n) return std::nullopt;
  TableScatter out;
  out.harmonics = std::min(static_cast<int>(n / 4), kScatterMaxHarmonics);
  FourierFit fit;
  try {
    fit = fit_fourier_series(phases, values, out.harmonics);
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
  out.spline_acceleration = spline_rms_acceleration(phases, values);
  if (!(out.spline_acceleration > 0.0)) return std::nullopt;
  std::vector<double> scatter(n);
  for (std::size_t i = 0; i < n; ++i) scatter[i] = values[i] - fourier_series_value(fit, phases[i]);
  out.scatter_rms = fit.residual_rms;
  out.scatter_share = spline_rms_acceleration(phases, scatter) / out.spline_acceleration;
  // The series' rms acceleration: Σ (2πk)⁴ (a_k² + b_k²) / 2, its harmonics orthogonal.
  double sum = 0.0;
  for (std::size_t k = 0; k < fit.cos_coeffs.size(); ++k) {
    const double w = 2.0 * std::numbers::pi * static_cast<double>(k + 1);
    sum +=
        w * w * w * w * (fit.cos_coeffs[k] * fit.cos_coeffs[k] + fit.sin_coeffs[k] * fit.sin_coeffs[k]) / 2.0;
  }
  out.series_acceleration = std::sqrt(sum);
  return out;
}

int fewest_harmonics_within_scatter(const std::vector<double>& phases, const std::vector<double>& values,
                                    const TableScatter& scatter) {
  // Each fit's unbiased estimate of the scatter: a fit of 2N + 1 coefficients absorbs that
  // many of the n points' degrees of freedom (K = n/4 takes half of them).
  const std::size_t n = phases.size();
  const auto sigma = [n](double rms, int harmonics) {
    return rms * std::sqrt(static_cast<double>(n) /
                           static_cast<double>(n - 2 * static_cast<std::size_t>(harmonics) - 1));
  };
  const double floor = sigma(scatter.scatter_rms, scatter.harmonics);
  for (int h = 1; h < scatter.harmonics; ++h) {
    try {
      if (sigma(fit_fourier_series(phases, values, h).residual_rms, h) <= kSuggestedScatterFactor * floor)
        return h;
    } catch (const std::invalid_argument&) {
      break;
    }
  }
  return scatter.harmonics;
}

}  // namespace flapsim::mbd
