#include "reduction/strip_mass.hpp"
#include "fem/skew.hpp"

#include <stdexcept>
#include <string>

namespace flapsim::reduction {

using fem::skew;

namespace {

Eigen::Vector3d vee(const Eigen::Matrix3d& s) {
  // The axial vector of the skew part of s.
  return 0.5 * Eigen::Vector3d(s(2, 1) - s(1, 2), s(0, 2) - s(2, 0), s(1, 0) - s(0, 1));
}

/// Rigid-body modes about the origin: u = v + ω × r, rotation ω (n_dof × 6).
Eigen::MatrixXd rigid_body_modes(const Eigen::Matrix3Xd& nodes) {
  const Eigen::Index n = nodes.cols();
  Eigen::MatrixXd phi = Eigen::MatrixXd::Zero(6 * n, 6);
  for (Eigen::Index i = 0; i < n; ++i) {
    phi.block<3, 3>(6 * i, 0).setIdentity();
    phi.block<3, 3>(6 * i, 3) = -skew(nodes.col(i));
    phi.block<3, 3>(6 * i + 3, 3).setIdentity();
  }
  return phi;
}

void check_sizes(const Eigen::SparseMatrix<double>& mass, const Eigen::Matrix3Xd& nodes) {
  if (mass.rows() != 6 * nodes.cols() || mass.cols() != 6 * nodes.cols())
    throw std::invalid_argument("strip_rigid_masses: mass matrix is " +
                                std::to_string(mass.rows()) + "x" + std::to_string(mass.cols()) +
                                ", expected 6 DOF for each of " + std::to_string(nodes.cols()) +
                                " nodes");
}

}  // namespace

Eigen::Matrix3d RigidMass::inertia_about_center() const {
  const Eigen::Vector3d c = center_of_mass();
  // I_O = I_c − m [c]×[c]×  ⇒  I_c = I_O + m [c]×[c]×
  return inertia_origin + mass * skew(c) * skew(c);
}

Eigen::Matrix3d RigidMass::inertia_about(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d d = center_of_mass() - p;
  return inertia_about_center() - mass * skew(d) * skew(d);
}

Eigen::Matrix<double, 6, 6> RigidMass::matrix() const {
  Eigen::Matrix<double, 6, 6> r;
  r.block<3, 3>(0, 0) = mass * Eigen::Matrix3d::Identity();
  r.block<3, 3>(0, 3) = -skew(first_moment);
  r.block<3, 3>(3, 0) = skew(first_moment);
  r.block<3, 3>(3, 3) = inertia_origin;
  return r;
}

RigidMass& RigidMass::operator+=(const RigidMass& other) {
  mass += other.mass;
  first_moment += other.first_moment;
  inertia_origin += other.inertia_origin;
  return *this;
}

RigidMass rigid_mass_from_matrix(const Eigen::Matrix<double, 6, 6>& r) {
  RigidMass out;
  out.mass = r.block<3, 3>(0, 0).trace() / 3.0;
  out.first_moment =
      0.5 * (vee(r.block<3, 3>(3, 0)) - vee(r.block<3, 3>(0, 3)));
  out.inertia_origin = 0.5 * (r.block<3, 3>(3, 3) + r.block<3, 3>(3, 3).transpose());
  return out;
}

std::vector<RigidMass> strip_rigid_masses(const Eigen::SparseMatrix<double>& mass,
                                          const Eigen::Matrix3Xd& nodes,
                                          const std::vector<int>& strip_of_node, int num_strips) {
  check_sizes(mass, nodes);
  if (static_cast<Eigen::Index>(strip_of_node.size()) != nodes.cols())
    throw std::invalid_argument("strip_rigid_masses: one strip index per node expected");
  const Eigen::MatrixXd phi = rigid_body_modes(nodes);
  const Eigen::MatrixXd m_phi = mass * phi;  // inertial loads of a rigid motion
  std::vector<Eigen::Matrix<double, 6, 6>> share(static_cast<std::size_t>(num_strips),
                                                 Eigen::Matrix<double, 6, 6>::Zero());
  for (Eigen::Index i = 0; i < nodes.cols(); ++i) {
    const int k = strip_of_node[static_cast<std::size_t>(i)];
    if (k < 0) continue;
    if (k >= num_strips) throw std::invalid_argument("strip_rigid_masses: strip index out of range");
    share[static_cast<std::size_t>(k)] +=
        phi.middleRows<6>(6 * i).transpose() * m_phi.middleRows<6>(6 * i);
  }
  std::vector<RigidMass> out;
  out.reserve(share.size());
  for (const auto& a : share) out.push_back(rigid_mass_from_matrix(0.5 * (a + a.transpose())));
  return out;
}

RigidMass total_rigid_mass(const Eigen::SparseMatrix<double>& mass, const Eigen::Matrix3Xd& nodes) {
  check_sizes(mass, nodes);
  const Eigen::MatrixXd phi = rigid_body_modes(nodes);
  const Eigen::MatrixXd r = phi.transpose() * (mass * phi);
  return rigid_mass_from_matrix(0.5 * (r + r.transpose()));
}

}  // namespace flapsim::reduction
