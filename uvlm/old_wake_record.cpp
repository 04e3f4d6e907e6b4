/// \file old_wake_record.cpp
/// \brief The older wake's recorded and held velocities (old_wake_record.hpp).

#include "uvlm/old_wake_record.hpp"

namespace flapsim::uvlm {

void OldWakeRecord::reserve(std::size_t n) {
  const Eigen::Index c = static_cast<Eigen::Index>(n);
  for (Eigen::Matrix3Xd* m : {&velocity, &points, &velocity_before, &points_before}) m->setZero(3, c);
  clear();
}

void OldWakeRecord::record(std::size_t i0, std::size_t n, const double* x, const double* y, const double* z,
                           const double* u, const double* v, const double* w) {
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Index k = static_cast<Eigen::Index>(i0 + i);
    velocity_before.col(k) = velocity.col(k);
    points_before.col(k) = points.col(k);
    velocity.col(k) << u[i], v[i], w[i];
    points.col(k) << x[i], y[i], z[i];
  }
}

void OldWakeRecord::finish(std::size_t n) {
  records = n == size ? records + 1 : 1;
  size = n;
}

void OldWakeRecord::held(std::size_t i0, std::size_t n, const double* x, const double* y, const double* z,
                         double* u, double* v, double* w) const {
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Index k = static_cast<Eigen::Index>(i0 + i);
    Eigen::Vector3d value = velocity.col(k);
    if (records >= 2) {
      const Eigen::Vector3d secant = points.col(k) - points_before.col(k);
      const double length2 = secant.squaredNorm();
      if (length2 > 0.0) {
        const double s = (Eigen::Vector3d(x[i], y[i], z[i]) - points.col(k)).dot(secant) / length2;
        value += s * (velocity.col(k) - velocity_before.col(k));
      }
    }
    u[i] = value.x();
    v[i] = value.y();
    w[i] = value.z();
  }
}

}  // namespace flapsim::uvlm
