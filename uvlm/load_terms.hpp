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

/// Surface gradient of a ring-circulation field G over panel (i, j), averaged over the panel
/// [G's unit / m]; G(i, j) gives ring (i, j)'s value (ring_gamma for the solve's Γ).
/// By Green's theorem A n × ∇Γ is the panel's vortex vector: the jumps of Γ across its bound
/// segments times their vectors — the ring's leading segment (on this panel's quarter chord)
/// and half of each of the panel's chordwise sides (shared with the panel beside it; Γ = 0
/// beyond root and tip). So ∇Γ = (vortex vector) × n / A, right on any quadrilateral; on a
/// parallelogram it is the dual-basis gradient g^ab (e_b · ∇Γ) e_a of the two edge-direction
/// differences. The panel's sides, not the ring's: the last ring's sides reach the
/// trailing-edge vortex, whose distance behind the edge follows the time step, while the
/// spanwise jumps of Γ act over the panel's chord (Katz & Plotkin §13.8: Δp from ∂Γ/∂c over
/// the panel's chord Δc and ∂Γ/∂s over its span Δb).
template <class RingGamma>
Eigen::Vector3d panel_gamma_gradient(const VortexLatticeModel& m, const VortexLatticeData& d, int i, int j,
                                     const RingGamma& G) {
  const auto& R = d.ring_nodes;
  const auto& P = d.nodes;
  const Eigen::Vector3d lead = R.col(m.node(i, j + 1)) - R.col(m.node(i, j));
  const Eigen::Vector3d root = P.col(m.node(i + 1, j)) - P.col(m.node(i, j));
  const Eigen::Vector3d tip = P.col(m.node(i + 1, j + 1)) - P.col(m.node(i, j + 1));
  const double g = G(i, j);
  const Eigen::Vector3d vortex =
      (G(i - 1, j) - g) * lead + 0.5 * (g - G(i, j - 1)) * root + 0.5 * (G(i, j + 1) - g) * tip;
  const int k = m.panel(i, j);
  return vortex.cross(d.normal.col(k)) / d.area(k);
}

/// Velocity [m/s] of ring node (q, j) for the surface nodes' velocities V (3 × nodes): the
/// same blend of them as its position.
Eigen::Vector3d ring_node_velocity(const VortexLatticeModel& m, const Eigen::Matrix3Xd& V, int q, int j);
/// The same for the last solve's node velocities.
inline Eigen::Vector3d ring_node_velocity(const VortexLatticeModel& m, const VortexLatticeData& d, int q, int j) {
  return ring_node_velocity(m, d.node_velocities, q, j);
}

/// ∂Γ/∂t of panel k following the panel [m²/s²]: BDF2 over the last two accepted steps,
/// backward Euler after the first one (and always with m.first_order_circulation_rate), and
/// Γ/Δt at the first step (impulsive start).
double gamma_rate(const VortexLatticeModel& m, const VortexLatticeData& d, int k);
/// The factor of the current Γ in gamma_rate [1/s] (3/2Δt for BDF2, 1/Δt for backward Euler).
double gamma_rate_factor(const VortexLatticeModel& m, const VortexLatticeData& d);

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
