#pragma once
/// \file fem_structure_setup.hpp
/// \brief The structure of a case with `[structure] kind = "fem"`: the wing's own shell and
/// vein FEM (fem::build_wing_fem: the mesh, elements and materials `flapsim modes` uses, or
/// the case's element sizes), geometrically nonlinear, its root clamp (nodes at or below
/// the wing's clamp_y) driven by the base motion, the lattice on its shell (docs/fsi.md,
/// "The FEM as the structure").

#include <memory>

#include <Eigen/Core>

#include "fem/wing_mesher.hpp"
#include "mbd/base_motion.hpp"
#include "pipeline/fsi/fem_structure.hpp"
#include "pipeline/io/case_model.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::app {

/// \brief Refuses the case's mesh sizes (`element_size_mm`, `vein_element_size_mm`, already
/// in `mesh` [m]; 0 = the wing file's) that the wing file's own rules would refuse: veins finer
/// than or as fine as the membrane, an element at most half the span, and the element budget
/// of wings/loader/mesh_budget.hpp (a typo of 0.01 for 1 asked gmsh for 10⁸ triangles).
/// \throws flapsim::InputError naming the case file, line and key
void check_case_mesh_sizes(const io::Case& c, const wings::Wing& wing, const fem::MeshOptions& mesh);

/// \brief Builds the FEM structure of a case.
/// \param lattice_nodes  lattice nodes in the wing frame, (nc+1)(ns+1) columns [m]; empty in vacuum
/// \param span           the wing's span R [m] (the scale of the coupling's change measure)
/// \throws flapsim::InputError if the wing cannot be meshed or nothing is clamped
std::shared_ptr<const fsi::FemStructureModel> make_fem_structure(const io::Case& c, const wings::Wing& wing,
                                                                 const mbd::BaseMotion& base,
                                                                 const Eigen::Matrix3Xd& lattice_nodes,
                                                                 double span);

}  // namespace flapsim::app
