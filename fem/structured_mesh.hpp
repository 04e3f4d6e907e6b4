#pragma once
/// \file structured_mesh.hpp
/// \brief Structured meshes built without gmsh: mapped quadrilateral grids split
/// into triangles (plates, cylindrical and twisted shells) and straight beams.
/// Used by the verification tests and by reduction checks on plate strips.

#include <functional>

#include "fem/mesh.hpp"

namespace flapsim::fem {

/// How each grid cell is split into two triangles.
enum class Diagonal {
  Forward,      ///< every cell split along the same diagonal
  Alternating,  ///< diagonals alternate (chequerboard): a more isotropic mesh
};

/// \brief An nx × ny cell grid mapped by `map(u, v)`, u, v ∈ [0, 1], into 3-D.
/// Node (i, j) has index j·(nx + 1) + i. Triangles are counter-clockwise in (u, v).
Mesh grid_mesh(int nx, int ny, const std::function<Eigen::Vector3d(double, double)>& map,
               Diagonal diagonal = Diagonal::Alternating);

/// \brief A flat rectangle [x0, x0 + lx] × [y0, y0 + ly] in the plane z = 0.
Mesh rectangle_mesh(double x0, double y0, double lx, double ly, int nx, int ny,
                    Diagonal diagonal = Diagonal::Alternating);

/// \brief A straight beam from a to b with n elements (n + 1 nodes), vein 0.
Mesh line_mesh(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int n);

}  // namespace flapsim::fem
