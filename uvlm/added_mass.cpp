/// \file added_mass.cpp
/// \brief The linearised added-mass response of the lattice's loads (added_mass.hpp).

#include "uvlm/added_mass.hpp"

#include <stdexcept>
#include <string>

namespace flapsim::uvlm {

namespace {

// δv of ring node (q, j): the blend of ring_node_velocity (aero_loads.cpp).
Eigen::Vector3d ring_node_change(const VortexLatticeModel& m, const Eigen::Matrix3Xd& dv, int q, int j) {
  if (q < m.chordwise) return dv.col(m.node(q, j)) + 0.25 * (dv.col(m.node(q + 1, j)) - dv.col(m.node(q, j)));
  return dv.col(m.node(q, j)) + 0.25 * (dv.col(m.node(q, j)) - dv.col(m.node(q - 1, j)));
}

// The leading-edge force's change: the suction of strip j, S = Σ_q in-plane part of
// ρ Γ_s (v_s × (b − a)) over its spanwise segments, changes by ρ δΓ_s (v_s × (b − a)) +
// ρ Γ_s (−δv_s × (b − a)) (v_s held but for the surface's own velocity), and the force by
// the model: attached δS; separated (Ŝ · δS) along ±n; none and shed nothing.
void add_suction_change(const VortexLatticeModel& m, const VortexLatticeData& d, const Eigen::Matrix3Xd& dv,
                        const AddedMassScratch& s, Eigen::Matrix3Xd& df) {
  if (m.leading_edge != LeadingEdge::Attached && m.leading_edge != LeadingEdge::Separated) return;
  const int nc = m.chordwise, ns = m.spanwise;
  const auto& S = d.bound_segments;
  if (S.size() < static_cast<std::size_t>(nc) * ns) return;
  const auto dgamma = [&](int i, int j) { return (i < 0 || i >= nc) ? 0.0 : s.dgamma(m.panel(i, j)); };
  for (int j = 0; j < ns; ++j) {
    Eigen::Vector3d change = Eigen::Vector3d::Zero();
    for (int q = 0; q < nc; ++q) {
      const std::size_t i = static_cast<std::size_t>(q) * ns + j;
      const Eigen::Vector3d a(S.ax()[i], S.ay()[i], S.az()[i]), b(S.bx()[i], S.by()[i], S.bz()[i]);
      const Eigen::Vector3d surface = 0.5 * (ring_node_change(m, dv, q, j) + ring_node_change(m, dv, q, j + 1));
      const double g = dgamma(q - 1, j) - dgamma(q, j);  // build_bound_segments' Γ_s
      Eigen::Vector3d f = d.rho * (g * d.segment_air_velocity.col(static_cast<Eigen::Index>(i)) - S.gamma()[i] * surface)
                                      .cross(b - a);
      const auto n = d.normal.col(m.panel(q, j));
      change += f - f.dot(n) * n;
    }
    const int k = m.panel(0, j);
    if (m.leading_edge == LeadingEdge::Attached) {
      df.col(k) += change;
    } else {
      const Eigen::Vector3d suction = d.loads.suction.col(j);
      const double size = suction.norm();
      if (size > 0.0) df.col(k) += (d.gamma(k) >= 0.0 ? 1.0 : -1.0) * (suction.dot(change) / size) * d.normal.col(k);
    }
  }
}

}  // namespace

void added_mass_force_change(const VortexLatticeModel& m, const VortexLatticeData& d,
                             const Eigen::Matrix3Xd& dv, AddedMassScratch& s, Eigen::Matrix3Xd& df,
                             AddedMassTerms terms) {
  const int nc = m.chordwise, ns = m.spanwise, np = m.panels();
  if (dv.cols() != m.nodes())
    throw std::invalid_argument("added_mass_force_change: " + std::to_string(dv.cols()) +
                                " node velocities for a lattice of " + std::to_string(m.nodes()) + " nodes");
  if (s.rhs.size() != np) throw std::invalid_argument("added_mass_force_change: scratch of another lattice");
  df.setZero(3, np);
  if (m.steady()) return;  // ∂Γ/∂t = 0
  if (!d.has_factorisation || !(d.dt > 0.0))
    throw std::invalid_argument("added_mass_force_change: the lattice has not been solved yet");
  // δrhs_k = n_k · δv at the collocation point (the interpolation of update_geometry).
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nc; ++i) {
      const int k = m.panel(i, j);
      const auto va = dv.col(m.node(i, j)), vb = dv.col(m.node(i + 1, j));
      const auto vc = dv.col(m.node(i, j + 1)), ve = dv.col(m.node(i + 1, j + 1));
      s.surface_velocity.col(k) = 0.5 * ((va + 0.75 * (vb - va)) + (vc + 0.75 * (ve - vc)));
      s.rhs(k) = s.surface_velocity.col(k).dot(d.normal.col(k));
    }
  s.dgamma = d.lu.solve(s.rhs);  // exact when lu factorises the current matrix
  if (!d.factorisation_current && s.gmres.size() == np) {
    // The iterative path: GMRES on the current matrix from the earlier matrix's answer.
    const PreconditionedGmres::Result r =
        s.gmres.solve(d.influence, d.lu, s.rhs, s.dgamma, m.iterative_tolerance, m.iterative_max_iterations);
    if (!r.converged) s.dgamma = d.lu.solve(s.rhs);  // the preconditioner's answer: approximate
  }
  // ∂Γ/∂t's factor on the current Γ (aero_loads.cpp gamma_rate: BDF2 from the second step).
  const double rate = (d.accepted_steps >= 2 ? 1.5 : 1.0) / d.dt;
  const auto dgamma = [&](int i, int j) {
    return (i < 0 || i >= nc || j < 0 || j >= ns) ? 0.0 : s.dgamma(m.panel(i, j));
  };
  const auto& R = d.ring_nodes;
  const auto& P = d.nodes;
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nc; ++i) {
      const int k = m.panel(i, j);
      double dp = rate * s.dgamma(k);
      if (terms != AddedMassTerms::Unsteady) {
        // δ(V · ∇Γ) = −δv_s · ∇Γ + V · ∇δΓ, ∇δΓ by the loads' own vortex-vector formula
        // (aero_loads.cpp); zero where the loads did not keep V and ∇Γ (Kutta–Joukowski).
        const Eigen::Vector3d lead = R.col(m.node(i, j + 1)) - R.col(m.node(i, j));
        const Eigen::Vector3d root = P.col(m.node(i + 1, j)) - P.col(m.node(i, j));
        const Eigen::Vector3d tip = P.col(m.node(i + 1, j + 1)) - P.col(m.node(i, j + 1));
        const double g = s.dgamma(k);
        const Eigen::Vector3d vortex = (dgamma(i - 1, j) - g) * lead + 0.5 * (g - dgamma(i, j - 1)) * root +
                                       0.5 * (dgamma(i, j + 1) - g) * tip;
        const Eigen::Vector3d grad = vortex.cross(d.normal.col(k)) / d.area(k);
        dp += d.panel_air_velocity.col(k).dot(grad) - s.surface_velocity.col(k).dot(d.panel_gamma_gradient.col(k));
      }
      df.col(k) = (d.rho * d.area(k) * dp) * d.normal.col(k);
    }
  if (terms == AddedMassTerms::All) add_suction_change(m, d, dv, s, df);
}

}  // namespace flapsim::uvlm
