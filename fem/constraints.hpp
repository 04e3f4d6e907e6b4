#pragma once
/// \file constraints.hpp
/// \brief Boundary conditions by DOF elimination: fixed DOFs are removed from
/// K and M (no penalty numbers, so conditioning is unchanged); displacements at
/// fixed DOFs are exactly zero.

#include <vector>

#include <Eigen/Core>

#include "fem/assembly.hpp"
#include "fem/mesh.hpp"

namespace flapsim::fem {

/// Which global DOFs are fixed, and the map between full and free numbering.
class Constraints {
 public:
  /// All `num_dofs` DOFs free.
  explicit Constraints(int num_dofs = 0);

  /// \brief Fix all six DOFs of each listed node (a clamp).
  void clamp_nodes(const std::vector<int>& nodes);
  /// \brief Fix one global DOF.
  void fix_dof(int dof);

  int num_dofs() const { return static_cast<int>(fixed_.size()); }
  int num_free() const;
  bool is_fixed(int dof) const { return fixed_[static_cast<size_t>(dof)] != 0; }
  /// Free index of each full DOF (−1 if fixed), and the full DOF of each free index.
  std::vector<int> free_index() const;
  std::vector<int> free_dofs() const;

  /// \brief The free–free block of a full matrix.
  SparseMatrix reduce(const SparseMatrix& A) const;
  /// \brief Free part of a full vector.
  Eigen::VectorXd reduce(const Eigen::VectorXd& v) const;
  /// \brief Full vector from free values (zeros at fixed DOFs).
  Eigen::VectorXd expand(const Eigen::VectorXd& free_values) const;

 private:
  std::vector<char> fixed_;
};

/// \brief Nodes with y <= clamp_y [m] (the wing root).
std::vector<int> nodes_at_or_below_y(const Mesh& mesh, double clamp_y);

/// \brief Constraints that clamp every node with y <= clamp_y.
Constraints root_clamp(const Mesh& mesh, double clamp_y);

}  // namespace flapsim::fem
