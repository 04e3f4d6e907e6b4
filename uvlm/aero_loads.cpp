/// \file aero_loads.cpp
/// \brief The Bernoulli route of the panel loads: the unsteady pressure jump from the
/// surface gradient of Γ (Katz & Plotkin §13.8, written for any quadrilateral), plus the
/// leading-edge force; and the pieces both routes share (load_terms.hpp).

#include "uvlm/lattice_internal.hpp"
#include "uvlm/leading_edge_side.hpp"
#include "uvlm/load_terms.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <cmath>

namespace flapsim::uvlm {

namespace detail {

Eigen::Vector3d ring_node_velocity(const VortexLatticeModel& m, const Eigen::Matrix3Xd& V, int q, int j) {
  if (q < m.chordwise) return V.col(m.node(q, j)) + 0.25 * (V.col(m.node(q + 1, j)) - V.col(m.node(q, j)));
  return V.col(m.node(q, j)) + 0.25 * (V.col(m.node(q, j)) - V.col(m.node(q - 1, j)));
}

double gamma_rate(const VortexLatticeModel& m, const VortexLatticeData& d, int k) {
  if (d.accepted_steps >= 2 && !m.first_order_circulation_rate)
    return (3.0 * d.gamma(k) - 4.0 * d.gamma_accepted(k) + d.gamma_accepted_before(k)) / (2.0 * d.dt);
  return (d.gamma(k) - d.gamma_accepted(k)) / d.dt;
}

double gamma_rate_factor(const VortexLatticeModel& m, const VortexLatticeData& d) {
  return (d.accepted_steps >= 2 && !m.first_order_circulation_rate ? 1.5 : 1.0) / d.dt;
}

void set_points_of_action(const VortexLatticeModel& m, VortexLatticeData& d) {
  for (int j = 0; j < m.spanwise; ++j)
    for (int i = 0; i < m.chordwise; ++i) {
      const int k = m.panel(i, j);
      d.loads.point.col(k) = 0.5 * (d.ring_nodes.col(m.node(i, j)) + d.ring_nodes.col(m.node(i, j + 1)));
      d.loads.point_velocity.col(k) = 0.5 * (ring_node_velocity(m, d, i, j) + ring_node_velocity(m, d, i, j + 1));
    }
}

Eigen::Vector3d leading_edge_force(const VortexLatticeModel& m, VortexLatticeData& d, int j,
                                   const Eigen::Vector3d& suction) {
  const int k = m.panel(0, j);
  const double magnitude = suction.norm();
  d.loads.suction.col(j) = suction;
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  switch (m.leading_edge) {
    case LeadingEdge::None: break;
    case LeadingEdge::Attached: out = suction; break;
    case LeadingEdge::Shed:  // the suction the edge holds (leading_edge_loads.cpp)
      out = shed_edge_force(m, d, j, suction);
      break;
    case LeadingEdge::Separated:
      // Polhamus: the suction's magnitude acts normal to the surface, on the side the
      // leading-edge bound vortex lifts toward (a positive ring circulation pushes along +n;
      // leading_edge_side.hpp).
      out = (leading_edge_side(m, d, j) * magnitude) * d.normal.col(k);
      break;
  }
  d.loads.leading_edge_force.col(k) = out;
  return out;
}

void finish_loads(VortexLatticeData& d) {
  // Summed panel by panel in index order: the same bits whatever the build's vectorisation
  // of a reduction (Eigen's rowwise sum may split it by the data's alignment).
  d.loads.total_force.setZero();
  for (Eigen::Index k = 0; k < d.loads.force.cols(); ++k) d.loads.total_force += d.loads.force.col(k);
  d.loads.power = 0.0;
  for (Eigen::Index k = 0; k < d.loads.force.cols(); ++k) {
    d.loads.pressure_jump(k) = d.loads.force.col(k).dot(d.normal.col(k)) / d.area(k);
    d.loads.power -= d.loads.force.col(k).dot(d.loads.point_velocity.col(k));
  }
}

}  // namespace detail

namespace {

/// The suction of every strip: Kutta–Joukowski forces on the spanwise bound segments (rows
/// q < nc, the first nc·ns of build_bound_segments), their in-plane parts summed per strip,
/// through detail::leading_edge_force into loads.leading_edge_force.
void add_leading_edge_forces(const VortexLatticeModel& m, VortexLatticeData& d) {
  const int nc = m.chordwise, ns = m.spanwise;
  const std::size_t n = detail::loads_midpoints(LoadMethod::Bernoulli, m, d);  // nc·ns
  const auto& S = d.bound_segments;
  detail::induced_at_bound_midpoints(m, d, n);  // each segment's own velocity left out
  d.loads.leading_edge_force.setZero();
  for (int j = 0; j < ns; ++j) {
    Eigen::Vector3d suction = Eigen::Vector3d::Zero();
    for (int q = 0; q < nc; ++q) {
      const std::size_t s = static_cast<std::size_t>(q) * ns + j;
      const Eigen::Vector3d a(S.ax()[s], S.ay()[s], S.az()[s]), b(S.bx()[s], S.by()[s], S.bz()[s]);
      const Eigen::Vector3d surface =
          0.5 * (detail::ring_node_velocity(m, d, q, j) + detail::ring_node_velocity(m, d, q, j + 1));
      const Eigen::Vector3d v = d.free_stream - surface + d.eval.velocity(s);
      d.segment_air_velocity.col(static_cast<Eigen::Index>(s)) = v;
      suction += detail::in_plane(d, m.panel(q, j), d.rho * S.gamma()[s] * v.cross(b - a));
    }
    detail::leading_edge_force(m, d, j, suction);
  }
}

}  // namespace

void compute_bernoulli_loads(const VortexLatticeModel& model, VortexLatticeData& d) {
  const VortexLatticeModel m = detail::solved_lattice_model(model, d);  // a steady solve's own
  using detail::ring_gamma;
  const int nc = m.chordwise, ns = m.spanwise, np = m.panels();
  add_leading_edge_forces(m, d);
  // Bound-induced velocity at the collocation points (the tangential part matters on a
  // curved or deformed surface; on a flat one it is normal to the panels).
  // On the threads of one parallel region, each point's sum as on one thread
  // (detail::for_target_chunks): the same bits whatever the thread count.
  for (int k = 0; k < np; ++k) d.eval.set(k, d.collocation.col(k));
  d.eval.size = np;
  d.eval.zero_velocity();
  const std::size_t segments = d.bound_segments.size() + d.trailing_edge_segments.size();
  detail::for_target_chunks(static_cast<std::size_t>(np), static_cast<std::size_t>(np) * segments,
                            [&](std::size_t i0, std::size_t c) {
                              PointSet& e = d.eval;
                              const double *x = e.x.data() + i0, *y = e.y.data() + i0, *z = e.z.data() + i0;
                              double *u = e.u.data() + i0, *v = e.v.data() + i0, *w = e.w.data() + i0;
                              add_induced_velocity(d.bound_segments, x, y, z, c, u, v, w, m.bound_core());
                              add_induced_velocity(d.trailing_edge_segments, x, y, z, c, u, v, w, m.core);
                            });
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nc; ++i) {
      const int k = m.panel(i, j);
      const Eigen::Vector3d vrel =
          d.free_stream - d.surface_velocity.col(k) + d.wake_velocity.col(k) + d.eval.velocity(k);
      const Eigen::Vector3d n = d.normal.col(k);
      const Eigen::Vector3d grad =
          detail::panel_gamma_gradient(m, d, i, j, [&](int a, int b) { return ring_gamma(m, d, a, b); });
      d.panel_air_velocity.col(k) = vrel;
      d.panel_gamma_gradient.col(k) = grad;
      const double rate = detail::gamma_rate(m, d, k);  // [m²/s²]
      const double dp = d.rho * (vrel.dot(grad) + rate);
      d.loads.unsteady_force.col(k) = d.rho * rate * d.area(k) * n;
      d.loads.force.col(k) = dp * d.area(k) * n + d.loads.leading_edge_force.col(k);
    }
  detail::set_points_of_action(m, d);
  detail::finish_loads(d);
}

}  // namespace flapsim::uvlm
