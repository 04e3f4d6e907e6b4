#pragma once
/// \file skew.hpp
/// \brief The cross-product matrix: skew(v)·w = v × w.

#include <Eigen/Core>

namespace flapsim::reduction {

inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

}  // namespace flapsim::reduction
