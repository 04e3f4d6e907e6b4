#include "fem/static_solver.hpp"

#include <Eigen/CholmodSupport>

#include "fem/serial_openmp_regions.hpp"

namespace flapsim::fem {

struct StaticSolver::Factor {
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
};

StaticSolver::StaticSolver(const SparseMatrix& K, Constraints constraints)
    : constraints_(std::move(constraints)), factor_(std::make_unique<Factor>()) {
  if (constraints_.num_free() == 0) return;
  const SparseMatrix Kf = constraints_.reduce(K);
  const SerialOpenMpRegions cholmod_on_this_thread;  // CHOLMOD's fixed 4-thread teams
  factor_->llt.compute(Kf);
  if (factor_->llt.info() != Eigen::Success)
    throw SingularStiffness(
        "static solve: the constrained stiffness matrix is not positive definite "
        "(is the structure supported, connected, with non-zero stiffness?)");
}

StaticSolver::~StaticSolver() = default;

Eigen::VectorXd StaticSolver::solve(const Eigen::VectorXd& F) const {
  if (F.size() != constraints_.num_dofs())
    throw std::invalid_argument("StaticSolver::solve: load vector size does not match the DOF count");
  if (constraints_.num_free() == 0) return Eigen::VectorXd::Zero(F.size());
  const SerialOpenMpRegions cholmod_on_this_thread;
  const Eigen::VectorXd uf = factor_->llt.solve(constraints_.reduce(F));
  return constraints_.expand(uf);
}

Eigen::MatrixXd StaticSolver::solve(const Eigen::MatrixXd& F) const {
  Eigen::MatrixXd U(F.rows(), F.cols());
  for (Eigen::Index c = 0; c < F.cols(); ++c) U.col(c) = solve(Eigen::VectorXd(F.col(c)));
  return U;
}

Eigen::VectorXd reactions(const SparseMatrix& K, const Eigen::VectorXd& u, const Eigen::VectorXd& F) {
  return K * u - F;
}

}  // namespace flapsim::fem
