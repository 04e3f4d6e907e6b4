#pragma once
/// \file axis_frame.hpp
/// \brief The flexural-axis frame of the reduction: a straight line in the wing plane
/// at an angle ψ to y_W, passing the pivot (wing-frame origin) at the chordwise
/// offset n₀ (zero: through the pivot)
/// (docs/reduction.md, "Frames and the flexural axis").

#include <Eigen/Core>

#include <cmath>

namespace flapsim::reduction {

/// Axis frame A: e_s along the flexural axis (span), e_n in the wing plane toward
/// the leading edge, e_z = e_n × e_s = z_W. Body frames of the chain are this frame
/// translated to each joint (body x = e_n, body y = e_s).
struct AxisFrame {
  double psi = 0.0;     ///< angle from y_W toward +x_W [rad]
  double offset = 0.0;  ///< n₀: the line's point nearest the pivot is n₀ e_n [m]

  /// Unit vector along the axis, in W.
  Eigen::Vector3d e_s() const { return {std::sin(psi), std::cos(psi), 0.0}; }
  /// Unit in-plane normal toward the leading edge, in W.
  Eigen::Vector3d e_n() const { return {std::cos(psi), -std::sin(psi), 0.0}; }
  /// Out-of-plane unit vector (z_W).
  static Eigen::Vector3d e_z() { return Eigen::Vector3d::UnitZ(); }
  /// R_WA: columns e_n, e_s, e_z (maps axis-frame components to W).
  Eigen::Matrix3d rotation() const {
    Eigen::Matrix3d r;
    r.col(0) = e_n();
    r.col(1) = e_s();
    r.col(2) = e_z();
    return r;
  }
  /// Span coordinate s of a point in W [m].
  double s(const Eigen::Vector3d& p) const { return p.dot(e_s()); }
  /// Chordwise coordinate n (from the axis, + toward the leading edge) [m].
  double n(const Eigen::Vector3d& p) const { return p.dot(e_n()) - offset; }
  /// The point (s, n, z) of the axis frame, in W [m].
  Eigen::Vector3d point(double s, double n, double z = 0.0) const {
    return s * e_s() + (n + offset) * e_n() + z * e_z();
  }
};

}  // namespace flapsim::reduction
