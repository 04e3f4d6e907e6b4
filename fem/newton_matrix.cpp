#include "fem/newton_matrix.hpp"

#include "fem/serial_openmp_regions.hpp"

namespace flapsim::fem {

NewtonMatrix::NewtonMatrix(TangentForm form, const std::vector<int>& free_dofs) : form_(form) {
  if (free_dofs.size() % kDofsPerNode != 0) rotatable_ = false;
  for (std::size_t i = 0; rotatable_ && i < free_dofs.size(); i += kDofsPerNode)
    for (int d = 0; d < kDofsPerNode; ++d)
      if (free_dofs[i + static_cast<std::size_t>(d)] != free_dofs[i] + d || free_dofs[i] % kDofsPerNode != 0)
        rotatable_ = false;
  rhs_.resize(static_cast<Eigen::Index>(free_dofs.size()));
  // An LLᵀ refused is an answer here (the LDLᵀ follows), not a warning for the user:
  // CHOLMOD would print one line for each to stderr.
  llt_.cholmod().print = 0;
}

bool NewtonMatrix::factorize(const SparseMatrix& A, const Eigen::Matrix3d& frame, double h) {
  valid_ = false;
  frame_ = frame;
  h_ = h;
  if (form_ == TangentForm::SymmetricLower) {
    if (!split_tried_) {
      // Two parts on two threads if the matrix's graph has a small separator (the same
      // factor on one thread: the choice depends on the pattern alone).
      split_tried_ = true;
      if (A.rows() >= kMinSplitRows && split_.analyse(A)) factor_nonzeros_ = split_.factor_nonzeros();
    }
    bool positive_definite = false;
    if (split_.analysed()) {
      positive_definite = split_.factorize(A);
      solver_ = Solver::Split;
    } else {
      const SerialOpenMpRegions cholmod_on_this_thread;  // CHOLMOD's fixed 4-thread teams
      if (!llt_analysed_) {
        llt_.analyzePattern(A);
        factor_nonzeros_ = llt_.cholmod().lnz;
      }
      llt_analysed_ = true;
      llt_.factorize(A);
      positive_definite = llt_.info() == Eigen::Success;
      solver_ = Solver::Llt;
    }
    if (positive_definite) {
      valid_ = true;
      return true;
    }
    // Not positive definite (the symmetrised tangent under large moments on nodes of
    // small rotary inertia; a thin film in compression): the same matrix by LDLᵀ, which
    // takes an indefinite matrix as long as no pivot vanishes, else by LU.
    ++fallbacks_;
    if (factorize_ldlt(A)) return true;
    full_ = A.selfadjointView<Eigen::Lower>();
    solver_ = Solver::Lu;
    if (!lu_analysed_) lu_.analyzePattern(full_);
    lu_analysed_ = true;
    lu_.factorize(full_);
  } else {
    solver_ = Solver::Lu;
    if (!lu_analysed_) lu_.analyzePattern(A);
    lu_analysed_ = true;
    lu_.factorize(A);
  }
  valid_ = lu_.info() == Eigen::Success;
  return valid_;
}

bool NewtonMatrix::factorize_ldlt(const SparseMatrix& A) {
  if (split_.analysed()) {
    // The pattern has a separator: LDLᵀ in two parts as well (else, or if a pivot vanishes
    // there, the whole matrix's LDLᵀ, whose order differs).
    if (!split_ldlt_tried_) {
      split_ldlt_tried_ = true;
      split_ldlt_.analyse(A);
    }
    if (split_ldlt_.analysed() && split_ldlt_.factorize(A)) {
      solver_ = Solver::SplitLdlt;
      valid_ = true;
      return true;
    }
  }
  const SerialOpenMpRegions cholmod_on_this_thread;
  if (!ldlt_analysed_) ldlt_.analyzePattern(A);
  ldlt_analysed_ = true;
  ldlt_.factorize(A);
  if (ldlt_.info() != Eigen::Success) return false;
  solver_ = Solver::Ldlt;
  valid_ = true;
  return true;
}

void NewtonMatrix::rotate(Eigen::VectorXd& v, const Eigen::Matrix3d& S) const {
  for (Eigen::Index i = 0; i + 2 < v.size(); i += 3) v.segment<3>(i) = S * v.segment<3>(i).eval();
}

void NewtonMatrix::solve(const Eigen::VectorXd& r, const Eigen::Matrix3d& frame, Eigen::VectorXd& x) {
  const Eigen::Matrix3d S = frame * frame_.transpose();
  const bool turn = rotatable_ && !S.isIdentity(0.0);
  rhs_ = r;
  if (turn) rotate(rhs_, S.transpose());
  const SerialOpenMpRegions cholmod_on_this_thread;  // (the LU's solve opens no regions)
  switch (solver_) {
    case Solver::Split: split_.solve(rhs_, x); break;
    case Solver::SplitLdlt: split_ldlt_.solve(rhs_, x); break;
    case Solver::Llt: x = llt_.solve(rhs_); break;
    case Solver::Ldlt: x = ldlt_.solve(rhs_); break;
    case Solver::Lu: x = lu_.solve(rhs_); break;
  }
  if (turn) rotate(x, S);
}

}  // namespace flapsim::fem
