#pragma once
/// \file block_rotation.hpp
/// \brief The element transformation T = diag(R, R, …, R): one 3×3 block per
/// translation or rotation triple, so that K_global = Tᵀ K_local T.

#include <Eigen/Core>

namespace flapsim::fem {

/// \param R  rows are the element's local axes in global coordinates
template <int N>
Eigen::Matrix<double, N, N> block_rotation(const Eigen::Matrix3d& R) {
  static_assert(N % 3 == 0, "one 3x3 block per triple of DOFs");
  Eigen::Matrix<double, N, N> T = Eigen::Matrix<double, N, N>::Zero();
  for (int blk = 0; blk < N / 3; ++blk) T.template block<3, 3>(3 * blk, 3 * blk) = R;
  return T;
}

}  // namespace flapsim::fem
