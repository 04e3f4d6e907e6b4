// The reduction's linearised chain (small motions about the straight rest shape)
// against mbd's mass matrix and against the Hencky cantilever of mbd's own eigen-analysis
// (docs/validation.md R4, R5).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "mbd/chain_data.hpp"
#include "mbd/chain_dynamics.hpp"
#include "mbd/chain_kinematics.hpp"
#include "mbd/chain_model.hpp"
#include "reduction/linear_chain.hpp"

namespace flapsim::reduction {
namespace {

TEST(LinearChain, MassMatrixEqualsMbdAtRest) {
  // A uniform chain made lopsided: offset centres of mass and full inertia tensors,
  // and a rotated root frame, so that every term of the mass matrix is exercised.
  mbd::ChainModel chain = mbd::make_uniform_cantilever_chain(0.05, 1e-4, 5e-5, 7e-4, 2e-9, 5);
  for (int k = 0; k < chain.num_bodies(); ++k) {
    auto& b = chain.bodies[static_cast<std::size_t>(k)];
    b.center_of_mass += Eigen::Vector3d(-0.002 * (k + 1), 0.0005, 0.0);
    b.inertia(0, 1) = b.inertia(1, 0) = 0.1 * std::min(b.inertia(0, 0), b.inertia(1, 1));
  }
  chain.root_rotation = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const LinearChain lin(chain);
  mbd::ChainData data(chain);
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(chain.num_dofs());
  mbd::forward_kinematics(chain, data, mbd::BasePose{}, q, q);
  mbd::compute_mass_matrix_and_bias(chain, data);
  // Independent routes to the same M(Φ = 0): composite-rigid-body assembly in mbd,
  // small-rotation Jacobians here. Equal to round-off.
  const double scale = data.mass_matrix.cwiseAbs().maxCoeff();
  EXPECT_LT((lin.mass_matrix() - data.mass_matrix).cwiseAbs().maxCoeff(), 1e-10 * scale);
}

// The first bending frequency [Hz] of a uniform Hencky cantilever written out in the plane,
// apart from mbd and LinearChain: n bars of length a = L/n, mass m' a and inertia m' a³/12
// about their centres; joint angles θ_j, bar angles φ_i = Σ_{j≤i} θ_j, bar-centre deflections
// w_i = Σ_{j<i} a φ_j + a φ_i / 2; T = ½ Σ (m ẇ_i² + I φ̇_i²), V = ½ Σ k_j θ_j² with
// k_0 = 2EI/a at the root and EI/a between bars (Hencky's lumping).
double planar_hencky_first_bending_hz(double L, double EI, double mpl, int n) {
  const double a = L / n, m = mpl * a, inertia = m * a * a / 12.0;
  Eigen::MatrixXd phi = Eigen::MatrixXd::Zero(n, n), w = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j) phi(i, j) = 1.0;
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < i; ++k) w.row(i) += a * phi.row(k);
    w.row(i) += 0.5 * a * phi.row(i);
  }
  const Eigen::MatrixXd M = m * w.transpose() * w + inertia * phi.transpose() * phi;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) K(j, j) = (j == 0 ? 2.0 : 1.0) * EI / a;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, M);
  return std::sqrt(eig.eigenvalues()(0)) / (2.0 * std::numbers::pi);
}

TEST(LinearChain, HenckyCantileverFrequencies) {
  // Uniform cantilever, root spring 2EI/a, interior EI/a, distributed-mass bars. Two
  // references: (1) the same chain written out in the plane above (an independent code):
  // LinearChain's first bending frequency equals it to 1e-9; (2) beam theory,
  // ω₁ = 1.8751² √(EI/(m' L⁴)) [Blevins 1979, Table 8-1]: the chain converges to it from below
  // at second order (error ratio 4 per halving of a). The often-quoted −3.9, −1.0, −0.25 %
  // are for a different lumping (docs/validation.md M2).
  const double L = 0.05, EI = 1e-4, GJ = 5e-5, mpl = 7e-4, ia = 2e-9;
  const double f_beam = 1.8751 * 1.8751 / (2.0 * std::numbers::pi) * std::sqrt(EI / (mpl * std::pow(L, 4)));
  double err[3];
  int i = 0;
  for (int nb : {4, 8, 16}) {
    const LinearChain lin(mbd::make_uniform_cantilever_chain(L, EI, GJ, mpl, ia, nb));
    double f = 0.0;
    for (const ChainMode& m : lin.modes())
      if (m.is_bending()) {
        f = m.frequency_hz;
        break;
      }
    const double planar = planar_hencky_first_bending_hz(L, EI, mpl, nb);
    EXPECT_NEAR(f / planar, 1.0, 1e-9) << nb;
    err[i] = f / f_beam - 1.0;
    EXPECT_LT(err[i], 0.0) << nb;  // from below
    ++i;
  }
  EXPECT_NEAR(err[0] / err[1], 4.0, 0.5);  // second order
  EXPECT_NEAR(err[1] / err[2], 4.0, 0.5);
}

// A joint without a twist spring (a chain file's twist_stiffness = 0): the chain's first mode
// is that joint's free twist, of frequency 0 and no spring energy. Its kind was the spring
// energy's round-off (a 4-body chain's warning said "0 Hz (bending)" for a mode whose shape
// was the twist of joint 2 alone); it is now named by its kinetic energy: torsion.
TEST(LinearChain, AJointWithoutATwistSpringGivesATorsionMechanism) {
  mbd::ChainModel chain = mbd::make_uniform_cantilever_chain(0.05, 1e-4, 5e-5, 7e-4, 2e-9, 4);
  chain.joints[2].twist_stiffness = 0.0;  // the joint inboard of the third body
  const std::vector<ChainMode> modes = LinearChain(chain).modes();
  ASSERT_FALSE(modes.empty());
  EXPECT_NEAR(modes[0].frequency_hz, 0.0, 1e-3);
  EXPECT_FALSE(modes[0].is_bending());
  EXPECT_LT(modes[0].bending_energy_fraction, 1e-6);
  // The other modes keep their spring-energy kinds: the first bending mode is still found.
  EXPECT_TRUE(std::any_of(modes.begin(), modes.end(), [](const ChainMode& m) { return m.is_bending(); }));
}

}  // namespace
}  // namespace flapsim::reduction
