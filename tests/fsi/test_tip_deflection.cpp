// The tip's bend and twist as both structures record them (pipeline/fsi/tip_deflection.hpp,
// docs/fsi.md "The chain against the FEM"): the tip's rotation from rest in the wing frame
// W, split as Rx(bend) Ry(twist), whatever axis a chain's bodies lie along.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

#include "mbd/chain_model.hpp"
#include "mbd/wing_kinematics.hpp"
#include "pipeline/fsi/chain_structure.hpp"
#include "pipeline/fsi/tip_deflection.hpp"

using namespace flapsim;

TEST(TipDeflection, SplitsABendThenATwistIntoTheTwoAngles) {
  // Rx(b) Ry(t) is read back as (b, t) to round-off over the angles a wing meets.
  for (const double b : {-1.2, -0.3, 0.0, 0.05, 0.7, 1.4})
    for (const double t : {-0.9, -0.02, 0.0, 0.4, 1.1}) {
      const Eigen::Matrix3d r = Eigen::AngleAxisd(b, Eigen::Vector3d::UnitX()).toRotationMatrix() *
                                Eigen::AngleAxisd(t, Eigen::Vector3d::UnitY()).toRotationMatrix();
      const fsi::TipDeflection d = fsi::tip_deflection(r);
      EXPECT_NEAR(d.bend, b, 1e-14) << b << " " << t;
      EXPECT_NEAR(d.twist, t, 1e-14) << b << " " << t;
    }
}

TEST(TipDeflection, AChainAlongATiltedAxisIsReadInTheWingFrame) {
  // A chain whose axis lies at ψ = 0.3 rad to y_W, its first joint bent by a small θ about
  // the body's x axis e_n = R_WR x̂ and nothing twisted: the tip turns by the rotation
  // vector θ e_n, whose components along x_W and y_W are its bend and twist in W to O(θ²)
  // (Rx(b) Ry(t) ≈ I + [b x̂ + t ŷ]×). The chain's sum of joint angles read (θ, 0): a twist
  // that the FEM's tip section, read in W, does not have (the 64 % of docs/fsi.md's
  // correction came from this).
  auto model = std::make_shared<fsi::ChainStructureModel>();
  model->chain = mbd::make_uniform_cantilever_chain(0.04, 2e-5, 2e-6, 1e-3, 1e-9, 4);
  const double psi = 0.3;
  model->chain.root_rotation = mbd::rotation_z(psi);
  model->base_motion = [](double) { return mbd::BasePose{}; };
  auto data = model->make_data();
  data->initialize(0.0);
  auto& chain = dynamic_cast<fsi::ChainStructureData&>(*data);
  const double theta = 1e-4;  // [rad]
  chain.state.q = model->chain.rest_angles();
  ASSERT_GE(chain.state.q.size(), 2);
  chain.state.q(0) += theta;
  const Eigen::Vector3d e_n = model->chain.root_rotation.col(0);
  ASSERT_GT(std::abs(e_n.y()), 0.25);  // the tilt gives the bend a twist component
  const fsi::StructureReadout r = chain.readout();
  EXPECT_NEAR(r.tip_bend, theta * e_n.x(), 1e-3 * theta);
  EXPECT_NEAR(r.tip_twist, theta * e_n.y(), 1e-3 * theta);
}
