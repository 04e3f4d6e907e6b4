#pragma once
/// \file fem_attachment.hpp
/// \brief How the aerodynamic surface rides on the wing's FEM shell (issue of the FEM as the
/// structure of a run; docs/fsi.md, "Attachment to the FEM"): every lattice node, and every
/// panel's point of action, is tied once, in the reference configuration, to one shell
/// triangle by its barycentric coordinates in the triangle's plane. The lattice keeps its
/// own resolution: nothing ties it to the FEM mesh's size.
///
/// Surface: x = Σᵢ wᵢ xᵢ, v = Σᵢ wᵢ vᵢ over the triangle's three deformed nodes (the
/// shell's flat-facet geometry, exact for a rigid motion of the triangle). A point a little
/// outside the mesh (an outline the mesh follows by straight edges) takes the nearest
/// triangle, with weights that extrapolate its plane linearly.
///
/// Loads: a panel force F at its deformed point of action P goes to its triangle's nodes as
/// wᵢ F, and the moment (P − P′) × F of the offset between P and P′ = Σᵢ wᵢ xᵢ goes to the
/// three nodes' rotations in equal thirds, so Σ forces = F and Σ moments about any point
/// = (P − c) × F, both to round-off.

#include <Eigen/Core>

#include <array>
#include <vector>

#include "fem/mesh.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::fsi {

/// A point fixed in a shell triangle: its index and barycentric weights (sum 1).
struct ShellPoint {
  int triangle = 0;
  std::array<double, 3> weights{};
};

/// The lattice on the FEM: host triangles of the lattice nodes and of the panels' points of
/// action (quarter chord, mid-span of the reference panel).
struct FemAttachment {
  std::vector<ShellPoint> nodes;   ///< one per lattice node, lattice order
  std::vector<ShellPoint> panels;  ///< one per panel, lattice panel order
  int num_fem_nodes = 0;
  /// The lattice nodes on the undeformed shell, Σᵢ wᵢ Xᵢ over the reference mesh, in its
  /// frame W [m] (a node off its triangle's plane is carried in the plane;
  /// StructureModel::reference_surface).
  Eigen::Matrix3Xd reference_nodes;
};

/// \brief The shell point of \p p [m] (reference configuration, the mesh's frame): the
/// triangle that holds it in its plane, else the one whose plane holds it least outside.
/// \throws std::invalid_argument for a mesh without triangles
ShellPoint locate_on_shell(const fem::Mesh& mesh, const Eigen::Vector3d& p);

/// \brief Attaches a lattice to a shell mesh.
/// \param mesh        the FEM mesh (reference node positions, the wing frame) [m]
/// \param nodes_wing  lattice nodes in the same frame, (nc+1)(ns+1) columns [m]
/// \throws std::invalid_argument if the node count does not match nc, ns
FemAttachment attach_wing_to_fem(const fem::Mesh& mesh, const Eigen::Matrix3Xd& nodes_wing,
                                 int chordwise, int spanwise);

/// \brief The lattice on the deformed FEM.
/// \param fem_positions   deformed FEM node positions, 3 × mesh nodes, ground [m]
/// \param fem_velocities  their velocities [m/s]
/// \param positions, velocities  lattice nodes out (resized to 3 × lattice nodes)
void fem_surface_nodes(const FemAttachment& attachment, const fem::Mesh& mesh,
                       const Eigen::Matrix3Xd& fem_positions, const Eigen::Matrix3Xd& fem_velocities,
                       Eigen::Matrix3Xd& positions, Eigen::Matrix3Xd& velocities);

/// \brief Adds the panel loads to nodal loads of the FEM (see the file comment).
/// \param fem_positions  deformed FEM node positions, ground [m]
/// \param nodal_loads    6 per node (force [N], moment [N m]) in ground axes, fem::dof_index
///                       order; added to, not cleared
void add_panel_loads_to_fem(const FemAttachment& attachment, const fem::Mesh& mesh,
                            const Eigen::Matrix3Xd& fem_positions, const uvlm::PanelLoads& panels,
                            Eigen::VectorXd& nodal_loads);

/// \brief The same for given panel forces [N] acting at given points [m] (3 × panels each),
/// e.g. a part of the panels' loads (uvlm::PanelLoads::unsteady_force).
void add_panel_forces_to_fem(const FemAttachment& attachment, const fem::Mesh& mesh,
                             const Eigen::Matrix3Xd& fem_positions, const Eigen::Matrix3Xd& forces,
                             const Eigen::Matrix3Xd& points, Eigen::VectorXd& nodal_loads);

}  // namespace flapsim::fsi
