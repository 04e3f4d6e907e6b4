#pragma once
/// \file nonlinear_static_solver.hpp
/// \brief Geometrically nonlinear statics of the co-rotational model: the load
/// applied in equal load steps, Newton iterations at each step on the free
/// DOFs with the consistent, non-symmetric tangent of nonlinear_assembly.hpp
/// (Eigen's sparse LU, the symbolic analysis done once). Symmetrising the
/// tangent (an LLᵀ-able matrix) made Newton converge only linearly under the
/// end moment of the roll-up test; the consistent tangent converges
/// quadratically (docs/fem.md, "Geometrically nonlinear FEM"). Loads keep their global direction (dead
/// loads; a nodal moment is a moment about fixed global axes).

#include <string>

#include <Eigen/Core>

#include "fem/constraints.hpp"
#include "fem/nonlinear_assembly.hpp"

namespace flapsim::fem {

/// Load stepping and Newton settings.
struct NonlinearStaticOptions {
  int load_steps = 10;        ///< equal increments of the load factor to 1
  int max_iterations = 30;    ///< Newton iterations per load step
  /// ‖r_free‖ ≤ tolerance · ‖F_free‖ (relative residual). Round-off bounds what
  /// can be reached: a thin strip (membrane/bending stiffness ratio 10⁴) stalls
  /// at 3e-10.
  double tolerance = 1e-8;
};

/// Outcome: converged, or the reason it stopped.
struct NonlinearStaticResult {
  bool converged = false;
  int load_steps_done = 0;    ///< load steps that converged
  int total_iterations = 0;   ///< Newton iterations over all steps
  double residual = 0.0;      ///< last relative residual
  double strain_energy = 0.0; ///< [J]
  std::string failure;        ///< empty when converged
};

/// \brief Equilibrium f_int(state) = F on the free DOFs, starting from `state`.
/// \param F            nodal loads, full numbering [N, N·m]; entries at fixed DOFs ignored
/// \param constraints  fixed DOFs (they keep the values they have in `state`)
/// \param state        start, overwritten with the last converged configuration
NonlinearStaticResult solve_nonlinear_static(const CorotationalModel& model, const Constraints& constraints,
                                             const Eigen::VectorXd& F, CorotationalState& state,
                                             const NonlinearStaticOptions& options = {});

}  // namespace flapsim::fem
