#include "mbd/periodic_signal.hpp"

#include "mbd/fourier_fit.hpp"

#include <vector>

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
  // Solved in O(n) (the cyclic Thomas algorithm with the Sherman–Morrison correction for
  // the two corner terms [Press et al., Numerical Recipes, 3rd ed., §2.7.2]; the matrix is
  // symmetric and strictly diagonally dominant, so no pivoting): a dense solve took 46 s at
  // 8000 points and ran out of memory at 200 000 (a finely sampled measured wingbeat).
  auto h = [&](std::size_t i) {
    return i + 1 < n ? phases[i + 1] - phases[i] : phases[0] + 1.0 - phases[n - 1];
  };
  std::vector<double> sub(n), diag(n), super(n), rhs(n);  // row i: sub M_{i-1}, diag M_i, super M_{i+1}
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t prev = (i + n - 1) % n, next = (i + 1) % n;
    const double hp = h(prev), hi = h(i);
    sub[i] = hp;
    diag[i] = 2.0 * (hp + hi);
    super[i] = hi;
    rhs[i] = 6.0 * ((values[next] - values[i]) / hi - (values[i] - values[prev]) / hp);
  }
  // The corners: row 0's M_{n-1} (beta) and row n-1's M_0 (alpha).
  const double beta = sub[0], alpha = super[n - 1], gamma = -diag[0];
  std::vector<double> d = diag;
  d[0] -= gamma;
  d[n - 1] -= alpha * beta / gamma;
  // Thomas algorithm on the tridiagonal part for two right-hand sides: rhs and u = (γ, 0, …, α).
  std::vector<double> u(n, 0.0);
  u[0] = gamma;
  u[n - 1] = alpha;
  std::vector<double> c(n);
  std::vector<double> x = rhs, z = u;
  c[0] = super[0] / d[0];
  x[0] /= d[0];
  z[0] /= d[0];
  for (std::size_t i = 1; i < n; ++i) {
    const double m = d[i] - sub[i] * c[i - 1];
    c[i] = i + 1 < n ? super[i] / m : 0.0;
    x[i] = (x[i] - sub[i] * x[i - 1]) / m;
    z[i] = (z[i] - sub[i] * z[i - 1]) / m;
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    x[i] -= c[i] * x[i + 1];
    z[i] -= c[i] * z[i + 1];
  }
  const double factor = (x[0] + beta * x[n - 1] / gamma) / (1.0 + z[0] + beta * z[n - 1] / gamma);
  std::vector<double> M(n);
  for (std::size_t i = 0; i < n; ++i) M[i] = x[i] - factor * z[i];

  PeriodicSignal s;
  s.tabulated_ = true;
  s.phases_ = std::move(phases);
  s.values_ = std::move(values);
  s.second_derivs_ = std::move(M);
  return s;
}

PeriodicSignal PeriodicSignal::fitted(const std::vector<double>& phases, const std::vector<double>& values,
                                      int harmonics) {
  FourierFit fit = fit_fourier_series(phases, values, harmonics);
  PeriodicSignal s = harmonic(fit.mean, std::move(fit.cos_coeffs), std::move(fit.sin_coeffs));
  s.table_fit_ = TableFit{static_cast<int>(phases.size()), harmonics, fit.residual_rms, fit.residual_largest,
                          fit.largest_phase};
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

int PeriodicSignal::highest_harmonic() const {
  if (tabulated_) return 0;
  for (std::size_t n = std::max(cos_.size(), sin_.size()); n > 0; --n)
    if ((n <= cos_.size() && cos_[n - 1] != 0.0) || (n <= sin_.size() && sin_[n - 1] != 0.0))
      return static_cast<int>(n);
  return 0;
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
