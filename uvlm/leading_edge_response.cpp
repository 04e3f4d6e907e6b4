/// \file leading_edge_response.cpp
/// \brief The leading-edge force's response to a node-velocity change, held and
/// re-evaluated (leading_edge_response.hpp).

#include "uvlm/leading_edge_response.hpp"
#include "uvlm/lattice_internal.hpp"
#include "uvlm/leading_edge_side.hpp"
#include "uvlm/load_terms.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace flapsim::uvlm {

namespace {

/// The orthonormal frame of panel k (columns: chordwise, spanwise, normal).
Eigen::Matrix3d panel_frame(const VortexLatticeData& d, int k) {
  const Eigen::Vector3d n = d.normal.col(k);
  const Eigen::Vector3d c = (d.chord_tangent.col(k) - d.chord_tangent.col(k).dot(n) * n).normalized();
  Eigen::Matrix3d f;
  f << c, n.cross(c), n;
  return f;
}

}  // namespace

LeadingEdgeScratch::LeadingEdgeScratch(const VortexLatticeModel& m) {
  const std::size_t nc = static_cast<std::size_t>(m.chordwise), ns = static_cast<std::size_t>(m.spanwise);
  bound.reserve(nc * ns + (ns + 1) * nc);
  trailing_edge.reserve(ns);
  midpoints.reserve(nc * ns);
}

bool leading_edge_responds(const VortexLatticeModel& m) {
  return m.leading_edge == LeadingEdge::Attached || m.leading_edge == LeadingEdge::Separated;
}

void hold_leading_edge_column(const VortexLatticeModel& m, const VortexLatticeData& d,
                              const Eigen::VectorXd& dgamma, const Eigen::Matrix3Xd& dv,
                              LeadingEdgeScratch& s, LeadingEdgeColumn& column) {
  const int nc = m.chordwise, ns = m.spanwise;
  const std::size_t n = static_cast<std::size_t>(nc) * ns;
  if (dgamma.size() != m.panels() || dv.cols() != m.nodes())
    throw std::invalid_argument("hold_leading_edge_column: " + std::to_string(dgamma.size()) + " circulations and " +
                                std::to_string(dv.cols()) + " node velocities for a lattice of " +
                                std::to_string(m.panels()) + " panels");
  const auto G = [&](int i, int j) {
    return (i < 0 || i >= nc || j < 0 || j >= ns) ? 0.0 : dgamma(m.panel(i, j));
  };
  // The lattice's segments with δΓ (as build_bound_segments, the same order).
  s.bound.clear();
  s.trailing_edge.clear();
  detail::push_ring_segments(m, d.ring_nodes, G, s.bound, s.trailing_edge);
  // Their induced velocity at the spanwise segments' midpoints, each segment's own left out
  // (vortex_lattice.cpp induced_at_bound_midpoints).
  PointSet& p = s.midpoints;
  const SegmentSet& B = d.bound_segments;
  for (std::size_t k = 0; k < n; ++k)
    p.set(k, 0.5 * Eigen::Vector3d(B.ax()[k] + B.bx()[k], B.ay()[k] + B.by()[k], B.az()[k] + B.bz()[k]));
  p.size = n;
  p.zero_velocity();
  add_induced_velocity(s.bound, p.x.data(), p.y.data(), p.z.data(), n, p.u.data(), p.v.data(), p.w.data(),
                       m.bound_core());
  add_induced_velocity(s.trailing_edge, p.x.data(), p.y.data(), p.z.data(), n, p.u.data(), p.v.data(),
                       p.w.data(), m.core);
  column.segment_gamma_change.resize(static_cast<Eigen::Index>(n));
  column.velocity_change.resize(3, static_cast<Eigen::Index>(n));
  for (int q = 0; q < nc; ++q)
    for (int j = 0; j < ns; ++j) {
      const std::size_t k = static_cast<std::size_t>(q) * ns + j;
      const Eigen::Vector3d induced = p.velocity(k) - segment_velocity(s.bound, k, p.position(k), m.bound_core());
      const Eigen::Vector3d surface = 0.5 * (detail::ring_node_velocity(m, dv, q, j) + detail::ring_node_velocity(m, dv, q, j + 1));
      column.segment_gamma_change(static_cast<Eigen::Index>(k)) = s.bound.gamma()[k];  // δγ_s
      column.velocity_change.col(static_cast<Eigen::Index>(k)) =
          panel_frame(d, m.panel(q, j)).transpose() * (induced - surface);
    }
}

void add_leading_edge_force_change(const VortexLatticeModel& m, const VortexLatticeData& d,
                                   const LeadingEdgeColumn& column, Eigen::Matrix3Xd& df) {
  if (!leading_edge_responds(m)) return;
  const int nc = m.chordwise, ns = m.spanwise;
  const Eigen::Index n = static_cast<Eigen::Index>(nc) * ns;
  if (column.segment_gamma_change.size() != n || df.cols() != m.panels())
    throw std::invalid_argument("add_leading_edge_force_change: a column or forces of another lattice");
  const SegmentSet& B = d.bound_segments;
  for (int j = 0; j < ns; ++j) {
    Eigen::Vector3d ds = Eigen::Vector3d::Zero();
    for (int q = 0; q < nc; ++q) {
      const std::size_t s = static_cast<std::size_t>(q) * ns + j;
      const int k = m.panel(q, j);
      const Eigen::Vector3d l(B.bx()[s] - B.ax()[s], B.by()[s] - B.ay()[s], B.bz()[s] - B.az()[s]);
      const Eigen::Vector3d v = d.segment_air_velocity.col(static_cast<Eigen::Index>(s));
      const Eigen::Vector3d dw = panel_frame(d, k) * column.velocity_change.col(static_cast<Eigen::Index>(s));
      const double dgamma = column.segment_gamma_change(static_cast<Eigen::Index>(s));
      ds += detail::in_plane(d, k, d.rho * (dgamma * v.cross(l) + B.gamma()[s] * dw.cross(l)));
    }
    const int k0 = m.panel(0, j);
    if (m.leading_edge == LeadingEdge::Attached) {
      df.col(k0) += ds;
    } else {
      const Eigen::Vector3d suction = d.loads.suction.col(j);
      const double magnitude = suction.norm();
      if (magnitude > 0.0)
        df.col(k0) += (leading_edge_side(m, d, j) * suction.dot(ds) / magnitude) * d.normal.col(k0);
    }
  }
}

}  // namespace flapsim::uvlm
