#pragma once
/// \file displacement_control.hpp
/// \brief Geometrically nonlinear statics under displacement control: one
/// translational DOF is prescribed and the load that holds it there (its
/// reaction) is computed, so a load–deflection path can be followed through a
/// limit point where load control (nonlinear_static_solver.hpp) must stop,
/// e.g. the snap-through of the hinged cylindrical roof of [Sze et al. 2004].
/// The path must be monotonic in the controlled DOF (no snap-back); beyond
/// that an arc-length method is needed.
///
/// Newton iterations on the free DOFs with the consistent tangent of
/// nonlinear_assembly.hpp and Eigen's sparse LU, as in the load-controlled
/// solver. The first iteration after a change of the prescribed value is the
/// tangent predictor: the free DOFs answer the prescribed increment linearly.

#include <string>

#include <Eigen/Core>

#include "fem/constraints.hpp"
#include "fem/nonlinear_assembly.hpp"

namespace flapsim::fem {

/// Newton settings.
struct DisplacementControlOptions {
  int max_iterations = 30;
  /// ‖r_free‖ ≤ tolerance · ‖f_int‖ over all DOFs (the internal force with the
  /// reactions of the fixed and the controlled DOFs: the force scale of the state).
  double tolerance = 1e-8;
  /// Also converged when the largest Newton correction is below this fraction
  /// of the model's size (bounding-box diagonal; translations) or this many
  /// radians (rotations): where the membrane is far stiffer than the bending
  /// (a rod: EA L²/EI ~ 1e5) the residual of a small deflection has a
  /// round-off floor above `tolerance`.
  double increment_tolerance = 1e-12;
};

/// Outcome of one prescribed value.
struct DisplacementControlResult {
  bool converged = false;
  int iterations = 0;       ///< Newton iterations
  double residual = 0.0;    ///< last relative residual
  double reaction = 0.0;    ///< f_int at the controlled DOF: the load that holds it [N]
  std::string failure;      ///< empty when converged
};

/// \brief Equilibrium with the translational DOF `controlled_dof` displaced by
/// `value` from its reference position and no load on the free DOFs.
/// \param constraints  fixed DOFs (they keep their values in `state`)
/// \param state        start (normally the previous converged point), overwritten
///                     with the equilibrium; left unchanged on failure
/// Throws std::invalid_argument if `controlled_dof` is a rotation or fixed.
DisplacementControlResult solve_displacement_controlled(const CorotationalModel& model,
                                                        const Constraints& constraints, int controlled_dof,
                                                        double value, CorotationalState& state,
                                                        const DisplacementControlOptions& options = {});

}  // namespace flapsim::fem
