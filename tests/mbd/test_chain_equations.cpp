// The chain's equations of motion checked against a second route: M against the
// Hessian of the kinetic energy, H against Lagrange's equation evaluated by finite
// differences of T, Q against the virtual work of the applied loads.

#include "chain_test_models.hpp"

#include "mbd/chain_data.hpp"
#include "mbd/chain_dynamics.hpp"
#include "mbd/chain_energy.hpp"
#include "mbd/chain_kinematics.hpp"
#include "mbd/chain_loads.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

namespace flapsim::mbd {
namespace {

using test::general_chain;
using test::wobbling_kinematics;

double kinetic(const ChainModel& model, ChainData& data, const BasePose& pose,
               const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  forward_kinematics(model, data, pose, q, v);
  return kinetic_energy(model, data);
}

Eigen::VectorXd sample_q(int n) {
  Eigen::VectorXd q(n);
  for (int i = 0; i < n; ++i) q(i) = 0.3 * std::sin(1.7 * i + 0.4) + 0.1;
  return q;
}
Eigen::VectorXd sample_v(int n) {
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v(i) = 40.0 * std::cos(2.3 * i + 0.2);
  return v;
}

// T is quadratic in Φ̇: M_ij = T(v+e_i+e_j) − T(v+e_i) − T(v+e_j) + T(v) exactly
// (polarization identity), for a fixed and for a moving base.
void expect_mass_matrix_is_hessian_of_t(const BasePose& pose) {
  const ChainModel model = general_chain();
  ChainData data(model);
  const int n = model.num_dofs();
  const Eigen::VectorXd q = sample_q(n), v0 = sample_v(n);
  forward_kinematics(model, data, pose, q, v0);
  compute_mass_matrix_and_bias(model, data);
  const Eigen::MatrixXd M = data.mass_matrix;

  const double t0 = kinetic(model, data, pose, q, v0);
  Eigen::MatrixXd Mfd(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::VectorXd ei = Eigen::VectorXd::Unit(n, i), ej = Eigen::VectorXd::Unit(n, j);
      Mfd(i, j) = kinetic(model, data, pose, q, v0 + ei + ej) - kinetic(model, data, pose, q, v0 + ei) -
                  kinetic(model, data, pose, q, v0 + ej) + t0;
    }
  // Round-off of T (~1e-16 T with |Φ̇| ~ 40 rad/s) relative to |M|: 1e-9 is ample.
  EXPECT_LT((M - Mfd).cwiseAbs().maxCoeff(), 1e-9 * M.cwiseAbs().maxCoeff());
  EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-14 * M.cwiseAbs().maxCoeff());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues().minCoeff(), 0.0);
}

TEST(ChainEquations, MassMatrixIsHessianOfKineticEnergyFixedBase) {
  expect_mass_matrix_is_hessian_of_t(BasePose{});
}

TEST(ChainEquations, MassMatrixIsHessianOfKineticEnergyMovingBase) {
  expect_mass_matrix_is_hessian_of_t(wobbling_kinematics(26.0).pose(0.013));
}

// Lagrange: H_inertial(Φ, Φ̇, t) = d/dt(∂T/∂Φ̇) − ∂T/∂Φ along Φ(τ) = Φ + Φ̇τ (Φ̈ = 0),
// t → t + τ, with the base moving (ω, ω̇ ≠ 0). ∂T/∂Φ̇ by central differences in Φ̇ (exact
// for a quadratic), d/dt and ∂/∂Φ by central differences (error O(δ²)).
TEST(ChainEquations, BiasForcesEqualLagrangeEquationByFiniteDifferences) {
  const ChainModel model = general_chain();
  ChainData data(model);
  const int n = model.num_dofs();
  const WingKinematics kin = wobbling_kinematics(26.0);
  const Eigen::VectorXd q = sample_q(n), v = sample_v(n);
  const double t = 0.0071;

  forward_kinematics(model, data, kin.pose(t), q, v);
  compute_mass_matrix_and_bias(model, data);
  const Eigen::VectorXd h = data.inertial_bias;

  auto momentum = [&](const Eigen::VectorXd& qq, double tt) {
    Eigen::VectorXd p(n);
    const BasePose pose = kin.pose(tt);
    for (int i = 0; i < n; ++i) {
      const Eigen::VectorXd e = Eigen::VectorXd::Unit(n, i);
      p(i) = (kinetic(model, data, pose, qq, v + e) - kinetic(model, data, pose, qq, v - e)) / 2.0;
    }
    return p;
  };
  const double dt = 2e-6;  // [s]; (2π·26·dt)² ~ 1e-7 truncation
  const Eigen::VectorXd dpdt = (momentum(q + v * dt, t + dt) - momentum(q - v * dt, t - dt)) / (2.0 * dt);
  Eigen::VectorXd dtdq(n);
  const double dq = 1e-6;
  for (int i = 0; i < n; ++i) {
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(n, i) * dq;
    dtdq(i) = (kinetic(model, data, kin.pose(t), q + e, v) - kinetic(model, data, kin.pose(t), q - e, v)) /
              (2.0 * dq);
  }
  const Eigen::VectorXd h_lagrange = dpdt - dtdq;
  const double scale = h.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  // Finite-difference truncation ~ (ω δt)² and round-off ~ 1e-16 T/δ: 1e-6 of |H|.
  EXPECT_LT((h - h_lagrange).cwiseAbs().maxCoeff(), 1e-6 * scale)
      << "H = " << h.transpose() << "\nLagrange = " << h_lagrange.transpose();
}

