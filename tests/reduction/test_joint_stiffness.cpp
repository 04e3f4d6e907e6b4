// The joint stiffness by reciprocity (docs/reduction.md, "Joint stiffness by
// reciprocity"; issue 17): K = (T C Tᵀ)⁻¹ (T: chord slopes and twist differences) from the station compliance C = Aᵀ K_FEM⁻¹ A.
// Checked here: K is symmetric positive definite for every shipped wing and chain size,
// including the film-like thin-membrane hawkmoth and the robofly whose clamp covers
// several bodies; and the chain's static joint angles under every unit joint load equal
// the FEM's T u (chord slopes, twist differences) under the same load to round-off.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "fem/wing_fem.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/linear_chain.hpp"
#include "wings/loader/wing_file.hpp"

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
// the stations (Tᵀ Q: three transverse forces at the joint stations for a bending moment,
// a pair of torques at the mid-span stations for a joint torque), applied to the FEM
// through A, solved with the FEM's own factorisation, its motion averaged by Aᵀ into the
// stations' motion u, and Φ_FEM = T u (joint_stiffness.hpp). Exact by construction
// (K⁻¹ = T C Tᵀ), so any error in A, C, T or the chain's generalized forces shows here.
void expect_static_exactness(const ClampedWingAnalysis& an, int nb) {
  const LumpedChain lc = lump_into_chain(an, nb);
  const LinearChain lin(lc.chain);
  const int n = lc.chain.num_dofs(), ns = lc.stations.size();
  const int ndof = static_cast<int>(an.nodes().cols()) * fem::kDofsPerNode;
  const JointStiffness& js = lc.joint_stiffness;
  auto fem_joint_angles = [&](const Eigen::VectorXd& station_loads) {  // (F, M_n, M_s) per station
    const Eigen::VectorXd x = an.solve(lc.stations.load_vector(station_loads, ndof));
    return js.joint_angles(lc.stations.station_motion(x));
  };
  auto relative = [](const Eigen::VectorXd& chain, const Eigen::VectorXd& fem) {
    return (chain - fem).norm() / fem.norm();
  };
  double worst = 0.0;
  for (int j = 0; j < n; ++j) {  // a bending moment or a torque at every joint
    const Eigen::VectorXd q_unit = Eigen::VectorXd::Unit(n, j);
    worst = std::max(worst, relative(lin.static_response(q_unit), fem_joint_angles(js.station_loads(q_unit))));
  }
  // A transverse force and a torque at the tip: on the last body at the chain's tip (its
  // outboard joint, the last station) — the FEM gets the same force (torque) on that
  // station (the torque on the last body's mid-span station: a torque's generalized force
  // does not depend on where on the body it acts).
  const int last = lc.chain.num_bodies() - 1;
  const Eigen::Vector3d tip = lin.joint_position(last) + lc.chain.bodies.back().outboard_joint;
  const Eigen::VectorXd q_force = lin.static_response(
      lin.generalized_force(last, tip, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Zero()));
  const Eigen::VectorXd q_torque = lin.static_response(
      lin.generalized_force(last, tip, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY()));
  Eigen::VectorXd tip_force = Eigen::VectorXd::Zero(3 * ns), tip_torque = Eigen::VectorXd::Zero(3 * ns);
  tip_force[3 * (ns - 1)] = 1.0;       // w of the last (outboard-joint) station
  tip_torque[3 * (ns - 2) + 2] = 1.0;  // φ of the last mid-span station
  const double force_error = relative(q_force, fem_joint_angles(tip_force));
  worst = std::max(worst, relative(q_torque, fem_joint_angles(tip_torque)));
  std::printf("N_b=%d: largest relative difference chain vs FEM joint angles: unit joint loads and tip torque "
              "%.2e, tip force %.2e\n", nb, worst, force_error);
  // Issue 17: within 1e-8 relative.
  EXPECT_LT(worst, 1e-8) << nb;
  EXPECT_LT(force_error, 1e-8) << nb;
}

TEST(JointStiffness, StaticJointAnglesEqualFemStationRotationsUnderEveryUnitJointLoad) {
  const auto w = reduce_wing("hawkmoth_thin_membrane.toml");
  for (int nb : {4, 10}) expect_static_exactness(*w->analysis, nb);
}

}  // namespace
}  // namespace flapsim::reduction
