// The rotation-phase paper's 3-body validation system (Table 1, base motion eq. 5,
// forces eq. 6, f = 26 Hz) integrated by flapsim and by Simbody, an independent
// multibody engine (as the paper checked its code against MSC Adams). The trajectory
// of point A (tip of body 3) must agree within 0.5 % of its amplitude over 3 cycles.

#include "chain_test_models.hpp"
#include "three_body_trajectory.hpp"

#include "mbd/angle_units.hpp"
#include "mbd/chain_data.hpp"
#include "mbd/chain_kinematics.hpp"
#include "mbd/generalized_alpha.hpp"

#include <gtest/gtest.h>

#include <Simbody.h>

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <cmath>
#include <vector>

namespace flapsim::mbd {
namespace {

using test::kPi;
using test::kThreeBodyFrequency;

// Eq. 6 applied at a station of a Simbody body, ground components.
class EqSixForce : public SimTK::Force::Custom::Implementation {
 public:
  EqSixForce(const SimTK::MobilizedBody& body, SimTK::Vec3 station)
      : body_(body), station_(station) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
    const double w = 2.0 * kPi * kThreeBodyFrequency, t = s.getTime();
    body_.applyForceToBodyPoint(s, station_,
                                SimTK::Vec3(0.02 * std::sin(w * t), 0.0, 0.04 * std::cos(w * t)),
                                body_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0.0; }

