#pragma once
/// \file load_transfer.hpp
/// \brief Aerodynamic panel loads to point forces on the bodies of the chain.
///
/// Each panel force F_p (ground components) acts at its point of action P_p on the
/// deformed surface. It goes to the panel's host body as the same force at the same
/// point: the point is expressed in the host's frame at the pose the lattice was solved
/// on, p = R_kᵀ (P_p − o_k), and the force keeps its ground components
/// (mbd::LoadFrame::ground). So Σ over bodies of the forces equals Σ F_p and, at that
/// pose, the moment about any point equals Σ (P_p − c) × F_p, both to round-off — no
/// lumping to joints, no moment arm lost. While the chain solver moves the bodies within
/// a step, the points move with their bodies (the moment arms follow the pose).

#include "mbd/chain_data.hpp"
#include "mbd/chain_loads.hpp"
#include "pipeline/fsi/wing_attachment.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::fsi {

/// \brief Adds the panel loads to \p loads (does not clear it first).
/// \param attachment  host body of each panel
/// \param data        chain kinematics at the pose the lattice was solved on
/// \param panels      the lattice's panel forces [N] and points of action [m] (ground)
/// \param loads       chain loads to add to (sized for the chain's bodies)
void add_panel_loads(const WingAttachment& attachment, const mbd::ChainData& data,
                     const uvlm::PanelLoads& panels, mbd::Loads& loads);

}  // namespace flapsim::fsi
