/// \file added_mass.cpp
/// \brief The linearised added-mass response of the lattice's loads (added_mass.hpp).

#include "uvlm/added_mass.hpp"
#include "uvlm/lattice_internal.hpp"
#include "uvlm/load_terms.hpp"

#include <stdexcept>
#include <string>

namespace flapsim::uvlm {

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
      s.surface_velocity.col(k) = detail::three_quarter_chord(m, dv, i, j);
      s.rhs(k) = s.surface_velocity.col(k).dot(d.normal.col(k));
    }
  s.dgamma = d.lu.solve(s.rhs);  // exact when lu factorises the current matrix
  if (!d.factorisation_current && s.gmres.size() == np) {
    // The iterative path: GMRES on the current matrix from the earlier matrix's answer.
    const PreconditionedGmres::Result r =
        s.gmres.solve(d.influence, d.lu, s.rhs, s.dgamma, m.iterative_tolerance, m.iterative_max_iterations);
    if (!r.converged) s.dgamma = d.lu.solve(s.rhs);  // the preconditioner's answer: approximate
  }
  // ∂Γ/∂t's factor on the current Γ (load_terms.hpp gamma_rate).
  const double rate = detail::gamma_rate_factor(m, d);
  const auto dgamma = [&](int i, int j) {
    return (i < 0 || i >= nc || j < 0 || j >= ns) ? 0.0 : s.dgamma(m.panel(i, j));
  };
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nc; ++i) {
      const int k = m.panel(i, j);
      double dp = rate * s.dgamma(k);
      if (terms != AddedMassTerms::Unsteady) {
        // δ(V · ∇Γ) = −δv_s · ∇Γ + V · ∇δΓ, ∇δΓ by the loads' own formula
        // (load_terms.hpp); zero where the loads did not keep V and ∇Γ (Kutta–Joukowski).
        const Eigen::Vector3d grad = detail::panel_gamma_gradient(m, d, i, j, dgamma);
        dp += d.panel_air_velocity.col(k).dot(grad) - s.surface_velocity.col(k).dot(d.panel_gamma_gradient.col(k));
      }
      df.col(k) = (d.rho * d.area(k) * dp) * d.normal.col(k);
    }
  if (terms == AddedMassTerms::All && leading_edge_responds(m)) {
    hold_leading_edge_column(m, d, s.dgamma, dv, s.leading_edge, s.column);
    add_leading_edge_force_change(m, d, s.column, df);
  }
}

}  // namespace flapsim::uvlm