 private:
  const SimTK::MobilizedBody& body_;
  SimTK::Vec3 station_;
};

// A full joint stiffness and damping over the mobilities of the chain's joints:
// mobility forces −K (q − q_rest) − C u, energy ½ (q − q_rest)ᵀ K (q − q_rest).
class CoupledJointForce : public SimTK::Force::Custom::Implementation {
 public:
  CoupledJointForce(std::vector<const SimTK::MobilizedBody*> joints, Eigen::MatrixXd k, Eigen::MatrixXd c,
                    Eigen::VectorXd rest)
      : joints_(std::move(joints)), k_(std::move(k)), c_(std::move(c)), rest_(std::move(rest)) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobility_forces) const override {
    Eigen::VectorXd q, u;
    read(s, q, u);
    const Eigen::VectorXd f = -k_ * (q - rest_) - c_ * u;
    for (std::size_t j = 0; j < joints_.size(); ++j)
      for (int i = 0; i < 2; ++i)
        joints_[j]->applyOneMobilityForce(s, SimTK::MobilizerUIndex(i), f(2 * static_cast<int>(j) + i),
                                          mobility_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    Eigen::VectorXd q, u;
    read(s, q, u);
    return 0.5 * (q - rest_).dot(k_ * (q - rest_));
  }

 private:
  void read(const SimTK::State& s, Eigen::VectorXd& q, Eigen::VectorXd& u) const {
    const int n = 2 * static_cast<int>(joints_.size());
    q.resize(n);
    u.resize(n);
    for (std::size_t j = 0; j < joints_.size(); ++j)
      for (int i = 0; i < 2; ++i) {
        q(2 * static_cast<int>(j) + i) = joints_[j]->getOneQ(s, i);
        u(2 * static_cast<int>(j) + i) = joints_[j]->getOneU(s, i);
      }
  }
  std::vector<const SimTK::MobilizedBody*> joints_;
  Eigen::MatrixXd k_, c_;
  Eigen::VectorXd rest_;
};

SimTK::Body::Rigid simbody_body(const ChainBody& b) {
  const Eigen::Vector3d c = b.center_of_mass;
  const Eigen::Matrix3d& I = b.inertia;
  // Simbody wants the inertia about the body origin: shift the central tensor.
  const SimTK::Inertia central(I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2));
  const SimTK::Vec3 com(c.x(), c.y(), c.z());
  return SimTK::Body::Rigid(
      SimTK::MassProperties(b.mass, com, central.shiftFromMassCenter(-com, b.mass)));
}



// Same chain in Simbody: the base as three Pin mobilizers z, x, y (R = Rz(φ) Rx(θ)
// Ry(−α)) with Motion::Sinusoid each, body 1 on the last of them; joints 2, 3 as
// Universal mobilizers (x, then the new y: exactly Rx(θ) Ry(α)); MobilityLinearSpring
// and MobilityLinearDamper per coordinate; eq. 6 as a custom force.
test::Trajectory run_simbody(const ChainModel& model, double t_end, int samples) {
  using namespace SimTK;
  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  const double w = 2.0 * kPi * kThreeBodyFrequency;
  const Body::Rigid carrier(MassProperties(1.0, Vec3(0), Inertia(1.0)));  // motion prescribed
  const Rotation z_to_x(Pi / 2, YAxis), z_to_y(-Pi / 2, XAxis);

  MobilizedBody::Pin sweep(matter.Ground(), Transform(), carrier, Transform());
  Motion::Sinusoid(sweep, Motion::Position, 60 * kDegToRad, w, Pi / 2);  // φ = 60° cos ωt
  MobilizedBody::Pin deviation(sweep, Transform(z_to_x), carrier, Transform(z_to_x));
  Motion::Sinusoid(deviation, Motion::Position, 10 * kDegToRad, 2 * w, Pi / 2);  // θ = 10° cos 2ωt
  // Ry(−α) = Ry(−90°) · Ry(60° sin ωt): the constant part in the inboard frame.
  MobilizedBody::Pin body1(deviation, Transform(Rotation(-Pi / 2, YAxis) * z_to_y),
                           simbody_body(model.bodies[0]), Transform(z_to_y));
  Motion::Sinusoid(body1, Motion::Position, 60 * kDegToRad, w, 0.0);

  std::vector<MobilizedBody::Universal> joints;
  joints.reserve(2);  // the custom force keeps pointers to them
  MobilizedBody* parent = &body1;
  for (int i = 1; i < 3; ++i) {
    const Eigen::Vector3d o = model.bodies[i - 1].outboard_joint;
    joints.emplace_back(*parent, Transform(Vec3(o.x(), o.y(), o.z())), simbody_body(model.bodies[i]),
                        Transform());
    const ChainJoint& j = model.joints[i];
    if (model.stiffness_matrix.size() == 0) {
      Force::MobilityLinearSpring(forces, joints.back(), MobilizerQIndex(0), j.bend_stiffness, j.bend_rest);
      Force::MobilityLinearSpring(forces, joints.back(), MobilizerQIndex(1), j.twist_stiffness, j.twist_rest);
      Force::MobilityLinearDamper(forces, joints.back(), MobilizerUIndex(0), j.bend_damping);
      Force::MobilityLinearDamper(forces, joints.back(), MobilizerUIndex(1), j.twist_damping);
    }
    parent = &joints.back();
  }
  if (model.stiffness_matrix.size() > 0)  // a full K and C: one custom force over all joints
    Force::Custom(forces, new CoupledJointForce({&joints[0], &joints[1]}, model.stiffness(), model.damping(),
                                                model.rest_angles()));
  const MobilizedBody::Universal& body2 = joints[0];
  const MobilizedBody::Universal& body3 = joints[1];
  Force::Custom(forces, new EqSixForce(body2, Vec3(0, model.bodies[1].length, 0)));

  system.realizeTopology();
  State state = system.getDefaultState();
  state.setTime(0.0);
  RungeKuttaMersonIntegrator integ(system);
  integ.setAccuracy(1e-10);
  integ.initialize(state);
  test::Trajectory out;
  const Vec3 tip(0, model.bodies[2].length, 0);
  for (int k = 0; k <= samples; ++k) {
    const double t = t_end * k / samples;
    if (k > 0) integ.stepTo(t);
    const State& s = integ.getState();
    system.realize(s, Stage::Position);
    const Vec3 a = body3.findStationLocationInGround(s, tip);
    out.t.push_back(t);
    out.a.emplace_back(a[0], a[1], a[2]);
    out.q.emplace_back(body2.getOneQ(s, 0), body2.getOneQ(s, 1), body3.getOneQ(s, 0), body3.getOneQ(s, 1));
  }
  return out;
}

constexpr int kSamples = 600;  // over 3 cycles

// The Simbody reference, computed once for the tests of this file.
const test::Trajectory& simbody_reference() {
  static const test::Trajectory ref =
      run_simbody(test::three_body_chain(), 3.0 / kThreeBodyFrequency, kSamples);
  return ref;
}

// Amplitude of the motion: half the peak-to-peak range of the largest coordinate.
double amplitude_of(const test::Trajectory& ref) {
  double amplitude = 0.0;
  for (int c = 0; c < 3; ++c) {
    double lo = 1e9, hi = -1e9;
    for (const auto& a : ref.a) {
      lo = std::min(lo, a(c));
      hi = std::max(hi, a(c));
    }
    amplitude = std::max(amplitude, 0.5 * (hi - lo));
  }
  return amplitude;
}

void expect_agreement(const ChainModel& model, const test::Trajectory& ref, const char* label) {
  const double t_end = 3.0 / kThreeBodyFrequency;
  const test::Trajectory ours = test::integrate_three_body(model, t_end, kSamples, 5);  // 1000 steps per cycle
  const double amplitude = amplitude_of(ref);
  double worst = 0.0, worst_t = 0.0;
  for (std::size_t k = 0; k < ref.a.size(); ++k) {
    ASSERT_NEAR(ref.t[k], ours.t[k], 1e-12);
    const double d = (ref.a[k] - ours.a[k]).norm();
    if (d > worst) {
      worst = d;
      worst_t = ref.t[k];
    }
  }
  const double percent = 100.0 * worst / amplitude;
  ::testing::Test::RecordProperty("max_deviation_percent_of_amplitude", std::to_string(percent));
  std::printf("[%s] amplitude of A %.4f mm, max |A_flapsim - A_simbody| %.3e mm "
              "at t = %.4f s = %.4f %% of amplitude\n",
              label, amplitude * 1e3, worst * 1e3, worst_t, percent);
  // Issue 5: within 0.5 % of the motion's amplitude over 3 cycles (the paper's check
  // against MSC Adams, rotation-phase paper §2.3, Fig. 7).
  EXPECT_LT(percent, 0.5);

  // A finer look than the tip position (dominated by the rigid flapping): the joint
  // angles themselves, against their largest excursion (a 5 % change of one spring moves
  // A by only 0.2 % of its amplitude but the angles by several %).
  double q_max = 0.0, q_dev = 0.0;
  for (std::size_t k = 0; k < ref.q.size(); ++k) {
    q_max = std::max(q_max, ref.q[k].cwiseAbs().maxCoeff());
    q_dev = std::max(q_dev, (ref.q[k] - ours.q[k]).cwiseAbs().maxCoeff());
  }
  std::printf("[%s] largest joint angle %.3f deg, max joint-angle deviation %.3e deg "
              "(%.3f %%)\n", label, q_max / kDegToRad, q_dev / kDegToRad, 100.0 * q_dev / q_max);
  EXPECT_LT(q_dev, 0.01 * q_max);
}

TEST(SimbodyThreeBody, TipTrajectoryAgreesWithSimbodyOverThreeCycles) {
  expect_agreement(test::three_body_chain(), simbody_reference(), "three-body");
}

// Issue 17: a full joint stiffness and damping (bend–twist and joint-to-joint coupling),
// as the reduction by reciprocity produces, against Simbody with the same K and C as a
// custom force; the same tolerances as the diagonal chain above.
TEST(SimbodyThreeBody, CoupledStiffnessChainAgreesWithSimbodyOverThreeCycles) {
  const ChainModel model = test::three_body_chain_coupled();
  model.validate();  // K and C symmetric positive semi-definite
  static const test::Trajectory ref = run_simbody(model, 3.0 / kThreeBodyFrequency, kSamples);
  expect_agreement(model, ref, "three-body, coupled K");
}

}  // namespace
}  // namespace flapsim::mbd
