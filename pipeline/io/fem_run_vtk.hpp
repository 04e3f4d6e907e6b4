#pragma once
/// \file fem_run_vtk.hpp
/// \brief One frame of a coupled run's FEM structure (fem.pvd): the deformed shell triangles
/// and vein segments, with the elastic displacement and the membrane strain (docs/fsi.md,
/// "Outputs").

#include <Eigen/Core>

#include "fem/mesh.hpp"
#include "pipeline/io/vtk_writers.hpp"

namespace flapsim::io {

/// \brief The FEM at its current nodal positions as polygons (triangles) and lines (veins).
/// Point data "displacement_m": x − (p + Q X), the motion beyond the base's rigid placement
/// of the reference node X [m, ground axes]. Cell data "membrane_strain": the largest
/// principal in-plane Green–Lagrange strain of each triangle, by magnitude, with its sign
/// (extension > 0) [-], 0 on vein segments; "vein": the vein's index, −1 on triangles.
/// \param positions       current node positions, ground frame [m], one column per node
/// \param base_rotation   Q: ground ← wing frame W of the base at this time
/// \param base_position   p: the pivot in the ground frame [m]
/// \param time            [s]
PolyDataMesh fem_frame_mesh(const fem::Mesh& mesh, const Eigen::Matrix3Xd& positions,
                            const Eigen::Matrix3d& base_rotation, const Eigen::Vector3d& base_position,
                            double time);

/// \brief Largest principal in-plane Green–Lagrange strain of the triangle (a, b, c) whose
/// reference corners are (A, B, C), by magnitude, with its sign [-].
double triangle_membrane_strain(const Eigen::Vector3d& A, const Eigen::Vector3d& B, const Eigen::Vector3d& C,
                                const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace flapsim::io
