#pragma once
/// \file load_cases.hpp
/// \brief Standard static load cases of a root-clamped wing, for fem.vtu and
/// quick stiffness checks: unit tip forces at the leading and trailing edges,
/// a unit tip bending moment and a unit tip torque.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/mesh.hpp"

namespace flapsim::fem {

/// A station near the tip where the loads are applied.
struct TipStation {
  double y = 0.0;                 ///< spanwise position [m]
  std::vector<int> nodes;         ///< nodes in the band |y_node − y| <= half_width
  int leading_edge_node = -1;     ///< node of the band with the largest x
  int trailing_edge_node = -1;    ///< node of the band with the smallest x
};

/// A named nodal load vector (full DOF numbering).
struct LoadCase {
  std::string name;
  Eigen::VectorXd loads;  ///< [N] on translations, [N·m] on rotations
};

/// \brief Station at y = y_min + fraction · (y_max − y_min); the band half width
/// grows from `half_width` until it holds at least two nodes.
TipStation tip_station(const Mesh& mesh, double fraction = 0.9, double half_width = 0.0);

/// \brief The four cases, in this order: "tip_force_le" (F_z = 1 N at the
/// leading-edge node), "tip_force_te" (F_z = 1 N at the trailing-edge node),
/// "tip_moment" (M_x = 1 N·m: spanwise bending, spread evenly over the band's
/// nodes) and "tip_torque" (M_y = 1 N·m about the span, spread the same way).
std::vector<LoadCase> tip_load_cases(const Mesh& mesh, const TipStation& station);

}  // namespace flapsim::fem
