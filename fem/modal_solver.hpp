#pragma once
/// \file modal_solver.hpp
/// \brief The lowest natural modes of K x = λ M x (λ = ω²) with Spectra's
/// Lanczos in shift-invert mode; K − σM is factorised once with CHOLMOD.

#include <limits>

#include <Eigen/Core>

#include "fem/assembly.hpp"
#include "fem/constraints.hpp"

namespace flapsim::fem {

/// Options of the modal solve.
struct ModalOptions {
  int num_modes = 20;        ///< number of lowest modes wanted
  /// Shift σ [rad²/s²]. Default (NaN): 0 if anything is constrained, else
  /// σ = −1e-9 · max_i(K_ii / M_ii) so K − σM is positive definite with
  /// rigid-body modes (free–free) while staying far below the first elastic
  /// eigenvalue in practice.
  double shift = std::numeric_limits<double>::quiet_NaN();
  int max_iterations = 1000;
  double tolerance = 1e-10;  ///< Spectra's relative tolerance on the transformed eigenvalues
  /// Sturm check: count the eigenvalues below the highest one found (LDLᵀ
  /// inertia of K − λM) and search again, deflated, for any Lanczos missed.
  /// Lanczos finds one vector per exactly repeated eigenvalue, so this matters
  /// for free structures (six rigid-body modes) and symmetric ones. Auto: only
  /// when nothing is constrained (it costs one more factorisation).
  enum class SturmCheck { Auto, Always, Never };
  SturmCheck sturm_check = SturmCheck::Auto;
};

/// Modes, lowest first.
struct ModalResult {
  Eigen::VectorXd eigenvalues;     ///< λ = ω² [rad²/s²]
  Eigen::VectorXd frequencies_hz;  ///< f = sign(λ)·√|λ| / 2π [Hz]
  /// Mode shapes, one column per mode, full DOF numbering (zero at fixed DOFs),
  /// mass-normalised: φᵀ M φ = 1.
  Eigen::MatrixXd shapes;
};

/// \brief Lowest modes of the constrained system.
/// \param K, M         assembled stiffness and mass (full DOF numbering)
/// \param constraints  fixed DOFs (none for a free–free structure)
/// \param options      number of modes, shift, tolerances
/// Throws SingularStiffness (static_solver.hpp) if K − σM cannot be factorised
/// and std::runtime_error if Lanczos does not converge.
ModalResult solve_modes(const SparseMatrix& K, const SparseMatrix& M,
                        const Constraints& constraints, const ModalOptions& options = {});

}  // namespace flapsim::fem
