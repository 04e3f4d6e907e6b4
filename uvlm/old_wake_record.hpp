#pragma once
/// \file old_wake_record.hpp
/// \brief The older wake's velocity at one of the wing's point sets, as the last two
/// solves of a step summed it, and the held value at moved points (old_wake_hold.hpp).
///
/// Held at a point that moved from its last recorded place x₂ by Δ, the velocity is the
/// last record u₂ plus the change along the last two records' secant: u₂ + s (u₂ − u₁),
/// s = Δ·(x₂ − x₁)/|x₂ − x₁|² (0 with one record, or where the point did not move between
/// them). A coupling's sub-iterations move the wing along nearly the same direction, so the
/// secant takes the first-order change of the velocity along it; at x₂ itself s = 0 and the
/// value is u₂'s bits.

#include <Eigen/Core>

#include <cstddef>

namespace flapsim::uvlm {

struct OldWakeRecord {
  Eigen::Matrix3Xd velocity, points;                ///< the last record [m/s], [m]
  Eigen::Matrix3Xd velocity_before, points_before;  ///< the one before it
  std::size_t size = 0;  ///< points recorded (0: none since the last advance)
  int records = 0;       ///< records of `size` points since the last advance

  /// Storage for up to n points (nothing allocated afterwards).
  void reserve(std::size_t n);
  /// Forget the records (the wake has moved).
  void clear() { size = 0, records = 0; }
  /// Record points [i0, i0 + n) at (x, y, z) with velocities (u, v, w), the last record
  /// becoming the one before.
  void record(std::size_t i0, std::size_t n, const double* x, const double* y, const double* z, const double* u,
              const double* v, const double* w);
  /// After the records of all `points` points: size and count (file comment).
  void finish(std::size_t points);
  /// The held velocity (file comment) of points [i0, i0 + n) at (x, y, z) into (u, v, w).
  void held(std::size_t i0, std::size_t n, const double* x, const double* y, const double* z, double* u, double* v,
            double* w) const;
};

}  // namespace flapsim::uvlm
