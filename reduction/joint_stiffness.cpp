#include "reduction/joint_stiffness.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>

#include "reduction/reduction_failure.hpp"

namespace flapsim::reduction {

Eigen::VectorXd JointStiffness::diagonal_springs() const { return compliance.diagonal().cwiseInverse(); }

JointStiffness joint_stiffness(const Eigen::MatrixXd& c) {
  const int ns = static_cast<int>(c.rows()) / 3;
  const int n = 2 * ns;
  JointStiffness out;
  // C_rr: the rotations (θ, φ) of every station.
  Eigen::MatrixXd crr(n, n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) crr(a, b) = c(3 * (a / 2) + 1 + a % 2, 3 * (b / 2) + 1 + b % 2);
  out.difference = Eigen::MatrixXd::Identity(n, n);
  for (int j = 2; j < n; ++j) out.difference(j, j - 2) = -1.0;
  out.compliance = out.difference * crr * out.difference.transpose();
  out.compliance = (0.5 * (out.compliance + out.compliance.transpose())).eval();
  Eigen::LLT<Eigen::MatrixXd> llt(out.compliance);
  if (llt.info() != Eigen::Success)
    throw ReductionFailure(
        "the joints' compliance measured on the FEM is not positive definite; a section may have no free nodes");
  out.stiffness = llt.solve(Eigen::MatrixXd::Identity(n, n));
  out.stiffness = (0.5 * (out.stiffness + out.stiffness.transpose())).eval();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(out.stiffness, Eigen::EigenvaluesOnly);
  out.min_eigenvalue = es.eigenvalues()(0);
  out.max_eigenvalue = es.eigenvalues()(n - 1);
  if (!(out.min_eigenvalue > 0.0) || !std::isfinite(out.max_eigenvalue))
    throw ReductionFailure("the joint stiffness from the FEM is not positive definite (smallest eigenvalue " +
                           std::to_string(out.min_eigenvalue) + " N m/rad)");
  return out;
}

std::vector<double> flexural_axis_offsets(const Eigen::MatrixXd& c) {
  std::vector<double> out;
  for (int k = 0; 3 * k + 2 < c.rows(); ++k) out.push_back(c(3 * k + 2, 3 * k) / c(3 * k + 2, 3 * k + 2));
  return out;
}

}  // namespace flapsim::reduction
