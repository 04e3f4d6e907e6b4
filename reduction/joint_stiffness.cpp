#include "reduction/joint_stiffness.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <string>

#include "reduction/reduction_failure.hpp"

namespace flapsim::reduction {

Eigen::VectorXd JointStiffness::diagonal_springs() const { return compliance.diagonal().cwiseInverse(); }

Eigen::MatrixXd chain_joint_map(int nb, double a) {
  // Station i's coordinates in u: 3 i + {0: w, 1: θ, 2: φ}; body i has stations 2i (mid) and 2i + 1 (joint).
  auto w_joint = [](int i) { return 3 * (2 * i + 1); };
  auto phi_mid = [](int i) { return 3 * (2 * i) + 2; };
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(2 * nb, 6 * nb);
  for (int i = 0; i < nb; ++i) {
    // θ-joint i = θ_i − θ_{i−1} = (w_i − 2 w_{i−1} + w_{i−2}) / a
    t(2 * i, w_joint(i)) += 1.0 / a;
    if (i >= 1) t(2 * i, w_joint(i - 1)) -= 2.0 / a;
    if (i >= 2) t(2 * i, w_joint(i - 2)) += 1.0 / a;
    // α-joint i = φ_i − φ_{i−1}
    t(2 * i + 1, phi_mid(i)) = 1.0;
    if (i >= 1) t(2 * i + 1, phi_mid(i - 1)) = -1.0;
  }
  return t;
}

JointStiffness joint_stiffness(const Eigen::MatrixXd& c, double body_length) {
  const int nb = static_cast<int>(c.rows()) / 6;
  const int n = 2 * nb;
  JointStiffness out;
  out.joint_map = chain_joint_map(nb, body_length);
  out.compliance = out.joint_map * c * out.joint_map.transpose();
  out.compliance = (0.5 * (out.compliance + out.compliance.transpose())).eval();
  Eigen::LLT<Eigen::MatrixXd> llt(out.compliance);
  if (llt.info() != Eigen::Success)
    throw ReductionFailure(
        "the joints' compliance measured on the FEM is not positive definite; a section may have no free nodes: "
        "use fewer bodies or a finer mesh ([mesh] element_size)");
  out.stiffness = llt.solve(Eigen::MatrixXd::Identity(n, n));
  out.stiffness = (0.5 * (out.stiffness + out.stiffness.transpose())).eval();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(out.stiffness, Eigen::EigenvaluesOnly);
  out.min_eigenvalue = es.eigenvalues()(0);
  out.max_eigenvalue = es.eigenvalues()(n - 1);
  if (!(out.min_eigenvalue > 0.0) || !std::isfinite(out.max_eigenvalue))
    throw ReductionFailure("the joint stiffness from the FEM is not positive definite (smallest eigenvalue " +
                           std::to_string(out.min_eigenvalue) + " N m/rad): use fewer bodies or a finer mesh ([mesh] element_size)");
  return out;
}

std::vector<double> flexural_axis_offsets(const Eigen::MatrixXd& c) {
  std::vector<double> out;
  for (int k = 0; 3 * k + 2 < c.rows(); ++k) out.push_back(c(3 * k + 2, 3 * k) / c(3 * k + 2, 3 * k + 2));
  return out;
}

}  // namespace flapsim::reduction
