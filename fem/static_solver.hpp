#pragma once
/// \file static_solver.hpp
/// \brief Linear statics K u = F with constrained DOFs eliminated, factorised
/// once with CHOLMOD (supernodal LLᵀ) and reused for any number of load cases.

#include <memory>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "fem/assembly.hpp"
#include "fem/constraints.hpp"

namespace flapsim::fem {

/// Thrown when a stiffness matrix cannot be factorised (a mechanism: missing
/// supports, disconnected parts, zero material constants).
class SingularStiffness : public std::runtime_error {
 public:
  explicit SingularStiffness(const std::string& what) : std::runtime_error(what) {}
};

/// Factorised constrained stiffness. Not copyable (owns the CHOLMOD factor).
class StaticSolver {
 public:
  /// \brief Factorise the free block of K.
  /// \param K            assembled stiffness (full DOF numbering)
  /// \param constraints  fixed DOFs; throws SingularStiffness if the free block is not positive definite
  StaticSolver(const SparseMatrix& K, Constraints constraints);
  ~StaticSolver();
  StaticSolver(const StaticSolver&) = delete;
  StaticSolver& operator=(const StaticSolver&) = delete;

  /// \brief Displacements for nodal loads F (full numbering; loads on fixed
  /// DOFs are ignored). Returns the full displacement vector, zero at fixed DOFs.
  Eigen::VectorXd solve(const Eigen::VectorXd& F) const;
  /// \brief One column per load case.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& F) const;

  const Constraints& constraints() const { return constraints_; }

 private:
  struct Factor;
  Constraints constraints_;
  std::unique_ptr<Factor> factor_;
};

/// \brief Reactions R = K u − F at the fixed DOFs (zero elsewhere up to round-off).
Eigen::VectorXd reactions(const SparseMatrix& K, const Eigen::VectorXd& u, const Eigen::VectorXd& F);

}  // namespace flapsim::fem
