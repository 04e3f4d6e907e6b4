#include "uvlm/rigid_motion.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace flapsim::uvlm {

bool is_rigid_motion(const Eigen::Matrix3Xd& before, const Eigen::Matrix3Xd& now, double tolerance) {
  const Eigen::Index n = before.cols();
  if (now.cols() != n || n < 3) return false;
  const Eigen::Vector3d p0 = before.col(0);
  // Reference points (chosen in `before`): 0, b the farthest from it, c the farthest from
  // the line through 0 and b.
  Eigen::Index b = 0, c = 0;
  double size2 = 0.0;
  for (Eigen::Index k = 1; k < n; ++k)
    if (const double d2 = (before.col(k) - p0).squaredNorm(); d2 > size2) size2 = d2, b = k;
  const double size = std::sqrt(size2);
  if (!(size > 0.0) || !std::isfinite(size)) return false;
  const Eigen::Vector3d e = (before.col(b) - p0) / size;
  double off_line = 0.0;
  for (Eigen::Index k = 1; k < n; ++k)
    if (const double h = (before.col(k) - p0).cross(e).norm(); h > off_line) off_line = h, c = k;
  if (!(off_line > 1e-6 * size)) return false;  // (nearly) collinear: the motion is not determined
  const double tol = tolerance * size;
  // Signed height of point k above the reference plane, in `x` [m].
  auto height = [&](const Eigen::Matrix3Xd& x, Eigen::Index k) {
    const Eigen::Vector3d nrm = (x.col(b) - x.col(0)).cross(x.col(c) - x.col(0));
    return nrm.dot(x.col(k) - x.col(0)) / nrm.norm();
  };
  for (Eigen::Index k = 0; k < n; ++k) {
    for (Eigen::Index r : {Eigen::Index{0}, b, c}) {
      const double d_before = (before.col(k) - before.col(r)).norm();
      const double d_now = (now.col(k) - now.col(r)).norm();
      if (!(std::abs(d_now - d_before) <= tol)) return false;  // also false for NaN
    }
    if (!(std::abs(height(now, k) - height(before, k)) <= tol)) return false;
  }
  return true;
}

}  // namespace flapsim::uvlm
