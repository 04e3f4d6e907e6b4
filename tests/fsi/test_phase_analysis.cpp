// Reading runs as the rotation-phase paper does (pipeline/fsi/phase_analysis).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "mbd/angle_units.hpp"
#include "mbd/wing_kinematics.hpp"
#include "pipeline/fsi/phase_analysis.hpp"

namespace {

using namespace flapsim;
constexpr double kPi = std::numbers::pi;

mbd::WingKinematics eq8(double dpsi) {
  // Eq. 8 of the rotation-phase paper with a deviation, to exercise all three angles.
  mbd::WingKinematics k;
  k.frequency = 26.1;
  k.rotation_phase = dpsi;
  k.sweep = mbd::PeriodicSignal::harmonic(10.0 * kDegToRad, {50.0 * kDegToRad}, {});
  k.deviation = mbd::PeriodicSignal::harmonic(0.0, {}, {8.0 * kDegToRad});
  k.rotation = mbd::PeriodicSignal::harmonic(90.0 * kDegToRad, {}, {-45.0 * kDegToRad});
  return k;
}

// The rotation phase of kinematics k read from its samples over `cycles` periods, `samples` a
// period, in the last period.
std::optional<double> sampled_rotation_phase(const mbd::WingKinematics& k, int samples, int cycles) {
  const double T = 1.0 / k.frequency;
  std::vector<double> t, phi, alpha;
  for (int n = 0; n <= cycles * samples; ++n) {
    t.push_back(n * T / samples);
    const auto a = k.angles(t.back());
    phi.push_back(a.sweep.value);
    alpha.push_back(a.rotation.value);
  }
  return fsi::rotation_phase(t, phi, alpha, T, (cycles - 1) * T, cycles * T);
}

TEST(FsiPhaseAnalysis, RotationPhaseOfEq8IsDeltaPsi) {
  // Eq. 8: the sweep reversal (φ max) is at ft = −δψ and α crosses 90° at ft = 0, so the
  // measured rotation phase is δψ itself (to the sampling's interpolation error).
  for (double dpsi : {-0.2, -0.1, 0.0, 0.05, 0.1}) {
    const auto p = sampled_rotation_phase(eq8(dpsi), 100, 3);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(*p, dpsi, 2e-4) << "dpsi " << dpsi;
  }
}

// A mean rotation other than 90° (80°, amplitude 45°) moves the two α = 90° crossings apart,
// by ∓asin(10/45)/2π = ∓0.0357 of a period about δψ; their mean is δψ. The crossing 0.0257
// of a period before the window's end has its reversal at the last sample, where no
// extremum can be seen. Before: that crossing was dropped and the phase read the other
// half-stroke's δψ + 0.0357 (0.0457 for δψ = 0.01; a user's run, against
// tools/rotation_phase.py's 0.0100).
TEST(FsiPhaseAnalysis, BothHalfStrokesCountWhenAReversalEndsTheSeries) {
  for (double dpsi : {0.01, -0.05, 0.1}) {
    auto k = eq8(dpsi);
    k.rotation = mbd::PeriodicSignal::harmonic(80.0 * kDegToRad, {}, {-45.0 * kDegToRad});
    const auto p = sampled_rotation_phase(k, 50, 3);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(*p, dpsi, 5e-4) << "dpsi " << dpsi;
  }
}

// A rotation phase of ½ (or near it): each crossing finds its reversal half a period before
// or after, by the samples' round-off. The phases are circular: ½ and −½ are the same timing,
// and their mean is ±½. Before: a linear mean of −½ and ½ read 0 (the base at −0.5, the tip
// at 0.0 of the same undeformed wing).
TEST(FsiPhaseAnalysis, ARotationPhaseOfAHalfIsAveragedOnTheCircle) {
  for (double dpsi : {0.5, 0.499, -0.499, 0.45}) {
    for (int samples : {100, 97}) {
      const auto k = eq8(dpsi);
      const double T = 1.0 / k.frequency;
      std::vector<double> t, phi, alpha;
      for (int n = 0; n <= 5 * samples; ++n) {
        t.push_back(n * T / samples);
        const auto a = k.angles(t.back());
        phi.push_back(a.sweep.value);
        alpha.push_back(a.rotation.value);
      }
      const auto p = fsi::rotation_phase(t, phi, alpha, T, 1 * T, 4 * T);
      ASSERT_TRUE(p.has_value());
      // Distance on the circle of phases, and the range (−½, ½].
      const double d = *p - dpsi - std::round(*p - dpsi);
      EXPECT_LE(std::abs(d), 5e-4) << "dpsi " << dpsi << ", " << samples << " samples: " << *p;
      EXPECT_GT(*p, -0.5);
      EXPECT_LE(*p, 0.5);
    }
  }
}

TEST(FsiPhaseAnalysis, CrossingLagAndWindowMean) {
  // x(t) = sin(2π(t − 0.07)) lags sin(2πt) by 0.07 of the period; the mean of
  // 1 + sin over whole periods is 1 (trapezoidal rule, exact for a sampled sine).
  std::vector<double> t, x, ref, y;
  for (int n = 0; n <= 400; ++n) {
    t.push_back(n / 100.0);
    ref.push_back(std::sin(2 * kPi * t.back()));
    x.push_back(std::sin(2 * kPi * (t.back() - 0.07)));
    y.push_back(1.0 + ref.back());
  }
  const auto lag = fsi::crossing_lag(t, x, ref, 0.0, 1.0, 1.0, 3.0);
  ASSERT_TRUE(lag.has_value());
  EXPECT_NEAR(*lag, 0.07, 1e-3);
  EXPECT_NEAR(fsi::window_mean(t, y, 1.0, 3.0), 1.0, 1e-12);
}


TEST(FsiPhaseAnalysis, CrossingLagPairsTheCrossingsOfTheSameCycle) {
  // x lags the reference sin(2πt) by 0.01 of the period in its first cycle and by 0.05
  // from t = 0.75 on (the jump where x is near its minimum, far from a crossing). In the
  // window [0.9, 1.1] the reference rises through 0 at t = 1, and x's crossing of that
  // cycle is at 1.05: lag 0.05. Before, the shift was wrapped before the nearest was
  // chosen, and the crossing of the cycle before (t = 0.01, wrapped 0.01) was taken.
  std::vector<double> t, x, ref;
  for (int n = -50; n <= 300; ++n) {
    t.push_back(n / 100.0);
    ref.push_back(std::sin(2 * kPi * t.back()));
    const double lag = t.back() < 0.75 ? 0.01 : 0.05;
    x.push_back(std::sin(2 * kPi * (t.back() - lag)));
  }
  const auto lag = fsi::crossing_lag(t, x, ref, 0.0, 1.0, 0.9, 1.1);
  ASSERT_TRUE(lag.has_value());
  EXPECT_NEAR(*lag, 0.05, 1e-3);  // linear interpolation between samples 0.01 apart
}

}  // namespace
