#pragma once
/// \file skew.hpp
/// \brief The cross-product matrix: skew(v)·w = v × w (the co-rotational FEM's spins, the
/// reduction's strip inertias and chain Jacobians).

#include <Eigen/Core>

namespace flapsim::fem {

inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

}  // namespace flapsim::fem
