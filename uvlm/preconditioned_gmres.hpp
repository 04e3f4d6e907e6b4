#pragma once
/// \file preconditioned_gmres.hpp
/// \brief Restarted GMRES (Saad & Schultz 1986, SIAM J. Sci. Stat. Comput. 7; Saad,
/// "Iterative Methods for Sparse Linear Systems", 2nd ed. 2003, Alg. 9.5) for a dense
/// system A x = b, right-preconditioned by the LU factorisation of a nearby matrix M:
/// it solves A M⁻¹ u = b, x = M⁻¹ u, so the residual it stops on is the true one,
/// ‖b − A x‖₂ ≤ tolerance · ‖b‖₂ (checked against the explicitly recomputed residual
/// before it stops). When M is the matrix of an earlier surface of a wing that moved by a
/// fraction of a panel, A M⁻¹ is close to the identity and a few iterations, each one
/// product with A and one solve with M's factors (O(N²)), replace a new factorisation
/// (O(N³)). Modified Gram–Schmidt, Givens rotations; all storage is allocated by reserve().

#include <Eigen/Core>
#include <Eigen/LU>

namespace flapsim::uvlm {

class PreconditionedGmres {
 public:
  struct Result {
    int iterations = 0;              ///< Krylov iterations (products with A)
    double relative_residual = 0.0;  ///< ‖b − A x‖₂ / ‖b‖₂ of the returned x
    bool converged = false;
  };

  /// Storage for systems of size n and `restart` iterations between restarts.
  void reserve(int n, int restart);
  int size() const { return static_cast<int>(basis_.rows()); }

  /// Solve A x = b to ‖b − A x‖₂ ≤ tolerance ‖b‖₂, x holding the first guess on entry,
  /// with at most max_iterations iterations (restarting every `restart`). Allocates nothing.
  Result solve(const Eigen::MatrixXd& a, const Eigen::PartialPivLU<Eigen::MatrixXd>& preconditioner,
               const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance, int max_iterations);

 private:
  Eigen::MatrixXd basis_;      ///< n × (restart + 1): the Krylov basis V
  Eigen::MatrixXd hessenberg_; ///< (restart + 1) × restart, triangularised in place
  Eigen::VectorXd cosine_, sine_, g_, y_;
  Eigen::VectorXd w_, z_, r_;
};

}  // namespace flapsim::uvlm
