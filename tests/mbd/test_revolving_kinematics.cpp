// The revolving wing (mbd::WingKinematics::Revolution, docs/kinematics.md "A revolving
// wing"): the rate rises from 0 to Ω over the ramp τ as Ω (1 − cos(π t/τ))/2 and stays at Ω;
// its angle is the closed-form integral, checked against quadrature and finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mbd/angle_units.hpp"
#include "mbd/wing_kinematics.hpp"

namespace {

using flapsim::kDegToRad;
using flapsim::mbd::PeriodicSignal;
using flapsim::mbd::WingKinematics;

WingKinematics revolving(double rate, double ramp) {
  WingKinematics k;
  k.frequency = 1.0;  // the time unit of the run only
  k.sweep = PeriodicSignal::harmonic(0.0, {}, {});
  k.rotation = PeriodicSignal::harmonic(45.0 * kDegToRad, {}, {});
  k.revolution.rate = rate;
  k.revolution.ramp = ramp;
  return k;
}

TEST(RevolvingKinematics, TheRampReachesTheRateAndTheAngleIsItsIntegral) {
  const double omega = -3.0, tau = 0.2;  // [rad/s], [s]
  const WingKinematics k = revolving(omega, tau);
  // At rest at t = 0, at Ω (and no acceleration) from τ on.
  EXPECT_EQ(k.angles(0.0).sweep.rate, 0.0);
  EXPECT_NEAR(k.angles(tau).sweep.rate, omega, 1e-15);
  EXPECT_NEAR(k.angles(tau).sweep.acceleration, 0.0, 1e-12);
  EXPECT_EQ(k.angles(0.7).sweep.rate, omega);
  // φ(t) = ∫₀ᵗ φ̇: Simpson's rule on 2000 intervals of the ramp (error ~1e-13), then Ω per second.
  const int n = 2000;
  double integral = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double t = tau * i / n, w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    integral += w * k.angles(t).sweep.rate;
  }
  integral *= tau / (3.0 * n);
  EXPECT_NEAR(k.angles(tau).sweep.value, integral, 1e-12);
  EXPECT_NEAR(integral, omega * tau / 2.0, 1e-12);  // the mean rate over the ramp is Ω/2
  EXPECT_NEAR(k.angles(0.7).sweep.value, omega * (tau / 2.0 + 0.7 - tau), 1e-14);
  // Rates and accelerations against central differences, on the ramp and after it.
  const double h = 1e-6;
  for (double t : {0.013, 0.05, 0.1, 0.17, 0.199, 0.3}) {
    const auto a = k.angles(t).sweep, p = k.angles(t + h).sweep, m = k.angles(t - h).sweep;
    EXPECT_NEAR(a.rate, (p.value - m.value) / (2 * h), 1e-8) << t;
    EXPECT_NEAR(a.acceleration, (p.rate - m.rate) / (2 * h), 1e-6) << t;
  }
  // The angular velocity of the base is the sweep rate about the stroke-plane normal.
  EXPECT_NEAR(k.pose(0.5).angular_velocity.z(), omega, 1e-14);
}

TEST(RevolvingKinematics, WithoutARampTheWingTurnsAtTheRateFromTheStart) {
  const WingKinematics k = revolving(2.0, 0.0);
  // At t = 0 itself too (until 2 Dec the rate was 0 there: the reference speed, a mean of
  // 720 samples from t = 0, came out 719/720 of Ω r2 R, CL and CD 0.28 % high).
  EXPECT_EQ(k.angles(0.0).sweep.rate, 2.0);
  EXPECT_EQ(k.angles(1e-9).sweep.rate, 2.0);
  EXPECT_NEAR(k.angles(0.25).sweep.value, 0.5, 1e-15);
  EXPECT_EQ(k.angles(0.0).sweep.value, 0.0);
}

}  // namespace
