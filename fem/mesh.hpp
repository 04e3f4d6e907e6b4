#pragma once
/// \file mesh.hpp
/// \brief The FEM mesh: nodes, shell triangles and vein (frame) elements that
/// share nodes. Global DOF numbering used throughout fem/ and by its users:
/// DOF = 6·node + d with d = 0..5 for (ux, uy, uz, rx, ry, rz).

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace flapsim::fem {

/// Number of DOFs per node and their order.
inline constexpr int kDofsPerNode = 6;
enum Dof : int { UX = 0, UY = 1, UZ = 2, RX = 3, RY = 4, RZ = 5 };

/// Global DOF index of component `d` of node `node`.
inline int dof_index(int node, int d) { return kDofsPerNode * node + d; }

/// A two-node frame element on a vein.
struct BeamElement {
  std::array<int, 2> nodes{};  ///< node indices, in order along the vein
  int vein = -1;               ///< index into Mesh::vein_names (and Wing::veins)
};

/// Nodes (in the wing frame for wings), triangles and beams.
struct Mesh {
  std::vector<Eigen::Vector3d> nodes;          ///< [m]
  std::vector<std::array<int, 3>> triangles;   ///< shell elements (node indices)
  std::vector<BeamElement> beams;              ///< vein elements (node indices)
  std::vector<std::string> vein_names;         ///< one per vein

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int num_dofs() const { return kDofsPerNode * num_nodes(); }
  /// The mean of triangle \p e's three edges [m]: its size, as the mesh's warnings take it.
  double triangle_mean_edge(std::size_t e) const {
    const auto& t = triangles[e];
    return ((nodes[t[1]] - nodes[t[0]]).norm() + (nodes[t[2]] - nodes[t[1]]).norm() +
            (nodes[t[0]] - nodes[t[2]]).norm()) / 3.0;
  }
};

}  // namespace flapsim::fem
