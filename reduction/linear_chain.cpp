#include "reduction/linear_chain.hpp"
#include "fem/skew.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace flapsim::reduction {

using fem::skew;

LinearChain::LinearChain(const mbd::ChainModel& chain) : chain_(&chain) {
  chain.validate();
  const int nb = chain.num_bodies();
  const Eigen::VectorXd rest = chain.rest_angles();
  if (rest.size() > 0 && rest.cwiseAbs().maxCoeff() > 0.0)
    throw std::invalid_argument("LinearChain: the chain must be straight at rest (zero rest angles)");
  joints_.assign(static_cast<std::size_t>(nb), Eigen::Vector3d::Zero());
  for (int k = 1; k < nb; ++k)
    joints_[static_cast<std::size_t>(k)] =
        joints_[static_cast<std::size_t>(k - 1)] + chain.bodies[static_cast<std::size_t>(k - 1)].outboard_joint;
  stiffness_ = chain.stiffness();
  const int n = chain.num_dofs();
  mass_ = Eigen::MatrixXd::Zero(n, n);
  // Body k's spatial velocity about its origin: v = Σ_j q̇_j e_j × (r_k − r_j), ω = Σ_j q̇_j e_j.
  Eigen::MatrixXd jac(6, n);
  for (int k = 0; k < nb; ++k) {
    jac.setZero();
    const Eigen::Vector3d& rk = joints_[static_cast<std::size_t>(k)];
    for (int j = chain.first_jointed_body(); j <= k; ++j) {
      const int d = chain.dof_of_body(j);
      const Eigen::Vector3d arm = rk - joints_[static_cast<std::size_t>(j)];
      const Eigen::Vector3d ex = Eigen::Vector3d::UnitX(), ey = Eigen::Vector3d::UnitY();
      jac.block<3, 1>(0, d) = ex.cross(arm);
      jac.block<3, 1>(3, d) = ex;
      jac.block<3, 1>(0, d + 1) = ey.cross(arm);
      jac.block<3, 1>(3, d + 1) = ey;
    }
    const mbd::ChainBody& b = chain.bodies[static_cast<std::size_t>(k)];
    Eigen::Matrix<double, 6, 6> r;
    const Eigen::Matrix3d c = skew(b.center_of_mass);
    r.block<3, 3>(0, 0) = b.mass * Eigen::Matrix3d::Identity();
    r.block<3, 3>(0, 3) = -b.mass * c;
    r.block<3, 3>(3, 0) = b.mass * c;
    r.block<3, 3>(3, 3) = b.inertia - b.mass * c * c;
    mass_ += jac.transpose() * r * jac;
  }
}

int LinearChain::body_at(double y) const {
  const int nb = static_cast<int>(joints_.size());
  for (int k = nb - 1; k > 0; --k)
    if (y >= joints_[static_cast<std::size_t>(k)].y()) return k;
  return 0;
}

std::vector<ChainMode> LinearChain::modes() const {
  const int n = num_dofs();
  std::vector<ChainMode> out;
  if (n == 0) return out;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(stiffness_, mass_);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("LinearChain: eigenvalue problem of the chain failed");
  // An eigenvalue below this fraction of the largest is a mechanism's (no spring), not a
  // mode's: at round-off.
  constexpr double kMechanism = 1e-12;
  const double largest = solver.eigenvalues().maxCoeff();
  for (int i = 0; i < n; ++i) {
    ChainMode m;
    const double lambda = std::max(solver.eigenvalues()[i], 0.0);
    m.frequency_hz = std::sqrt(lambda) / (2.0 * std::numbers::pi);
    m.shape = solver.eigenvectors().col(i);
    Eigen::VectorXd bend = m.shape, twist = m.shape;
    for (int d = 0; d < n; ++d) (d % 2 == 0 ? twist : bend)[d] = 0.0;
    double e_bend = bend.dot(stiffness_ * bend), e_twist = twist.dot(stiffness_ * twist);
    // A mode of no stiffness (a joint without a spring: frequency 0) stores no spring energy,
    // and its kind was the round-off's ("0 Hz (bending)" for a pure twist of the joint): it
    // is named by where its kinetic energy lies.
    if (!(lambda > kMechanism * largest)) {
      e_bend = bend.dot(mass_ * bend);
      e_twist = twist.dot(mass_ * twist);
    }
    m.bending_energy_fraction = e_bend + e_twist > 0.0 ? e_bend / (e_bend + e_twist) : 0.0;
    out.push_back(std::move(m));
  }
  return out;
}

Eigen::VectorXd LinearChain::generalized_force(int body, const Eigen::Vector3d& point,
                                               const Eigen::Vector3d& force,
                                               const Eigen::Vector3d& torque) const {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(num_dofs());
  for (int j = chain_->first_jointed_body(); j <= body; ++j) {
    const int d = chain_->dof_of_body(j);
    const Eigen::Vector3d arm = point - joints_[static_cast<std::size_t>(j)];
    q[d] = Eigen::Vector3d::UnitX().cross(arm).dot(force) + torque.x();
    q[d + 1] = Eigen::Vector3d::UnitY().cross(arm).dot(force) + torque.y();
  }
  return q;
}

Eigen::VectorXd LinearChain::static_response(const Eigen::VectorXd& generalized_force) const {
  Eigen::LLT<Eigen::MatrixXd> llt(stiffness_);
  if (llt.info() != Eigen::Success)
    throw std::runtime_error("the chain's joint stiffness is not positive definite: no static response");
  return llt.solve(generalized_force);
}

Eigen::Vector3d LinearChain::displacement(int body, const Eigen::Vector3d& point,
                                          const Eigen::VectorXd& q) const {
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  for (int j = chain_->first_jointed_body(); j <= body; ++j) {
    const int d = chain_->dof_of_body(j);
    const Eigen::Vector3d rot(q[d], q[d + 1], 0.0);
    u += rot.cross(point - joints_[static_cast<std::size_t>(j)]);
  }
  return u;
}

Eigen::Vector3d LinearChain::rotation(int body, const Eigen::VectorXd& q) const {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (int j = chain_->first_jointed_body(); j <= body; ++j) {
    const int d = chain_->dof_of_body(j);
    r += Eigen::Vector3d(q[d], q[d + 1], 0.0);
  }
  return r;
}

}  // namespace flapsim::reduction
