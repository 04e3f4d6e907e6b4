#include "mbd/periodic_signal.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace flapsim::mbd {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
}  // namespace

PeriodicSignal::PeriodicSignal() = default;

PeriodicSignal PeriodicSignal::harmonic(double mean, std::vector<double> cos_coeffs,
                                        std::vector<double> sin_coeffs) {
  PeriodicSignal s;
  s.mean_ = mean;
  s.cos_ = std::move(cos_coeffs);
  s.sin_ = std::move(sin_coeffs);
  return s;
}

PeriodicSignal PeriodicSignal::tabulated(std::vector<double> phases, std::vector<double> values) {
  const std::size_t n = phases.size();
  if (values.size() != n)
    throw std::invalid_argument("tabulated signal: " + std::to_string(n) + " phases but " +
                                std::to_string(values.size()) + " values");
  if (n < 3)
    throw std::invalid_argument("tabulated signal: at least 3 points are needed, got " +
                                std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(phases[i]) || !std::isfinite(values[i]))
      throw std::invalid_argument("tabulated signal: point " + std::to_string(i) +
                                  " is not a finite number");
    if (phases[i] < 0.0 || phases[i] >= 1.0)
      throw std::invalid_argument("tabulated signal: phase " + std::to_string(phases[i]) +
                                  " of point " + std::to_string(i) + " is outside [0, 1)");
    if (i > 0 && !(phases[i] > phases[i - 1]))
      throw std::invalid_argument("tabulated signal: phases are not strictly increasing at point " +
                                  std::to_string(i));
  }

  // Periodic cubic spline: continuity of y' at every knot (the interval after the
  // last knot wraps to the first one, one period later) gives a cyclic tridiagonal
  // system for the second derivatives M_i:
  //   h_{i-1} M_{i-1} + 2(h_{i-1} + h_i) M_i + h_i M_{i+1}
  //     = 6 [(y_{i+1} - y_i)/h_i - (y_i - y_{i-1})/h_{i-1}].
  // Tables are short (tens to hundreds of points), so a dense solve at construction is fine.
  auto h = [&](std::size_t i) {
    return i + 1 < n ? phases[i + 1] - phases[i] : phases[0] + 1.0 - phases[n - 1];
  };
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  Eigen::VectorXd b(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t prev = (i + n - 1) % n, next = (i + 1) % n;
    const double hp = h(prev), hi = h(i);
    const auto I = static_cast<Eigen::Index>(i);
    A(I, static_cast<Eigen::Index>(prev)) += hp;
    A(I, I) += 2.0 * (hp + hi);
    A(I, static_cast<Eigen::Index>(next)) += hi;
    b(I) = 6.0 * ((values[next] - values[i]) / hi - (values[i] - values[prev]) / hp);
  }
  const Eigen::VectorXd M = A.partialPivLu().solve(b);

  PeriodicSignal s;
  s.tabulated_ = true;
  s.phases_ = std::move(phases);
  s.values_ = std::move(values);
  s.second_derivs_.assign(M.data(), M.data() + M.size());
  return s;
}

bool PeriodicSignal::is_constant() const {
  if (tabulated_) {
    for (double v : values_)
      if (v != values_.front()) return false;
    return true;
  }
  for (double c : cos_)
    if (c != 0.0) return false;
  for (double c : sin_)
    if (c != 0.0) return false;
  return true;
}

AngleSample PeriodicSignal::at_phase(double s) const {
  AngleSample out;
  if (!tabulated_) {
    out.value = mean_;
    const std::size_t terms = std::max(cos_.size(), sin_.size());
    for (std::size_t k = 0; k < terms; ++k) {
      const double w = kTwoPi * static_cast<double>(k + 1);  // [rad/cycle]
      const double a = k < cos_.size() ? cos_[k] : 0.0;
      const double b = k < sin_.size() ? sin_[k] : 0.0;
      const double c = std::cos(w * s), sn = std::sin(w * s);
      out.value += a * c + b * sn;
      out.rate += w * (-a * sn + b * c);
      out.acceleration += -w * w * (a * c + b * sn);
    }
    return out;
  }

  // Bring s into [s_0, s_0 + 1), then find the interval [s_i, s_i + h_i] holding it.
  const std::size_t n = phases_.size();
  const double s0 = phases_.front();
  double u = s0 + (s - s0 - std::floor(s - s0));
  if (u >= s0 + 1.0) u = s0;  // rounding of a value just below a whole period
  const auto it = std::upper_bound(phases_.begin(), phases_.end(), u);
  const std::size_t i = static_cast<std::size_t>(it - phases_.begin()) - 1;
  const std::size_t next = (i + 1) % n;
  const double left = phases_[i];
  const double right = i + 1 < n ? phases_[i + 1] : phases_[0] + 1.0;
  const double h = right - left;
  const double A = (right - u) / h, B = (u - left) / h;
  const double yi = values_[i], yn = values_[next];
  const double Mi = second_derivs_[i], Mn = second_derivs_[next];
  out.value = A * yi + B * yn + ((A * A * A - A) * Mi + (B * B * B - B) * Mn) * h * h / 6.0;
  out.rate = (yn - yi) / h - (3.0 * A * A - 1.0) / 6.0 * h * Mi + (3.0 * B * B - 1.0) / 6.0 * h * Mn;
  out.acceleration = A * Mi + B * Mn;
  return out;
}

}  // namespace flapsim::mbd
