// The linear quasi-static deflection of a chain under its base's inertial loads
// (mbd/quasi_static_deflection.hpp), against the hand-derived answer for one joint.
//
// Two bodies on a rigid root along y; body 2 (mass m = 1e-4 kg, centre of mass at
// x_c = 2 mm, y_c = 10 mm from its joint, which sits 20 mm from the pivot; I_xx = 1e-9 kg m²)
// hangs on bend and twist springs k = 1e-3 N m/rad.
//  - Pivot accelerated along z by a_z: the inertial force −m a_z ẑ at the centre of mass;
//    ∂r_c/∂θ = x̂ × r = y_c ẑ and ∂r_c/∂α = −x_c ẑ (Ry(α) turns +x toward −z), so
//    k θ = −m y_c a_z and k α = m x_c a_z.
//  - Base turned about x with ω̇ (ω = 0): a_c = ω̇ x̂ × (x_c x̂ + 0.03 ŷ) = 0.03 ω̇ ẑ and the
//    body's angular acceleration ω̇ x̂ (∂ω/∂θ = x̂, ∂ω/∂α = ŷ, I_xy = 0), so
//    k θ = −(I_xx + m y_c · 0.03) ω̇ and k α = m x_c · 0.03 ω̇.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mbd/quasi_static_deflection.hpp"

namespace flapsim::mbd {
namespace {

ChainModel one_joint_chain() {
  ChainModel m;
  ChainBody b1;
  b1.length = 0.02;
  b1.mass = 1e-5;
  b1.center_of_mass = {0, 0.01, 0};
  b1.inertia = Eigen::Vector3d(4e-10, 1e-11, 4e-10).asDiagonal();
  b1.outboard_joint = {0, 0.02, 0};
  ChainBody b2 = b1;
  b2.mass = 1e-4;
  b2.center_of_mass = {0.002, 0.01, 0};
  b2.inertia = Eigen::Vector3d(1e-9, 1e-10, 1e-9).asDiagonal();
  m.bodies = {b1, b2};
  m.joints.resize(2);
  m.joints[1].bend_stiffness = 1e-3;
  m.joints[1].twist_stiffness = 1e-3;
  return m;
}

TEST(QuasiStaticDeflection, PivotAccelerationBendsAndTwistsAsByHand) {
  const double period = 0.05, a0 = 100.0;  // a_z = a0 cos(2π t / T) [m/s²]
  const BaseMotion heave = [&](double t) {
    BasePose p;
    p.acceleration = {0, 0, a0 * std::cos(2 * std::numbers::pi * t / period)};
    return p;
  };
  const QuasiStaticDeflection q = peak_quasi_static_deflection(one_joint_chain(), heave, period, 16);
  EXPECT_NEAR(q.tip_bend, 1e-4 * 0.01 * a0 / 1e-3, 1e-12);   // 0.1 rad
  EXPECT_NEAR(q.tip_twist, 1e-4 * 0.002 * a0 / 1e-3, 1e-12);  // 0.02 rad
  EXPECT_EQ(q.joint, 1);
  EXPECT_FALSE(q.twist);
  EXPECT_NEAR(q.joint_angle, 0.1, 1e-12);
  EXPECT_NEAR(q.time, 0.0, 1e-15);  // |a_z| is largest at t = 0 (and T/2)
}

TEST(QuasiStaticDeflection, AngularAccelerationOfTheBaseLoadsTheJointThroughTheLeverArm) {
  const double wdot = 2000.0;  // [rad/s²], constant; ω = 0
  const BaseMotion turn = [&](double) {
    BasePose p;
    p.angular_acceleration = {wdot, 0, 0};
    return p;
  };
  const QuasiStaticDeflection q = peak_quasi_static_deflection(one_joint_chain(), turn, 0.05, 4);
  EXPECT_NEAR(q.tip_bend, (1e-9 + 1e-4 * 0.01 * 0.03) * wdot / 1e-3, 1e-12);  // 0.062 rad
  EXPECT_NEAR(q.tip_twist, 1e-4 * 0.002 * 0.03 * wdot / 1e-3, 1e-12);         // 0.012 rad
}

TEST(QuasiStaticDeflection, AChainWithoutJointsIsRefused) {
  ChainModel m = one_joint_chain();
  m.bodies.resize(1);
  m.joints.resize(1);
  EXPECT_THROW(peak_quasi_static_deflection(m, [](double) { return BasePose{}; }, 0.05, 4), std::invalid_argument);
}

}  // namespace
}  // namespace flapsim::mbd
