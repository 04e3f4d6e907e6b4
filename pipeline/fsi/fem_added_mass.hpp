#pragma once
/// \file fem_added_mass.hpp
/// \brief The lattice's added-mass response (panel_load_response.hpp) lumped to the FEM's
/// nodes, for a coupled step of the FEM (fem_structure.hpp; docs/fsi.md, "Added mass in the
/// coupling"). The chain takes the response whole, one column per joint coordinate; the FEM
/// has thousands of interface DOFs, and a dense D in its Newton matrix would cost a solve per
/// panel at every factorisation. Lumped, D is a 3 × 3 block per node and the Newton matrix
/// keeps its sparsity:
///
/// - each panel's pressure force changes along its normal n_k; the response to the whole
///   wing's translation by a unit velocity e_j (three right-hand sides of the lattice) gives
///   G_k = [δF_k(e_x) δF_k(e_y) δF_k(e_z)] = n_k g_kᵀ, and the panel's added mass per unit
///   normal velocity of the whole wing, m_k = −n_kᵀ G_k n_k [N s/m] (≥ 0: the air resists),
///   the row sum of the response in the normal direction (a heaving plate's distribution);
/// - D_k = m_k n_k n_kᵀ goes to the three nodes of the panel's shell triangle with its
///   attachment weights (those of a point outside its triangle clipped at 0): D_i += wᵢ D_k.
///
/// The lumping is exact for a uniform normal motion of the wing and overestimates the
/// response of finer motions (a pitching flat plate's added inertia twice over): too much
/// added mass only slows the coupling's contraction, too little lets a light wing's
/// partitioned step diverge. The coupled answer does not depend on it (load_damping.hpp).
/// D is held in the base frame (W), in which the added mass follows the wing's shape and
/// not its flapping pose, and turned with the base at each solve.

#include <Eigen/Core>

#include <vector>

#include "fem/mesh.hpp"
#include "pipeline/fsi/fem_attachment.hpp"
#include "pipeline/fsi/panel_load_response.hpp"

namespace flapsim::fsi {

/// D per FEM node, in the base frame W [N s/m].
struct LumpedAddedMass {
  std::vector<int> nodes;
  std::vector<Eigen::Matrix3d> blocks;
  double total = 0.0;  ///< Σ m_k over the panels [N s/m]
};

/// \brief Lumps the response at the lattice's last solve (file comment).
/// \param base_rotation  ground ← W at the time of that solve
/// \param lattice_nodes  the lattice's node count (the response's velocity columns)
LumpedAddedMass lump_added_mass(const FemAttachment& attachment, const fem::Mesh& mesh,
                                PanelLoadResponse& response, const Eigen::Matrix3d& base_rotation,
                                int lattice_nodes);

}  // namespace flapsim::fsi
