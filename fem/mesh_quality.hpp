#pragma once
/// \file mesh_quality.hpp
/// \brief Sliver triangles in a wing's mesh: the smallest angle and where it lies, and the
/// warning `mesh`, `check`, `modes`, `reduce` and an FEM run give for one below
/// wings::kSliverAngleDeg (docs/wing_file.md, "Checks", "Slivers").

#include <string>

#include <Eigen/Geometry>

#include "fem/mesh.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::fem {

/// The smallest interior angle of a mesh's shell triangles and the triangle that has it.
struct SmallestAngle {
  double degrees = 180.0;                              ///< [deg]; 180 for a mesh without triangles
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< of that triangle [m]
  double longest_edge = 0.0;                           ///< of that triangle [m]
};

SmallestAngle smallest_triangle_angle(const Mesh& mesh);

/// \brief "" or the warning for a mesh whose smallest angle is below wings::kSliverAngleDeg:
/// where the sliver lies (in the wing file's coordinates, mm), how thin it is, and what
/// makes one (a vein's end or point beside the outline or another vein, two veins close and
/// nearly parallel, two outline points a hair's breadth apart): the FEM's Newton can stall on
/// such a triangle.
std::string sliver_warning(const Mesh& mesh, const wings::Wing& wing);

}  // namespace flapsim::fem
