/// \file kutta_joukowski_loads.cpp
/// \brief The Kutta–Joukowski route of the panel loads: ρ Γ (V × dl) on every bound
/// segment, with V the relative air velocity at the segment's midpoint, plus ρ ∂Γ/∂t A n
/// per panel; the in-plane forces on a strip's spanwise segments are its leading-edge suction.

#include "uvlm/lattice_internal.hpp"
#include "uvlm/load_terms.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::uvlm {

void compute_kutta_joukowski_loads(const VortexLatticeModel& model, VortexLatticeData& d) {
  const VortexLatticeModel m = detail::solved_lattice_model(model, d);  // a steady solve's own
  const int nc = m.chordwise, ns = m.spanwise;
  const auto& S = d.bound_segments;
  d.panel_air_velocity.setZero();  // the Bernoulli route's terms (vortex_lattice.hpp)
  d.panel_gamma_gradient.setZero();
  // Wake, trailing-edge and bound velocity at the midpoints, each segment's own left out
  // (lattice_internal.hpp: rounding puts the midpoint inside its tiny core, off its line).
  detail::induced_at_bound_midpoints(m, d, detail::loads_midpoints(LoadMethod::KuttaJoukowski, m, d));  // all of S

  for (int k = 0; k < m.panels(); ++k)
    d.loads.unsteady_force.col(k) = d.rho * detail::gamma_rate(m, d, k) * d.area(k) * d.normal.col(k);
  d.loads.force = d.loads.unsteady_force;
  d.loads.leading_edge_force.setZero();
  auto segment_force = [&](std::size_t s, const Eigen::Vector3d& surface_vel) {
    const Eigen::Vector3d a(S.ax()[s], S.ay()[s], S.az()[s]), b(S.bx()[s], S.by()[s], S.bz()[s]);
    const Eigen::Vector3d v = d.free_stream - surface_vel + d.eval.velocity(s);
    return Eigen::Vector3d(d.rho * S.gamma()[s] * v.cross(b - a));
  };
  // Spanwise segments (same order as build_bound_segments): row q < nc is the leading
  // segment of ring q and loads panel (q, j); the trailing edge (another set) is shed
  // vorticity and carries no load. Each force's normal part stays on its panel; the in-plane parts of a strip's spanwise-segment forces add up to its suction, which
  // acts at the leading edge as model.leading_edge says (in a continuous sheet the only
  // in-plane force is the leading-edge singularity; on the lattice it is spread over the
  // bound vortices, because the boundary condition holds at the collocation points).
  std::size_t s = 0;
  Eigen::Matrix3Xd& suction = d.loads.suction;
  suction.setZero();
  for (int q = 0; q < nc; ++q)
    for (int j = 0; j < ns; ++j, ++s) {
      const Eigen::Vector3d sv =
          0.5 * (detail::ring_node_velocity(m, d, q, j) + detail::ring_node_velocity(m, d, q, j + 1));
      const Eigen::Vector3d f = segment_force(s, sv);
      d.segment_air_velocity.col(static_cast<Eigen::Index>(s)) = d.free_stream - sv + d.eval.velocity(s);
      const int k = m.panel(q, j);
      const Eigen::Vector3d tangential = detail::in_plane(d, k, f);
      d.loads.force.col(k) += f - tangential;
      suction.col(j) += tangential;
    }
  for (int j = 0; j < ns; ++j) d.loads.force.col(m.panel(0, j)) += detail::leading_edge_force(m, d, j, Eigen::Vector3d(suction.col(j)));
  // Chordwise segments: shared between the panels on either side.
  for (int j = 0; j <= ns; ++j)
    for (int q = 0; q < nc; ++q, ++s) {
      const Eigen::Vector3d sv =
          0.5 * (detail::ring_node_velocity(m, d, q, j) + detail::ring_node_velocity(m, d, q + 1, j));
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
  detail::set_points_of_action(m, d);
  detail::finish_loads(d);
}

}  // namespace flapsim::uvlm
