#pragma once
/// \file wing_fem.hpp
/// \brief The whole FEM of a wing in one call: mesh (gmsh), element properties,
/// assembled K and M, element masses and the root clamp; and its modes.
///
/// Typical use (the reduction stage):
/// \code
///   const auto fem = fem::build_wing_fem(wing);             // mesh + K, M
///   fem::StaticSolver statics(fem.system.stiffness, fem.root_clamp);
///   Eigen::VectorXd u = statics.solve(F);                    // F: node*6 + dof
///   const auto modes = fem::wing_modes(fem, 20);             // clamped-root modes
///   for (const auto& e : fem.system.element_masses) ...      // strip sums
/// \endcode

#include <vector>

#include "fem/assembly.hpp"
#include "fem/constraints.hpp"
#include "fem/modal_solver.hpp"
#include "fem/mode_classification.hpp"
#include "fem/structural_model.hpp"
#include "fem/wing_mesher.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::fem {

/// A wing's FEM: the constant model and its assembled matrices.
struct WingFem {
  StructuralModel model;   ///< mesh (model.mesh) and element properties
  AssembledSystem system;  ///< K, M, element masses
  Constraints root_clamp;  ///< all DOFs of nodes with y <= wing.clamp_y fixed
};

/// \brief Mesh, model, assembly and root clamp of a wing.
/// Throws flapsim::InputError if meshing fails or nothing is clamped.
WingFem build_wing_fem(const wings::Wing& wing, const MeshOptions& options = {});

/// Modes of a wing FEM with their kinds.
struct WingModes {
  ModalResult modes;
  std::vector<ModeKind> kinds;
};

/// \brief Lowest `num_modes` modes of the root-clamped wing (or free–free with
/// `clamped` false), classified.
WingModes wing_modes(const WingFem& fem, int num_modes, bool clamped = true);

}  // namespace flapsim::fem
