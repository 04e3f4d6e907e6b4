/// \file aero_loads.cpp
/// \brief Panel loads of a solved vortex lattice: the unsteady Bernoulli pressure jump
/// (Katz & Plotkin §13.8) and Kutta–Joukowski on the bound segments; both add the
/// ρ ∂Γ/∂t A n term, with ∂Γ/∂t from the last accepted step.

#include "uvlm/lattice_internal.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::uvlm {

namespace {

double ring_gamma(const VortexLatticeModel& m, const VortexLatticeData& d, int i, int j) {
  return (i < 0 || i >= m.chordwise || j < 0 || j >= m.spanwise) ? 0.0 : d.gamma(m.panel(i, j));
}

/// Quarter-chord point of panel k: the midpoint of its ring's leading segment.
Eigen::Vector3d quarter_chord_point(const VortexLatticeModel& m, const VortexLatticeData& d, int i, int j) {
  return 0.5 * (d.ring_nodes.col(m.node(i, j)) + d.ring_nodes.col(m.node(i, j + 1)));
}

/// Velocity of the ring node (q, j): the same blend of surface-node velocities as its position.
Eigen::Vector3d ring_node_velocity(const VortexLatticeModel& m, const VortexLatticeData& d, int q, int j) {
  const auto& V = d.node_velocities;
  if (q < m.chordwise) return V.col(m.node(q, j)) + 0.25 * (V.col(m.node(q + 1, j)) - V.col(m.node(q, j)));
  return V.col(m.node(q, j)) + 0.25 * (V.col(m.node(q, j)) - V.col(m.node(q - 1, j)));
}

void finish(VortexLatticeData& d) {
  d.loads.total_force = d.loads.force.rowwise().sum();
  for (Eigen::Index k = 0; k < d.loads.force.cols(); ++k)
    d.loads.pressure_jump(k) = d.loads.force.col(k).dot(d.normal.col(k)) / d.area(k);
}

}  // namespace

void compute_bernoulli_loads(const VortexLatticeModel& m, VortexLatticeData& d) {
  const int nc = m.chordwise, ns = m.spanwise, np = m.panels();
  // Bound-induced velocity at the collocation points (the tangential part matters on a
  // curved or deformed surface; on a flat one it is normal to the panels).
  for (int k = 0; k < np; ++k) d.eval.set(k, d.collocation.col(k));
  d.eval.size = np;
  d.eval.zero_velocity();
  add_induced_velocity(d.bound_segments, d.eval, m.bound_core());
  add_induced_velocity(d.trailing_edge_segments, d.eval, m.core);
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nc; ++i) {
      const int k = m.panel(i, j);
      const Eigen::Vector3d vrel =
          d.free_stream - d.surface_velocity.col(k) + d.wake_velocity.col(k) + d.eval.velocity(k);
      const double g = d.gamma(k);
      // Chordwise: backward difference (the ring's leading segment lies in this panel).
      const double dgc = (g - ring_gamma(m, d, i - 1, j)) / d.chord_length(k);
      // Spanwise: central difference over the panel, Γ = 0 beyond root and tip, so each
      // chordwise segment's jump is shared by the two panels beside it.
      const double dgs = (ring_gamma(m, d, i, j + 1) - ring_gamma(m, d, i, j - 1)) / (2.0 * d.span_length(k));
      const double dgt = (g - d.gamma_accepted(k)) / d.dt;
      const double dp = d.rho * (vrel.dot(d.chord_tangent.col(k)) * dgc +
                                 vrel.dot(d.span_tangent.col(k)) * dgs + dgt);
      d.loads.force.col(k) = dp * d.area(k) * d.normal.col(k);
      d.loads.point.col(k) = quarter_chord_point(m, d, i, j);
    }
  finish(d);
}

void compute_kutta_joukowski_loads(const VortexLatticeModel& m, VortexLatticeData& d) {
  const int nc = m.chordwise, ns = m.spanwise;
  const auto& S = d.bound_segments;
  const std::size_t nb = S.size();
  for (std::size_t s = 0; s < nb; ++s) {
    d.eval.x[s] = 0.5 * (S.ax()[s] + S.bx()[s]);
    d.eval.y[s] = 0.5 * (S.ay()[s] + S.by()[s]);
    d.eval.z[s] = 0.5 * (S.az()[s] + S.bz()[s]);
  }
  // Wake and bound velocity at the midpoints; a segment adds nothing at its own midpoint
  // (the core factor vanishes on its line), so "excluding itself" needs no special case.
  detail::induced_at_eval_points(m, d, nb, true);

  for (int k = 0; k < m.panels(); ++k) {
    const double dgt = (d.gamma(k) - d.gamma_accepted(k)) / d.dt;
    d.loads.force.col(k) = d.rho * dgt * d.area(k) * d.normal.col(k);
  }
  auto segment_force = [&](std::size_t s, const Eigen::Vector3d& surface_vel) {
    const Eigen::Vector3d a(S.ax()[s], S.ay()[s], S.az()[s]), b(S.bx()[s], S.by()[s], S.bz()[s]);
    const Eigen::Vector3d v = d.free_stream - surface_vel + d.eval.velocity(s);
    return Eigen::Vector3d(d.rho * S.gamma()[s] * v.cross(b - a));
  };
  // Spanwise segments (same order as build_bound_segments): row q < nc is the leading
  // segment of ring q and loads panel (q, j); the trailing edge (another set) is shed
  // vorticity and carries no load.
  std::size_t s = 0;
  for (int q = 0; q < nc; ++q)
    for (int j = 0; j < ns; ++j, ++s) {
      const Eigen::Vector3d sv = 0.5 * (ring_node_velocity(m, d, q, j) + ring_node_velocity(m, d, q, j + 1));
      d.loads.force.col(m.panel(q, j)) += segment_force(s, sv);
    }
  // Chordwise segments: shared between the panels on either side.
  for (int j = 0; j <= ns; ++j)
    for (int q = 0; q < nc; ++q, ++s) {
      const Eigen::Vector3d sv = 0.5 * (ring_node_velocity(m, d, q, j) + ring_node_velocity(m, d, q + 1, j));
      const Eigen::Vector3d f = segment_force(s, sv);
      if (j == 0) {
        d.loads.force.col(m.panel(q, 0)) += f;
      } else if (j == ns) {
        d.loads.force.col(m.panel(q, ns - 1)) += f;
      } else {
        d.loads.force.col(m.panel(q, j - 1)) += 0.5 * f;
        d.loads.force.col(m.panel(q, j)) += 0.5 * f;
      }
    }
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nc; ++i) d.loads.point.col(m.panel(i, j)) = quarter_chord_point(m, d, i, j);
  finish(d);
}

}  // namespace flapsim::uvlm
