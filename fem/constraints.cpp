#include "fem/constraints.hpp"

#include <stdexcept>

namespace flapsim::fem {

Constraints::Constraints(int num_dofs) : fixed_(static_cast<size_t>(num_dofs), 0) {}

void Constraints::clamp_nodes(const std::vector<int>& nodes) {
  for (int n : nodes)
    for (int d = 0; d < kDofsPerNode; ++d) fix_dof(dof_index(n, d));
}

void Constraints::fix_dof(int dof) {
  if (dof < 0 || dof >= num_dofs()) throw std::out_of_range("Constraints::fix_dof: DOF out of range");
  fixed_[static_cast<size_t>(dof)] = 1;
}

int Constraints::num_free() const {
  int n = 0;
  for (char f : fixed_) n += f ? 0 : 1;
  return n;
}

std::vector<int> Constraints::free_index() const {
  std::vector<int> idx(fixed_.size(), -1);
  int k = 0;
  for (size_t i = 0; i < fixed_.size(); ++i)
    if (!fixed_[i]) idx[i] = k++;
  return idx;
}

std::vector<int> Constraints::free_dofs() const {
  std::vector<int> out;
  out.reserve(fixed_.size());
  for (size_t i = 0; i < fixed_.size(); ++i)
    if (!fixed_[i]) out.push_back(static_cast<int>(i));
  return out;
}

SparseMatrix Constraints::reduce(const SparseMatrix& A) const {
  if (A.rows() != num_dofs() || A.cols() != num_dofs())
    throw std::invalid_argument("Constraints::reduce: matrix size does not match the DOF count");
  const std::vector<int> idx = free_index();
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<size_t>(A.nonZeros()));
  for (int c = 0; c < A.outerSize(); ++c) {
    if (idx[c] < 0) continue;
    for (SparseMatrix::InnerIterator it(A, c); it; ++it)
      if (idx[it.row()] >= 0) t.emplace_back(idx[it.row()], idx[c], it.value());
  }
  const int nf = num_free();
  SparseMatrix R(nf, nf);
  R.setFromTriplets(t.begin(), t.end());
  return R;
}

Eigen::VectorXd Constraints::reduce(const Eigen::VectorXd& v) const {
  Eigen::VectorXd r(num_free());
  int k = 0;
  for (size_t i = 0; i < fixed_.size(); ++i)
    if (!fixed_[i]) r(k++) = v(static_cast<Eigen::Index>(i));
  return r;
}

Eigen::VectorXd Constraints::expand(const Eigen::VectorXd& f) const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(num_dofs());
  int k = 0;
  for (size_t i = 0; i < fixed_.size(); ++i)
    if (!fixed_[i]) v(static_cast<Eigen::Index>(i)) = f(k++);
  return v;
}

std::vector<int> nodes_at_or_below_y(const Mesh& mesh, double clamp_y) {
  std::vector<int> out;
  for (int i = 0; i < mesh.num_nodes(); ++i)
    if (mesh.nodes[static_cast<size_t>(i)].y() <= clamp_y) out.push_back(i);
  return out;
}

Constraints root_clamp(const Mesh& mesh, double clamp_y) {
  Constraints c(mesh.num_dofs());
  c.clamp_nodes(nodes_at_or_below_y(mesh, clamp_y));
  return c;
}

}  // namespace flapsim::fem
