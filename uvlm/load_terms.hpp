#pragma once
/// \file load_terms.hpp
/// \brief Pieces shared by the two load routes of a solved vortex lattice (Bernoulli,
/// Kutta–Joukowski): ring circulations, points of action and their velocities, ∂Γ/∂t,
/// the leading-edge force and the finishing sums (not a public interface).

#include "uvlm/vortex_lattice.hpp"

namespace flapsim::uvlm::detail {

/// Circulation of ring (i, j) [m²/s]; 0 outside the lattice.
/// Ring (−1, j) is the leading-edge ring of a shedding leading edge (leading_edge_sheet.hpp).
inline double ring_gamma(const VortexLatticeModel& m, const VortexLatticeData& d, int i, int j) {
  if (i == -1 && j >= 0 && j < m.spanwise && d.le_sheet.active()) return d.le_sheet.current(j);
  return (i < 0 || i >= m.chordwise || j < 0 || j >= m.spanwise) ? 0.0 : d.gamma(m.panel(i, j));
}

/// Velocity [m/s] of ring node (q, j): the same blend of surface-node velocities as its position.
Eigen::Vector3d ring_node_velocity(const VortexLatticeModel& m, const VortexLatticeData& d, int q, int j);

/// ∂Γ/∂t of panel k following the panel [m²/s²]: BDF2 over the last two accepted steps,
/// backward Euler after the first one, and Γ/Δt at the first step (impulsive start).
double gamma_rate(const VortexLatticeData& d, int k);

/// Sets loads.point (the panel's quarter-chord point, the midpoint of its ring's leading
/// segment) and loads.point_velocity for every panel.
void set_points_of_action(const VortexLatticeModel& m, VortexLatticeData& d);

/// In-plane part [N] of a Kutta–Joukowski force f on the spanwise bound segment of panel k.
inline Eigen::Vector3d in_plane(const VortexLatticeData& d, int k, const Eigen::Vector3d& f) {
  const auto n = d.normal.col(k);
  return f - f.dot(n) * n;
}

/// The leading-edge force of strip j from its suction [N], the sum of the in-plane parts of
/// the Kutta–Joukowski forces on the strip's spanwise bound segments: records its magnitude
/// and returns what model.leading_edge makes of it (in plane, along the normal, or nothing).
Eigen::Vector3d leading_edge_force(const VortexLatticeModel& m, VortexLatticeData& d, int j,
                                   const Eigen::Vector3d& suction);

/// Total force, pressure jumps and power from loads.force and loads.point_velocity.
void finish_loads(VortexLatticeData& d);

}  // namespace flapsim::uvlm::detail
