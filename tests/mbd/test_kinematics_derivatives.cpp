// Rates and accelerations of the wing-base kinematics against central finite
// differences: Euler-angle rates (per second), ω from the orientation
// (ω̂ = Ṙ Rᵀ) and ω̇ from ω, for harmonic and tabulated signals with deviation,
// rotation phase and a tilted stroke plane.

#include "mbd/angle_units.hpp"
#include "mbd/wing_kinematics.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <numbers>
#include <vector>

using flapsim::mbd::BasePose;
using flapsim::mbd::PeriodicSignal;
using flapsim::mbd::WingKinematics;

namespace {

constexpr double kPi = std::numbers::pi;
using flapsim::kDegToRad;

// Rotation-phase paper eq. 5 (3-body validation case, 26 Hz) in our convention:
// φ = 60° cos 2πft, α = 90° − 60° sin 2πft, θ = 10° cos 4πft; here with an added
// rotation phase and stroke-plane tilt so every term of ω and ω̇ is exercised.
WingKinematics harmonic_case() {
  WingKinematics k;
  k.frequency = 26.0;
  k.sweep = PeriodicSignal::harmonic(0.0, {60 * kDegToRad}, {});
  k.rotation = PeriodicSignal::harmonic(90 * kDegToRad, {}, {-60 * kDegToRad});
  k.deviation = PeriodicSignal::harmonic(0.0, {0.0, 10 * kDegToRad}, {});
  k.rotation_phase = 0.07;
  k.stroke_plane_angle = 0.3;
  return k;
}

// Same with all three angles tabulated (uneven knots).
WingKinematics tabulated_case() {
  WingKinematics k;
  k.frequency = 26.1;
  k.sweep = PeriodicSignal::tabulated({0.0, 0.12, 0.3, 0.5, 0.64, 0.8},
                                      {1.0, 0.7, -0.2, -0.7, -0.3, 0.6});
  k.deviation = PeriodicSignal::tabulated({0.05, 0.3, 0.55, 0.8}, {0.1, -0.1, 0.12, -0.08});
  k.rotation = PeriodicSignal::tabulated({0.0, 0.2, 0.35, 0.5, 0.7, 0.85},
                                         {1.57, 0.9, 0.8, 1.57, 2.3, 2.2});
  k.rotation_phase = -0.1;
  k.stroke_plane_angle = -0.25;
  return k;
}

Eigen::Vector3d vee(const Eigen::Matrix3d& W) {
  return 0.5 * Eigen::Vector3d(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}

// ω from the orientation alone: Ṙ Rᵀ = ω̂ (ground frame), Ṙ by central differences.
Eigen::Vector3d omega_from_orientation(const WingKinematics& k, double t, double h) {
  const Eigen::Matrix3d Rdot = (k.pose(t + h).rotation - k.pose(t - h).rotation) / (2 * h);
  return vee(Rdot * k.pose(t).rotation.transpose());
}

void check_case(const WingKinematics& k) {
  const double T = 1.0 / k.frequency;
  const double h = 1e-7 * T;
  for (int i = 0; i < 23; ++i) {
    const double t = (i / 23.0 + 0.013) * T;
    // Euler-angle rates and accelerations, per second.
    const auto a = k.angles(t), ap = k.angles(t + h), am = k.angles(t - h);
    const auto check = [&](auto get, const char* name) {
      const auto c = get(a), p = get(ap), m = get(am);
      EXPECT_NEAR(c.rate, (p.value - m.value) / (2 * h), 1e-6 * (1 + std::abs(c.rate))) << name << " t/T=" << t / T;
      EXPECT_NEAR(c.acceleration, (p.rate - m.rate) / (2 * h), 1e-6 * (1 + std::abs(c.acceleration)))
          << name << " t/T=" << t / T;
    };
    check([](const WingKinematics::Angles& x) { return x.sweep; }, "sweep");
    check([](const WingKinematics::Angles& x) { return x.deviation; }, "deviation");
    check([](const WingKinematics::Angles& x) { return x.rotation; }, "rotation");

    // ω against skew(Ṙ Rᵀ); ω̇ against differences of ω.
    const BasePose p = k.pose(t);
    const Eigen::Vector3d w_fd = omega_from_orientation(k, t, h);
    EXPECT_LT((p.angular_velocity - w_fd).norm(), 1e-6 * (1 + p.angular_velocity.norm())) << "t/T=" << t / T;
    const Eigen::Vector3d dw_fd = (k.pose(t + h).angular_velocity - k.pose(t - h).angular_velocity) / (2 * h);
    EXPECT_LT((p.angular_acceleration - dw_fd).norm(), 1e-6 * (1 + p.angular_acceleration.norm()))
        << "t/T=" << t / T;
    // ω̇ from the orientation alone (second differences of R), looser step.
    const double H = 1e-4 * T;
    const Eigen::Vector3d dw_fd2 =
        (omega_from_orientation(k, t + H, 1e-7 * T) - omega_from_orientation(k, t - H, 1e-7 * T)) / (2 * H);
    EXPECT_LT((p.angular_acceleration - dw_fd2).norm(), 1e-4 * (1 + p.angular_acceleration.norm()))
        << "t/T=" << t / T;
  }
}

}  // namespace

TEST(KinematicsDerivatives, HarmonicRatesAndAngularMotionMatchFiniteDifferences) {
  check_case(harmonic_case());
}

TEST(KinematicsDerivatives, TabulatedRatesAndAngularMotionMatchFiniteDifferences) {
  check_case(tabulated_case());
}

TEST(KinematicsDerivatives, AngularVelocityIsSweepRateAboutStrokeNormalWhenOnlySweeping) {
  // Pure sweep: ω = φ̇ z_S exactly, ω̇ = φ̈ z_S (rigid rotation about a fixed axis).
  WingKinematics k;
  k.frequency = 20.0;
  k.sweep = PeriodicSignal::harmonic(0.0, {1.0}, {});
  k.stroke_plane_angle = 0.4;
  const Eigen::Vector3d z_S(std::sin(0.4), 0.0, std::cos(0.4));
  for (double t : {0.001, 0.013, 0.031}) {
    const auto a = k.angles(t);
    const BasePose p = k.pose(t);
    EXPECT_TRUE(p.angular_velocity.isApprox(a.sweep.rate * z_S, 1e-13));
    EXPECT_TRUE(p.angular_acceleration.isApprox(a.sweep.acceleration * z_S, 1e-13));
  }
}
