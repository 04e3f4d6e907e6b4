#pragma once
/// \file newton_matrix.hpp
/// \brief The factorised Newton matrix A = c_M M + K_T of the nonlinear dynamics
/// (nonlinear_dynamics.hpp), kept across Newton iterations and steps (modified Newton)
/// and carried along with the rotation of the wing's frame.
///
/// Factorisation: CHOLMOD supernodal LLᵀ of the symmetrised tangent (TangentForm::
/// SymmetricLower); if LLᵀ finds the matrix not positive definite, the same matrix is
/// factorised by CHOLMOD's simplicial LDLᵀ (no pivoting: any nonsingular matrix whose
/// pivots do not vanish), and by sparse LU only if that fails too (either counted as a
/// fallback): the 25 µm film wing's tangent is indefinite in many steps (docs/fsi.md,
/// "Film wings"), and Eigen's sparse LU of it took about a third of that run's time (perf).
/// From kMinSplitRows rows, where the matrix's graph has a small separator, the LLᵀ and the
/// LDLᵀ are each done in two parts on two threads (separated_cholesky.hpp). The consistent
/// tangent (TangentForm::Consistent) always goes to sparse LU.
///
/// Frame rotation. A wing that is turned rigidly by S (every node x ← S x, R ← S R) has
/// the tangent S_b K_T S_bᵀ, S_b = diag(S, S, …) on each node's translations and spins,
/// and the same mass: its 3 × 3 nodal blocks are multiples of the identity
/// (nonlinear_assembly.hpp: the same translational mass in x, y, z, isotropic rotary
/// inertia), so S_b M S_bᵀ = M. A matrix factorised when the frame was F_f therefore
/// solves the Newton system of the same deformation in the frame F as
///   x = S_b A_f⁻¹ S_bᵀ r,  S = F F_fᵀ.
/// The flapping base turns the whole wing by up to 0.06 rad a step (hawkmoth, 100 steps
/// per cycle) while its deformation changes little: the rotated factor stays a good
/// Newton matrix for many steps (docs/fem.md). The rotation is applied only when every
/// free DOF belongs to a node with all six DOFs free; otherwise S = I.

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <Eigen/SparseLU>

#include <vector>

#include "fem/assembly.hpp"
#include "fem/nonlinear_assembly.hpp"
#include "fem/separated_cholesky.hpp"

namespace flapsim::fem {

class NewtonMatrix {
 public:
  /// \param free_dofs  the full DOF of each free index (ascending)
  NewtonMatrix(TangentForm form, const std::vector<int>& free_dofs);

  /// \brief Factorise A (free DOFs, stored as `form` says) taken in the frame F; the
  /// step size h [s] it was made for is kept to tell when it no longer applies.
  /// \return false if A is singular.
  bool factorize(const SparseMatrix& A, const Eigen::Matrix3d& frame, double h);
  /// x = S_b A⁻¹ S_bᵀ r with S = F F_fᵀ (see above).
  void solve(const Eigen::VectorXd& r, const Eigen::Matrix3d& frame, Eigen::VectorXd& x);

  bool valid() const { return valid_; }
  /// The last matrix was factorised in two parts and their separator (separated_cholesky.hpp),
  /// by LLᵀ or (indefinite) LDLᵀ.
  bool separated() const { return valid_ && (solver_ == Solver::Split || solver_ == Solver::SplitLdlt); }
  double step_size() const { return h_; }
  void invalidate() { valid_ = false; }
  /// Matrices the LLᵀ refused (then factorised by LDLᵀ, or by LU if that failed too).
  long lu_fallbacks() const { return fallbacks_; }
  /// Memory its factors take, about [bytes]: 24 bytes a nonzero of L (the LLᵀ's and an
  /// LDLᵀ's values and indices); 0 before the first factorisation, or for the LU.
  double factor_bytes() const { return 24.0 * factor_nonzeros_; }

 private:
  void rotate(Eigen::VectorXd& v, const Eigen::Matrix3d& S) const;
  /// A by LDLᵀ (its pattern analysed once); false if a pivot vanished.
  bool factorize_ldlt(const SparseMatrix& A);

  TangentForm form_;
  bool rotatable_ = true;  ///< free DOFs come as whole nodes (six consecutive)
  enum class Solver { Split, SplitLdlt, Llt, Ldlt, Lu };
  /// Matrices with at least this many rows are factorised in two parts and their separator
  /// when their graph has one (separated_cholesky.hpp): the hawkmoth's default mesh, 27 618
  /// rows, 113–116 → 59–65 ms a factorisation and solve on two threads (docs/fem.md).
  static constexpr int kMinSplitRows = 2000;
  SeparatedCholesky split_;
  bool split_tried_ = false;
  SeparatedCholesky split_ldlt_{true};  ///< the LDLᵀ in two parts, for indefinite matrices
  bool split_ldlt_tried_ = false;
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt_;
  Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt_;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
  SparseMatrix full_;  ///< both triangles of a symmetric A, for the LU fallback
  bool llt_analysed_ = false, ldlt_analysed_ = false, lu_analysed_ = false, valid_ = false;
  Solver solver_ = Solver::Llt;
  Eigen::Matrix3d frame_ = Eigen::Matrix3d::Identity();
  double h_ = 0.0;
  long fallbacks_ = 0;
  double factor_nonzeros_ = 0.0;  ///< nonzeros of L (CHOLMOD's analysis)
  Eigen::VectorXd rhs_;
};

}  // namespace flapsim::fem
