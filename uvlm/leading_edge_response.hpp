#pragma once
/// \file leading_edge_response.hpp
/// \brief The leading-edge force's part of the lattice's added-mass response (added_mass.hpp),
/// split so that it can be held over steps and still follow each strip's leading edge.
///
/// The suction of strip j is the in-plane sum of the Kutta–Joukowski forces on its spanwise
/// bound segments s (rows q < nc; aero_loads.cpp, kutta_joukowski_loads.cpp),
///     S_j = Σ_q P_k ρ γ_s (v_s × l_s),   k = panel(q, j), P_k = 1 − n_k n_kᵀ,
/// γ_s the segment's circulation, v_s the air's velocity relative to the surface at its
/// midpoint, l_s its vector. A change δv of the node velocities changes γ_s through the
/// circulations (δγ_s = δΓ(q, j) − δΓ(q − 1, j), δΓ from the added-mass solve) and v_s by
/// δw_s = δv_ind,s − δu_s: the bound and trailing-edge vortices' induced velocity of δΓ
/// less the surface's own velocity change at the midpoint. Hence
///     δS_j = Σ_q P_k ρ (δγ_s v_s × l_s + γ_s δw_s × l_s).
/// The first half, hold_leading_edge_column, takes δγ_s and δw_s at one solve (δw_s in the
/// frame of panel k: chordwise, spanwise, normal, so that a wing that turns as a whole
/// carries it along). The second, leading_edge_force_change, evaluates δS_j at any later
/// solve with that solve's γ_s, v_s, l_s and normals, and the force of the edge as the
/// model turns the suction: δS_j (LeadingEdge::Attached); σ_j (Ŝ_j · δS_j) n_k
/// (LeadingEdge::Separated, Polhamus: the suction's magnitude along the normal, on the side
/// σ_j of the edge's circulation, leading_edge_side.hpp); nothing for LeadingEdge::None and LeadingEdge::Shed (the
/// shed sheet's criterion is not linearised). Re-evaluated at every step, the separated
/// force's response turns with the sign of the strip's leading-edge circulation, which a
/// response held over steps would not (docs/fsi.md, "Added mass in the coupling").
/// Taken and evaluated at the same solve it is the derivative of the leading-edge force
/// (test uvlm.AddedMass.*LeadingEdge*).

#include <Eigen/Core>

#include "uvlm/biot_savart.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::uvlm {

/// One node-velocity change's effect on the spanwise bound segments, held between solves.
struct LeadingEdgeColumn {
  Eigen::VectorXd segment_gamma_change;  ///< δγ_s of the nc·ns spanwise bound segments [m²/s]
  /// δw_s at their midpoints in the frame of panel (q, j): chordwise, spanwise, normal [m/s]
  Eigen::Matrix3Xd velocity_change;
};

/// Scratch of hold_leading_edge_column, allocated once (a lattice's size).
struct LeadingEdgeScratch {
  explicit LeadingEdgeScratch(const VortexLatticeModel& model);
  SegmentSet bound, trailing_edge;  ///< the lattice's bound and trailing-edge segments with δΓ
  PointSet midpoints;               ///< the spanwise bound segments' midpoints
};

/// Whether the model's leading-edge force has a response (Attached, Separated).
bool leading_edge_responds(const VortexLatticeModel& model);

/// \brief δγ_s and δw_s (file comment) at the last solve for the circulation change
/// \p gamma_change [m²/s] (panels) that the node velocity change \p node_velocity_change
/// [m/s] (3 × nodes) brings (the added-mass solve's δΓ).
/// \throws std::invalid_argument on wrong sizes
void hold_leading_edge_column(const VortexLatticeModel& model, const VortexLatticeData& data,
                              const Eigen::VectorXd& gamma_change, const Eigen::Matrix3Xd& node_velocity_change,
                              LeadingEdgeScratch& scratch, LeadingEdgeColumn& column);

/// \brief Adds the leading-edge forces' change [N] (file comment) at the last solve for the
/// held \p column to \p force_change (3 × panels, at loads.point; only the leading-edge
/// row's panels change). Nothing when the model has no response.
/// \throws std::invalid_argument on a column of another lattice
void add_leading_edge_force_change(const VortexLatticeModel& model, const VortexLatticeData& data,
                                   const LeadingEdgeColumn& column, Eigen::Matrix3Xd& force_change);

}  // namespace flapsim::uvlm