// Q = Σ J_pᵀ F + J_ωᵀ N: the virtual work of point forces (ground and body components),
// a pure moment and gravity, with ∂p/∂Φ and the rotation vector of ∂R/∂Φ taken by
// finite differences of the kinematics.
TEST(ChainEquations, GeneralizedForcesEqualVirtualWorkOfLoads) {
  ChainModel model = general_chain();
  model.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  ChainData data(model);
  const int n = model.num_dofs();
  const BasePose pose = wobbling_kinematics(26.0).pose(0.004);
  const Eigen::VectorXd q = sample_q(n), v = Eigen::VectorXd::Zero(n);

  const Eigen::Vector3d p1(0.003, 0.006, 0.0005), f1(0.01, -0.02, 0.03);   // body 2, ground
  const Eigen::Vector3d p2(-0.002, 0.01, 0.0), f2(-0.005, 0.004, 0.02);    // body 3, body frame
  const Eigen::Vector3d m3(1e-4, -2e-4, 3e-4);                             // body 1, body frame
  Loads loads(model.num_bodies());
  loads.add_force(2, p1, f1, LoadFrame::ground);
  loads.add_force(3, p2, f2, LoadFrame::body);
  loads.add_moment(1, m3, LoadFrame::body);
  forward_kinematics(model, data, pose, q, v);
  compute_generalized_loads(model, data, loads);
  const Eigen::VectorXd Q = data.generalized_load;
  const Eigen::Vector3d f2g = data.bodies[3].rotation * f2;  // frozen at this pose
  const Eigen::Vector3d m3g = data.bodies[1].rotation * m3;

  Eigen::VectorXd Qfd(n);
  const double d = 1e-6;
  for (int i = 0; i < n; ++i) {
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(n, i) * d;
    forward_kinematics(model, data, pose, q + e, v);
    const Eigen::Vector3d a1 = point_position(data, 2, p1), a2 = point_position(data, 3, p2);
    const Eigen::Matrix3d r1 = data.bodies[1].rotation;
    double pe_plus = 0.0;
    for (int b = 0; b < model.num_bodies(); ++b) pe_plus += model.bodies[b].mass * model.gravity.dot(data.bodies[b].com);
    forward_kinematics(model, data, pose, q - e, v);
    const Eigen::Vector3d b1 = point_position(data, 2, p1), b2 = point_position(data, 3, p2);
    const Eigen::Matrix3d s1 = data.bodies[1].rotation;
    double pe_minus = 0.0;
    for (int b = 0; b < model.num_bodies(); ++b) pe_minus += model.bodies[b].mass * model.gravity.dot(data.bodies[b].com);
    const Eigen::Matrix3d dR = (r1 - s1) * s1.transpose() / (2.0 * d);  // ≈ skew(∂θ/∂Φ_i)
    const Eigen::Vector3d dtheta(dR(2, 1), dR(0, 2), dR(1, 0));
    Qfd(i) = f1.dot(a1 - b1) / (2.0 * d) + f2g.dot(a2 - b2) / (2.0 * d) + m3g.dot(dtheta) +
             (pe_plus - pe_minus) / (2.0 * d);
  }
  EXPECT_LT((Q - Qfd).cwiseAbs().maxCoeff(), 1e-7 * Q.cwiseAbs().maxCoeff())
      << "Q = " << Q.transpose() << "\nvirtual work = " << Qfd.transpose();
}

// Points fixed in a body move with it: velocity = d/dt position (finite differences
// along a trajectory with moving base and joints).
TEST(ChainEquations, PointVelocityIsTimeDerivativeOfPosition) {
  const ChainModel model = general_chain();
  ChainData data(model);
  const int n = model.num_dofs();
  const WingKinematics kin = wobbling_kinematics(26.0);
  const Eigen::VectorXd q = sample_q(n), v = sample_v(n);
  const double t = 0.011, dt = 1e-7;
  const Eigen::Vector3d p(0.004, 0.008, -0.001);
  forward_kinematics(model, data, kin.pose(t + dt), q + v * dt, v);
  const Eigen::Vector3d xp = point_position(data, 3, p);
  forward_kinematics(model, data, kin.pose(t - dt), q - v * dt, v);
  const Eigen::Vector3d xm = point_position(data, 3, p);
  forward_kinematics(model, data, kin.pose(t), q, v);
  const Eigen::Vector3d vel = point_velocity(data, 3, p);
  EXPECT_LT((vel - (xp - xm) / (2.0 * dt)).norm(), 1e-6 * vel.norm());
}

// Joint convention (docs/multibody.md): R_{k−1,k} = Rx(θ)·Ry(α); a positive bend moves
// the child's tip toward +z of the parent.
TEST(ChainEquations, PositiveBendMovesChildTowardPlusZ) {
  ChainModel model = test::three_body_chain();
  ChainData data(model);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(model.num_dofs());
  q(0) = 0.2;  // θ of the joint between bodies 0 and 1
  forward_kinematics(model, data, BasePose{}, q, q * 0.0);
  const Eigen::Vector3d tip = point_position(data, 1, Eigen::Vector3d(0.0, 0.0161, 0.0));
  EXPECT_NEAR(tip.z(), 0.0161 * std::sin(0.2), 1e-15);  // geometry: L sin θ
  EXPECT_NEAR(tip.y(), 0.0161 + 0.0161 * std::cos(0.2), 1e-15);
}

}  // namespace
}  // namespace flapsim::mbd
