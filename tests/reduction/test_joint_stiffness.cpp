// The joint stiffness by reciprocity (docs/reduction.md, "Joint stiffness by
// reciprocity"; issue 17): K = (D C_rr Dᵀ)⁻¹ from the station compliance C = Aᵀ K_FEM⁻¹ A.
// Checked here: K is symmetric positive definite for every shipped wing and chain size,
// including the film-like thin-membrane hawkmoth and the robofly whose clamp covers
// several bodies; and the chain's static joint angles under every unit joint load equal
// the relative station rotations of the FEM under the same load to round-off.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "fem/wing_fem.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/linear_chain.hpp"
#include "wings/wing_file.hpp"

namespace flapsim::reduction {
namespace {

struct ReducedWing {
  fem::WingFem fem;
  std::unique_ptr<ClampedWingAnalysis> analysis;
};

std::unique_ptr<ReducedWing> reduce_wing(const std::string& file) {
  auto w = std::make_unique<ReducedWing>(ReducedWing{
      fem::build_wing_fem(wings::load_wing_file(std::string(FLAPSIM_SOURCE_DIR) + "/wings/" + file)), nullptr});
  w->analysis = std::make_unique<ClampedWingAnalysis>(w->fem.model.mesh, w->fem.system, w->fem.root_clamp);
  return w;
}

// Symmetric to round-off and every eigenvalue positive.
void expect_spd(const Eigen::MatrixXd& k, const std::string& what) {
  const double scale = k.cwiseAbs().maxCoeff();
  EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale) << what;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(k, Eigen::EigenvaluesOnly);
  EXPECT_GT(es.eigenvalues()(0), 0.0) << what;
  std::printf("%s: K %dx%d, eigenvalues %.3e ... %.3e N m/rad\n", what.c_str(), static_cast<int>(k.rows()),
              static_cast<int>(k.cols()), es.eigenvalues()(0), es.eigenvalues()(k.rows() - 1));
}

class JointStiffnessOfShippedWings : public ::testing::TestWithParam<const char*> {};

// Issue 17, done when: the robofly, the thin-membrane hawkmoth, the calibrated hawkmoth
// (and the MAV film wing, tests/reduction/test_mav_film_wing.cpp) reduce for 4, 8, 10
// and 16 bodies with K symmetric positive definite.
TEST_P(JointStiffnessOfShippedWings, ReducesWithPositiveDefiniteStiffnessForFourToSixteenBodies) {
  const auto w = reduce_wing(GetParam());
  for (int nb : {4, 8, 10, 16}) {
    const LumpedChain lc = lump_into_chain(*w->analysis, nb);
    ASSERT_EQ(lc.chain.stiffness_matrix.rows(), lc.chain.num_dofs());
    expect_spd(lc.chain.stiffness_matrix, std::string(GetParam()) + " N_b=" + std::to_string(nb) + " (" +
                                             std::to_string(lc.chain.first_jointed_body()) + " welded)");
    EXPECT_NEAR(lc.chain.total_mass(), lc.fem_mass, 1e-12 * lc.fem_mass);
  }
}

INSTANTIATE_TEST_SUITE_P(Wings, JointStiffnessOfShippedWings,
                         ::testing::Values("robofly.toml", "hawkmoth_thin_membrane.toml", "hawkmoth.toml"),
                         [](const auto& info) {
                           std::string n = info.param;
                           return n.substr(0, n.find('.'));
                         });

// The chain's static joint angles q = K⁻¹ Q against the FEM: the joint load Q spread on
// the stations (the moment pair Dᵀ Q on the two bodies of the joint), applied to the FEM
// through A, solved with the FEM's own factorisation, its motion averaged by Aᵀ into
// station rotations r, and Φ_FEM = D r. Exact by construction (K⁻¹ = D C_rr Dᵀ), so
// any error in A, C, D or the chain's generalized forces shows here.
void expect_static_exactness(const ClampedWingAnalysis& an, int nb) {
  const LumpedChain lc = lump_into_chain(an, nb);
  const LinearChain lin(lc.chain);
  const int n = lc.chain.num_dofs(), ns = lc.stations.size();
  const int ndof = static_cast<int>(an.nodes().cols()) * fem::kDofsPerNode;
  const Eigen::MatrixXd& d = lc.joint_stiffness.difference;
  auto fem_joint_angles = [&](const Eigen::VectorXd& station_moments) {  // [θ, φ] per station
    Eigen::VectorXd g = Eigen::VectorXd::Zero(3 * ns);
    for (int k = 0; k < ns; ++k) g.segment<2>(3 * k + 1) = station_moments.segment<2>(2 * k);
    const Eigen::VectorXd x = an.solve(lc.stations.load_vector(g, ndof));
    const Eigen::VectorXd u = lc.stations.station_motion(x);
    Eigen::VectorXd r(2 * ns);
    for (int k = 0; k < ns; ++k) r.segment<2>(2 * k) = u.segment<2>(3 * k + 1);
    return Eigen::VectorXd(d * r);
  };
  double worst = 0.0;
  for (int j = 0; j < n; ++j) {  // a bending moment or a torque at every joint
    const Eigen::VectorXd q_unit = Eigen::VectorXd::Unit(n, j);
    const Eigen::VectorXd q_chain = lin.static_response(q_unit);
    const Eigen::VectorXd q_fem = fem_joint_angles(d.transpose() * q_unit);
    worst = std::max(worst, (q_chain - q_fem).norm() / q_fem.norm());
  }
  // A torque at the tip station: the moment on the last body.
  const int last = lc.chain.num_bodies() - 1;
  const Eigen::VectorXd q_tip = lin.static_response(
      lin.generalized_force(last, lin.joint_position(last), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY()));
  Eigen::VectorXd tip_torque = Eigen::VectorXd::Zero(2 * ns);
  tip_torque[2 * ns - 1] = 1.0;
  const Eigen::VectorXd q_tip_fem = fem_joint_angles(tip_torque);
  worst = std::max(worst, (q_tip - q_tip_fem).norm() / q_tip_fem.norm());
  std::printf("N_b=%d: largest relative difference chain vs FEM joint angles under unit loads %.2e\n", nb, worst);
  // Issue 17: within 1e-8 relative.
  EXPECT_LT(worst, 1e-8) << nb;
}

TEST(JointStiffness, StaticJointAnglesEqualFemStationRotationsUnderEveryUnitJointLoad) {
  const auto w = reduce_wing("hawkmoth_thin_membrane.toml");
  for (int nb : {4, 10}) expect_static_exactness(*w->analysis, nb);
}

}  // namespace
}  // namespace flapsim::reduction
