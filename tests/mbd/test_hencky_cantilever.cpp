// A uniform Euler–Bernoulli cantilever cut into a Hencky bar chain: the first bending
// frequency of the chain (generalized eigenvalue of its linearised K and M) converges
// to the beam's from below at second order ([Hencky 1920], docs/references.md;
// docs/validation.md M1, M2).

#include "mbd/chain_data.hpp"
#include "mbd/chain_dynamics.hpp"
#include "mbd/chain_kinematics.hpp"
#include "mbd/chain_model.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <vector>

namespace flapsim::mbd {
namespace {

// First bending frequency [rad/s] of the chain at rest (straight, base fixed).
double chain_first_bending(const ChainModel& model) {
  ChainData data(model);
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(model.num_dofs());
  forward_kinematics(model, data, BasePose{}, q, q);
  compute_mass_matrix_and_bias(model, data);
  const int nb = model.num_bodies();
  // Bending (θ: even dofs) and torsion decouple for centres of mass on the axis.
  Eigen::MatrixXd M(nb, nb), K = Eigen::MatrixXd::Zero(nb, nb);
  for (int i = 0; i < nb; ++i) {
    K(i, i) = model.joints[i].bend_stiffness;
    for (int j = 0; j < nb; ++j) {
      M(i, j) = data.mass_matrix(2 * i, 2 * j);
      EXPECT_NEAR(data.mass_matrix(2 * i, 2 * j + 1), 0.0, 1e-14 * data.mass_matrix.norm());
    }
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M);
  return std::sqrt(es.eigenvalues()(0));
}

TEST(HenckyCantilever, FirstBendingFrequencyConvergesFromBelowAtSecondOrder) {
  const double L = 0.05, EI = 2e-5, GJ = 1e-5, m = 1e-3, ia = 1e-9;
  // Euler–Bernoulli cantilever: ω₁ = (β₁L)² √(EI/(m'L⁴)), β₁L = 1.8751 ([Blevins 1979], Table 8-1).
  const double beta = 1.87510407;
  const double w_beam = beta * beta * std::sqrt(EI / (m * std::pow(L, 4)));
  const int counts[3] = {4, 8, 16};
  // Often quoted: −3.9 %, −1.0 %, −0.25 % (≈ −62/N² %; docs/validation.md M2). This chain
  // (bars carrying their own distributed mass and rotary inertia, root spring 2EI/a, the
  // model the issue specifies) gives −2.79 %, −0.71 %, −0.18 % (≈ −45.8/N² %); masses lumped at the
  // joints instead give −4.9 %, −1.3 %, −0.33 %, a point mass at each bar's centre
  // −1.7 %, −0.42 %, −0.10 %: the quoted figures belong to none of these lumpings, so
  // they are reported beside ours (docs/multibody.md) rather than asserted. Asserted:
  // convergence from below, of second order (error ratio 4 per halving, ± 0.3 for the
  // O(1/N⁴) remainder), and errors no larger than the quoted ones.
  const double quoted[3] = {-3.9, -1.0, -0.25};  // [%], the quoted figures (validation.md M2)
  double err[3];
  for (int c = 0; c < 3; ++c) {
    const double w = chain_first_bending(make_uniform_cantilever_chain(L, EI, GJ, m, ia, counts[c]));
    err[c] = 100.0 * (w / w_beam - 1.0);
    std::printf("[hencky] %2d bodies: first bending error %+.3f %% (quoted %+.2f %%)\n",
                counts[c], err[c], quoted[c]);
    RecordProperty("first_mode_error_percent_" + std::to_string(counts[c]), std::to_string(err[c]));
    EXPECT_LT(err[c], 0.0);
    EXPECT_LE(std::abs(err[c]), std::abs(quoted[c]));
  }
  EXPECT_NEAR(err[0] / err[1], 4.0, 0.3);
  EXPECT_NEAR(err[1] / err[2], 4.0, 0.3);
}

// The quoted figures (docs/validation.md M2, no published source found) are those of a
// chain whose bars have rotary inertia m'a³/6 about
// their centre in bending: the mean of the consistent rigid-bar mass matrix (m'a³/12,
// flapsim's model, above) and the mass lumped at the bar ends (m'a³/4). An independent
// eigen-analysis of that lumping (a dense problem in absolute bar angles, by hand)
// gives −3.882 %, −1.006 %, −0.254 %. Built with our chain code and that inertia, the
// chain must reproduce the quoted figures within ± 0.2 %: a check of the chain's mass and
// stiffness assembly against the reference figures with their lumping stated, not a
// change of the model flapsim uses.
TEST(HenckyCantilever, ReproducesTheQuotedFiguresWithTheirBarInertia) {
  const double L = 0.05, EI = 2e-5, GJ = 1e-5, m = 1e-3, ia = 1e-9;
  const double beta = 1.87510407;  // Euler–Bernoulli cantilever, first mode
  const double w_beam = beta * beta * std::sqrt(EI / (m * std::pow(L, 4)));
  const int counts[3] = {4, 8, 16};
  const double quoted[3] = {-3.9, -1.0, -0.25};  // [%], the quoted figures, each ± 0.2 %
  for (int c = 0; c < 3; ++c) {
    ChainModel model = make_uniform_cantilever_chain(L, EI, GJ, m, ia, counts[c]);
    for (ChainBody& body : model.bodies) {
      // Bending about the body x axis: rotary inertia m'a³/6 about the centre.
      body.inertia(0, 0) = body.mass * body.length * body.length / 6.0;
      body.inertia(2, 2) = body.inertia(0, 0) + body.inertia(1, 1);  // thin bar: I_z = I_x + I_y
    }
    const double err = 100.0 * (chain_first_bending(model) / w_beam - 1.0);
    EXPECT_NEAR(err, quoted[c], 0.2) << counts[c] << " bodies";
  }
}

}  // namespace
}  // namespace flapsim::mbd
