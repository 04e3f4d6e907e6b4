#include "mbd/fourier_fit.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace flapsim::mbd {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// The basis at phase s: 1, cos 2πs, sin 2πs, …, cos 2πNs, sin 2πNs (angle addition from
/// the first harmonic: one cos and one sin a point).
void basis_at(double s, int harmonics, Eigen::VectorXd& row) {
  row[0] = 1.0;
  const double c1 = std::cos(kTwoPi * s), s1 = std::sin(kTwoPi * s);
  double c = 1.0, sn = 0.0;
  for (int n = 1; n <= harmonics; ++n) {
    const double next_c = c * c1 - sn * s1;
    sn = sn * c1 + c * s1;
    c = next_c;
    row[2 * n - 1] = c;
    row[2 * n] = sn;
  }
}
}  // namespace

FourierFit fit_fourier_series(const std::vector<double>& phases, const std::vector<double>& values,
                              int harmonics) {
  const std::size_t n = phases.size();
  if (values.size() != n)
    throw std::invalid_argument("Fourier fit: " + std::to_string(n) + " phases but " +
                                std::to_string(values.size()) + " values");
  if (harmonics < 0) throw std::invalid_argument("Fourier fit: a negative number of harmonics");
  const int unknowns = 2 * harmonics + 1;
  if (n < static_cast<std::size_t>(unknowns))
    throw std::invalid_argument("a series of " + std::to_string(harmonics) + " harmonics has " +
                                std::to_string(unknowns) + " coefficients, more than the " +
                                std::to_string(n) + " points determine (at most " +
                                std::to_string((n - 1) / 2) + " harmonics)");
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(unknowns, unknowns);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns), row(unknowns);
  for (std::size_t i = 0; i < n; ++i) {
    basis_at(phases[i], harmonics, row);
    normal.selfadjointView<Eigen::Lower>().rankUpdate(row);
    rhs += values[i] * row;
  }
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(normal.selfadjointView<Eigen::Lower>());
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12))
    throw std::invalid_argument("the points leave a series of " + std::to_string(harmonics) +
                                " harmonics undetermined (they cover too little of the cycle for it): "
                                "fewer harmonics, or points over the whole cycle");
  const Eigen::VectorXd x = ldlt.solve(rhs);

  FourierFit fit;
  fit.mean = x[0];
  fit.cos_coeffs.resize(static_cast<std::size_t>(harmonics));
  fit.sin_coeffs.resize(static_cast<std::size_t>(harmonics));
  for (int k = 1; k <= harmonics; ++k) {
    fit.cos_coeffs[static_cast<std::size_t>(k - 1)] = x[2 * k - 1];
    fit.sin_coeffs[static_cast<std::size_t>(k - 1)] = x[2 * k];
  }
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    basis_at(phases[i], harmonics, row);
    const double r = std::abs(values[i] - row.dot(x));
    sum_sq += r * r;
    if (r > fit.residual_largest) {
      fit.residual_largest = r;
      fit.largest_phase = phases[i];
    }
  }
  fit.residual_rms = std::sqrt(sum_sq / static_cast<double>(n));
  return fit;
}

double fourier_series_value(const FourierFit& fit, double s) {
  double v = fit.mean;
  for (std::size_t k = 0; k < fit.cos_coeffs.size(); ++k) {
    const double w = kTwoPi * static_cast<double>(k + 1) * s;
    v += fit.cos_coeffs[k] * std::cos(w) + fit.sin_coeffs[k] * std::sin(w);
  }
  return v;
}

}  // namespace flapsim::mbd
