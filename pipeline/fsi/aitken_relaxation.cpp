#include "pipeline/fsi/aitken_relaxation.hpp"

#include <algorithm>
#include <cmath>

namespace flapsim::fsi {

namespace {
constexpr double kMinStart = 0.05;  // a step never starts with a vanishing relaxation
}

AitkenRelaxation::AitkenRelaxation(double first_omega, double max_omega)
    : first_omega_(first_omega), max_omega_(max_omega), omega_(first_omega) {}

void AitkenRelaxation::start_step() {
  has_previous_ = false;
  omega_ = std::clamp(std::abs(omega_), kMinStart, 1.0);
  if (!std::isfinite(omega_)) omega_ = first_omega_;
}

double AitkenRelaxation::next(const Eigen::VectorXd& r) {
  if (has_previous_ && previous_.size() == r.size()) {
    difference_ = r - previous_;
    const double dd = difference_.squaredNorm();
    if (dd > 0.0) {
      const double w = -omega_ * previous_.dot(difference_) / dd;
      if (std::isfinite(w)) omega_ = std::clamp(w, -max_omega_, max_omega_);
    }
  }
  previous_ = r;
  has_previous_ = true;
  return omega_;
}

}  // namespace flapsim::fsi
