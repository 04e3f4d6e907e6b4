// Wing-base kinematics against the rotation-phase paper (eqs. 7 and 8) and the
// frame conventions of docs/kinematics.md:
//   R_GW = R_GS · Rz(φ) · Rx(θ) · Ry(−α), chord x_W = cosα·x' + sinα·z_S,
//   angle of attack α on the downstroke and 180° − α on the upstroke.

#include "mbd/angle_units.hpp"
#include "mbd/wing_kinematics.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <functional>
#include <numbers>

using flapsim::mbd::BasePose;
using flapsim::mbd::PeriodicSignal;
using flapsim::mbd::WingKinematics;
using flapsim::mbd::rotation_x;
using flapsim::mbd::rotation_y;
using flapsim::mbd::rotation_z;

namespace {

constexpr double kPi = std::numbers::pi;
using flapsim::kDegToRad;

// Rotation-phase paper, eq. 8 (f = 26.1 Hz):
//   φ = 10° + 50° cos(2π(ft + δψ)),  α = 90° − 45° sin(2πft).
WingKinematics eq8(double rotation_phase) {
  WingKinematics k;
  k.frequency = 26.1;
  k.sweep = PeriodicSignal::harmonic(10 * kDegToRad, {50 * kDegToRad}, {});
  k.rotation = PeriodicSignal::harmonic(90 * kDegToRad, {}, {-45 * kDegToRad});
  k.rotation_phase = rotation_phase;
  return k;
}

// Rotation-phase paper, eq. 7 (Lua et al.'s kinematics) with α measured from the
// stroke plane: φ = 60° cos 2πft, α = 90° − 60° sin 2πft. f is not given with eq. 7;
// any value will do for angles.
WingKinematics eq7() {
  WingKinematics k;
  k.frequency = 26.0;
  k.sweep = PeriodicSignal::harmonic(0.0, {60 * kDegToRad}, {});
  k.rotation = PeriodicSignal::harmonic(90 * kDegToRad, {}, {-60 * kDegToRad});
  return k;
}

struct AttackState {
  double angle_of_attack;  // [rad] angle between chord (toward the leading edge) and the velocity
  double lead;             // x_W · v [m/s]: > 0 when the leading edge leads
  double chord_up;         // x_W · z_G: > 0 when the leading edge is above the trailing edge
  double sweep_rate;       // φ̇ [rad/s]
};

// Geometric angle of attack of the blade element at radius r on the span axis,
// from the pose alone: the element moves with v = ω × (r y_W) (pivot fixed).
AttackState attack_at(const WingKinematics& k, double t, double r = 0.03) {
  const BasePose p = k.pose(t);
  const Eigen::Vector3d x_W = p.rotation.col(0), y_W = p.rotation.col(1);
  const Eigen::Vector3d v = p.angular_velocity.cross(r * y_W);
  AttackState s;
  s.angle_of_attack = std::acos(std::clamp(x_W.dot(v.normalized()), -1.0, 1.0));
  s.lead = x_W.dot(v);
  s.chord_up = x_W.z();
  s.sweep_rate = k.angles(t).sweep.rate;
  return s;
}

// Root of g in [a, b] by bisection (g(a), g(b) of opposite sign).
double bisect(const std::function<double(double)>& g, double a, double b) {
  double ga = g(a);
  for (int i = 0; i < 200 && b - a > 1e-15; ++i) {
    const double m = 0.5 * (a + b), gm = g(m);
    if ((gm < 0) == (ga < 0)) {
      a = m;
      ga = gm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

TEST(KinematicsConventions, ElementaryRotationsAreRightHanded) {
  // Right-hand rule: a quarter turn about z takes x to y, about x takes y to z,
  // about y takes z to x.
  const Eigen::Vector3d ex = Eigen::Vector3d::UnitX(), ey = Eigen::Vector3d::UnitY(),
                        ez = Eigen::Vector3d::UnitZ();
  EXPECT_TRUE((rotation_z(kPi / 2) * ex).isApprox(ey, 1e-15));
  EXPECT_TRUE((rotation_x(kPi / 2) * ey).isApprox(ez, 1e-15));
  EXPECT_TRUE((rotation_y(kPi / 2) * ez).isApprox(ex, 1e-15));
  // Independent construction: Eigen's AngleAxis.
  for (double a : {-2.0, 0.3, 1.1}) {
    EXPECT_TRUE(rotation_x(a).isApprox(Eigen::AngleAxisd(a, ex).toRotationMatrix(), 1e-15));
    EXPECT_TRUE(rotation_y(a).isApprox(Eigen::AngleAxisd(a, ey).toRotationMatrix(), 1e-15));
    EXPECT_TRUE(rotation_z(a).isApprox(Eigen::AngleAxisd(a, ez).toRotationMatrix(), 1e-15));
  }
}

TEST(KinematicsConventions, FrameAxesFollowTheConventions) {
  // docs/kinematics.md: chord x_W = cosα·x' + sinα·z_S; θ > 0 lifts the span out of the
  // stroke plane (toward +z_S); the sweep turns the span about z_S.
  WingKinematics k;
  k.frequency = 1.0;
  const double phi = 0.4, theta = 0.2, alpha = 1.1;
  k.sweep = PeriodicSignal::harmonic(phi, {}, {});
  k.deviation = PeriodicSignal::harmonic(theta, {}, {});
  k.rotation = PeriodicSignal::harmonic(alpha, {}, {});
  const Eigen::Matrix3d R = k.pose(0.0).rotation;
  const Eigen::Vector3d x_swept = rotation_z(phi) * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d span(-std::sin(phi) * std::cos(theta), std::cos(phi) * std::cos(theta), std::sin(theta));
  EXPECT_TRUE(R.col(1).isApprox(span, 1e-14));
  EXPECT_GT(R.col(1).z(), 0.0);
  // With θ = 0 the chord formula holds exactly.
  k.deviation = PeriodicSignal();
  const Eigen::Matrix3d R0 = k.pose(0.0).rotation;
  EXPECT_TRUE(R0.col(0).isApprox(std::cos(alpha) * x_swept + std::sin(alpha) * Eigen::Vector3d::UnitZ(), 1e-14));
  EXPECT_TRUE(R0.col(2).isApprox(R0.col(0).cross(R0.col(1)), 1e-14));  // z_W = x_W × y_W
  // α = 90°: chord normal to the stroke plane, leading edge up.
  k.rotation = PeriodicSignal::harmonic(kPi / 2, {}, {});
  k.sweep = PeriodicSignal();
  EXPECT_TRUE(k.pose(0.0).rotation.col(0).isApprox(Eigen::Vector3d::UnitZ(), 1e-14));
}

TEST(KinematicsConventions, StrokePlaneTiltIsRotationAboutGroundY) {
  // R_GS = Ry(β): the stroke-plane normal z_S = (sin β, 0, cos β) in G.
  WingKinematics k;
  k.frequency = 1.0;
  k.stroke_plane_angle = 0.35;
  k.rotation = PeriodicSignal::harmonic(kPi / 2, {}, {});  // chord along z_S
  const Eigen::Matrix3d R = k.pose(0.0).rotation;
  EXPECT_TRUE(R.col(0).isApprox(Eigen::Vector3d(std::sin(0.35), 0.0, std::cos(0.35)), 1e-14));
}

TEST(KinematicsConventions, Eq8RotationIsAt90DegreesAtStrokeReversal) {
  // Rotation-phase paper, eq. 8 and Fig. 10, δψ = 0: the sweep is extremal
  // (φ = 60° at t = 0, −40° at T/2, φ̇ = 0) exactly when α = 90°.
  const WingKinematics k = eq8(0.0);
  const double T = 1.0 / k.frequency;
  for (double t : {0.0, 0.5 * T, T}) {
    const auto a = k.angles(t);
    EXPECT_NEAR(a.rotation.value, 90 * kDegToRad, 1e-12) << "t/T = " << t / T;
    EXPECT_NEAR(a.sweep.rate, 0.0, 1e-9) << "t/T = " << t / T;
  }
  EXPECT_NEAR(k.angles(0.0).sweep.value, 60 * kDegToRad, 1e-12);
  EXPECT_NEAR(k.angles(0.5 * T).sweep.value, -40 * kDegToRad, 1e-12);
  EXPECT_LT(k.angles(0.0).sweep.acceleration, 0.0);     // a maximum
  EXPECT_GT(k.angles(0.5 * T).sweep.acceleration, 0.0);  // a minimum
}

TEST(KinematicsConventions, Eq8AngleOfAttackIs45DegreesMidstrokeLeadingEdgeFirst) {
  // Eq. 8: α(T/4) = 45°, α(3T/4) = 135°. Downstroke (φ̇ < 0): angle of attack α = 45°;
  // upstroke: 180° − α = 45°. Measured here from the pose, as the angle between the
  // chord and the velocity of a point on the span axis, for two radii.
  const WingKinematics k = eq8(0.0);
  const double T = 1.0 / k.frequency;
  for (double r : {0.01, 0.0483}) {
    const AttackState down = attack_at(k, 0.25 * T, r), up = attack_at(k, 0.75 * T, r);
    EXPECT_LT(down.sweep_rate, 0.0);
    EXPECT_GT(up.sweep_rate, 0.0);
    EXPECT_NEAR(down.angle_of_attack / kDegToRad, 45.0, 1e-9);
    EXPECT_NEAR(up.angle_of_attack / kDegToRad, 45.0, 1e-9);
    EXPECT_GT(down.lead, 0.0);  // leading edge leads on the downstroke …
    EXPECT_GT(up.lead, 0.0);    // … and on the upstroke
    EXPECT_GT(down.chord_up, 0.0);  // leading edge pitched up on both: lift is +z
    EXPECT_GT(up.chord_up, 0.0);
  }
}

TEST(KinematicsConventions, Eq7AngleOfAttackIs30DegreesMidstroke) {
  // Eq. 7 in our convention: α = 90° − 60° sin 2πft -> α(T/4) = 30°, α(3T/4) = 150°:
  // angle of attack 30° on both half-strokes (90° − 60°).
  const WingKinematics k = eq7();
  const double T = 1.0 / k.frequency;
  const AttackState down = attack_at(k, 0.25 * T), up = attack_at(k, 0.75 * T);
  EXPECT_NEAR(k.angles(0.25 * T).rotation.value / kDegToRad, 30.0, 1e-12);
  EXPECT_NEAR(down.angle_of_attack / kDegToRad, 30.0, 1e-9);
  EXPECT_NEAR(up.angle_of_attack / kDegToRad, 30.0, 1e-9);
  EXPECT_GT(down.lead, 0.0);
  EXPECT_GT(up.lead, 0.0);
}

TEST(KinematicsConventions, NegativeRotationPhaseAdvancesRotationByThatFraction) {
  // Rotation-phase paper: δψ < 0 is an advanced rotation, the wing flips (α = 90°)
  // before the sweep reverses (φ extremal), by δψ of a period. With δψ = −0.1:
  // α = 90° at t = 0, the sweep maximum at t = 0.1 T; found here numerically.
  for (double dpsi : {-0.1, 0.05}) {
    const WingKinematics k = eq8(dpsi);
    const double T = 1.0 / k.frequency;
    const double t_flip = bisect([&](double t) { return k.angles(t).rotation.value - kPi / 2; }, -0.2 * T, 0.2 * T);
    const double t_reversal = bisect([&](double t) { return k.angles(t).sweep.rate; }, -0.24 * T, 0.24 * T);
    EXPECT_GT(k.angles(t_reversal).sweep.value, 59.9 * kDegToRad);  // the maximum, φ = 60°
    EXPECT_NEAR((t_reversal - t_flip) / T, -dpsi, 1e-9) << "δψ = " << dpsi;
  }
}

TEST(KinematicsConventions, RotationPhaseShiftsSweepAndDeviationNotRotation) {
  // φ(t) = φ_signal(f t + δψ), θ likewise, α(t) = α_signal(f t).
  WingKinematics k = eq8(0.0);
  k.deviation = PeriodicSignal::harmonic(0.0, {0.0, 10 * kDegToRad}, {});
  WingKinematics shifted = k;
  shifted.rotation_phase = 0.13;
  const double t = 0.0071;
  const double s = k.frequency * t;
  EXPECT_NEAR(shifted.angles(t).sweep.value, k.sweep.at_phase(s + 0.13).value, 1e-14);
  EXPECT_NEAR(shifted.angles(t).deviation.value, k.deviation.at_phase(s + 0.13).value, 1e-14);
  EXPECT_NEAR(shifted.angles(t).rotation.value, k.rotation.at_phase(s).value, 1e-14);
  // Rates per second = f · (per cycle).
  EXPECT_NEAR(shifted.angles(t).sweep.rate, k.frequency * k.sweep.at_phase(s + 0.13).rate, 1e-10);
  EXPECT_NEAR(shifted.angles(t).sweep.acceleration,
              k.frequency * k.frequency * k.sweep.at_phase(s + 0.13).acceleration, 1e-6);
}

TEST(KinematicsConventions, OrientationIsARotation) {
  WingKinematics k = eq8(-0.07);
  k.deviation = PeriodicSignal::harmonic(0.0, {0.0, 10 * kDegToRad}, {});
  k.stroke_plane_angle = 0.2;
  for (int i = 0; i < 50; ++i) {
    const Eigen::Matrix3d R = k.pose(i * 0.00137).rotation;
    EXPECT_TRUE((R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-14));
    EXPECT_NEAR(R.determinant(), 1.0, 1e-14);
  }
}

TEST(KinematicsConventions, StrokeAnglesInvertTheStrokeRotation) {
  // R_GW = R_GS · stroke_rotation(φ, θ, α) with R_GS = Ry(β); stroke_angles must return
  // the kinematics' own angles from R_GSᵀ R_GW, and stroke_rotation must equal the same
  // product built independently from angle-axis rotations.
  WingKinematics k = eq8(-0.1);
  k.deviation = PeriodicSignal::harmonic(0.0, {}, {8.0 * kDegToRad});
  k.stroke_plane_angle = 0.2;
  for (double t : {0.0, 0.003, 0.011, 0.025, 0.037}) {
    const auto a = k.angles(t);
    const Eigen::Matrix3d r_sw = rotation_y(k.stroke_plane_angle).transpose() * k.pose(t).rotation;
    const flapsim::mbd::StrokeAngles e = flapsim::mbd::stroke_angles(r_sw);
    EXPECT_NEAR(e.sweep, a.sweep.value, 1e-12);
    EXPECT_NEAR(e.deviation, a.deviation.value, 1e-12);
    EXPECT_NEAR(e.rotation, a.rotation.value, 1e-12);
    const Eigen::Matrix3d by_axes = (Eigen::AngleAxisd(e.sweep, Eigen::Vector3d::UnitZ()) *
                                     Eigen::AngleAxisd(e.deviation, Eigen::Vector3d::UnitX()) *
                                     Eigen::AngleAxisd(-e.rotation, Eigen::Vector3d::UnitY()))
                                        .toRotationMatrix();
    EXPECT_LT((flapsim::mbd::stroke_rotation(e) - by_axes).norm(), 1e-14);
    EXPECT_LT((flapsim::mbd::stroke_rotation(e) - r_sw).norm(), 1e-14);
  }
}

TEST(KinematicsConventions, BaseMotionIsThePose) {
  const WingKinematics k = eq8(0.05);
  const auto motion = flapsim::mbd::make_base_motion(k);
  const BasePose a = motion(0.0123), b = k.pose(0.0123);
  EXPECT_EQ(a.rotation, b.rotation);
  EXPECT_EQ(a.angular_velocity, b.angular_velocity);
  EXPECT_EQ(a.angular_acceleration, b.angular_acceleration);
}
