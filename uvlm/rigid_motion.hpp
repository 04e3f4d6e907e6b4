#pragma once
/// \file rigid_motion.hpp
/// \brief Whether a point set has moved as a rigid body: the test under which the vortex
/// lattice keeps the influence coefficients that a rigid motion does not change
/// (model.reuse_rigid_influence, vortex_lattice.cpp).

#include <Eigen/Core>

namespace flapsim::uvlm {

/// Deviation from a rigid motion, relative to the size of the point set, below which a
/// motion counts as rigid. A rigid wing's nodes, computed as R·x + t, keep their distances
/// to about 1e-16 of the size; a deviation of 1e-12 of it changes an influence coefficient
/// by about 1e-12 × size/distance, far below the solution's rounding for any lattice of
/// fewer than millions of panels. Any real deformation is many orders larger.
inline constexpr double kRigidMotionTolerance = 1e-12;

/// True if `now` is `before` moved by a proper rigid motion (a rotation and a translation,
/// no reflection) to within tolerance × the size of `before` (its largest distance from
/// its first point): every point keeps its distances to three reference points (the
/// first, the farthest from it, the farthest from the line through those two) and its
/// signed height above their plane. False for different sizes, fewer than three
/// non-collinear points, or non-finite coordinates.
bool is_rigid_motion(const Eigen::Matrix3Xd& before, const Eigen::Matrix3Xd& now,
                     double tolerance = kRigidMotionTolerance);

}  // namespace flapsim::uvlm
