#pragma once
/// \file added_mass.hpp
/// \brief The added-mass part of the lattice's loads, linearised: how the panel forces of
/// the last solve change when the surface nodes' velocities change, through the
/// circulations' time derivative alone (docs/fsi.md, "Added mass in the coupling").
///
/// A change δv of the node velocities changes the boundary condition at the collocation
/// points, δrhs_k = n_k · δv_k (δv_k bilinear at the three-quarter chord point, as the
/// solve interpolates the surface velocity), hence the circulations, A δΓ = δrhs, and the
/// unsteady term of the pressure jump, ρ ∂Γ_k/∂t, by ρ c δΓ_k / Δt (c = 1 for the first
/// accepted step's BDF1 rate, 3/2 for BDF2; aero_loads.cpp gamma_rate):
///     δF_k = ρ A_k n_k c δΓ_k / Δt     at the panel's point of action (loads.point).
/// This is the term that scales as 1/Δt and makes a light wing's partitioned coupling
/// slow or unstable (the air's added mass). AddedMassTerms::Pressure (the default) adds
/// the Bernoulli route's quasi-steady term, linearised with V and ∇Γ of the last solve held:
///     δΔp_k = ρ (c δΓ_k / Δt − δv_k · ∇Γ_k + V_k · ∇δΓ_k),
/// ∇δΓ by the loads' vortex-vector formula (aero_loads.cpp). Left out: the bound vortices'
/// own velocity change at the panels and the trailing-edge vortex's placement (it follows
/// the edge's velocity). AddedMassTerms::All adds the leading-edge force's change
/// (leading_edge_response.hpp; its `separated` form turns with the sign of the
/// leading-edge circulation, so a structure that holds the response over steps takes that
/// part apart and re-evaluates it: docs/fsi.md, "Added mass in the coupling"). For a wing at
/// rest in still air the response is the exact derivative of the loads, for a flat plate
/// in a free stream too (test uvlm.AddedMass.*).

#include <Eigen/Core>

#include "uvlm/leading_edge_response.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::uvlm {

/// Which terms of the loads added_mass_force_change linearises (file comment).
enum class AddedMassTerms {
  Unsteady,  ///< ρ A n ∂Γ/∂t alone
  Pressure,  ///< and the Bernoulli route's ρ V·∇Γ
  All        ///< and the leading-edge force (leading_edge_response.hpp)
};

/// Scratch of added_mass_force_change, allocated once (a lattice's panel count).
struct AddedMassScratch {
  explicit AddedMassScratch(const VortexLatticeModel& model)
      : rhs(Eigen::VectorXd::Zero(model.panels())), dgamma(Eigen::VectorXd::Zero(model.panels())),
        surface_velocity(Eigen::Matrix3Xd::Zero(3, model.panels())), leading_edge(model) {
    if (model.iterative(model.panels())) gmres.reserve(model.panels(), model.iterative_restart);
  }
  Eigen::VectorXd rhs, dgamma;
  Eigen::Matrix3Xd surface_velocity;  ///< δv at the collocation points
  PreconditionedGmres gmres;  ///< the iterative path's solves (reserved when the model has it)
  LeadingEdgeScratch leading_edge;  ///< AddedMassTerms::All's
  LeadingEdgeColumn column;         ///< AddedMassTerms::All's
};

/// \brief δF [N] (3 × panels, at loads.point) of the last solve for the node velocity change
/// \p node_velocity_change [m/s] (3 × nodes), by the formula of the file comment.
/// \throws std::invalid_argument on wrong sizes or before any solve
void added_mass_force_change(const VortexLatticeModel& model, const VortexLatticeData& data,
                             const Eigen::Matrix3Xd& node_velocity_change, AddedMassScratch& scratch,
                             Eigen::Matrix3Xd& force_change, AddedMassTerms terms = AddedMassTerms::Pressure);

}  // namespace flapsim::uvlm
