// The least-squares Fourier series of a periodic table (mbd/fourier_fit.hpp) and the
// scatter of a table's spline (mbd/table_scatter.hpp), against their mathematics: a series
// sampled at uneven points is recovered exactly; at even points the fit is the discrete
// Fourier transform's coefficients; rounding to a step q scatters by q/sqrt(12).

#include "mbd/fourier_fit.hpp"
#include "mbd/table_scatter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

using flapsim::mbd::fit_fourier_series;
using flapsim::mbd::fourier_series_value;
using flapsim::mbd::FourierFit;
using flapsim::mbd::measure_table_scatter;
using flapsim::mbd::spline_rms_acceleration;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Eq. 8's sweep of the rotation-phase paper [deg]: 10 + 50 cos 2πs.
double eq8_sweep(double s) { return 10.0 + 50.0 * std::cos(kTwoPi * s); }

std::vector<double> even_phases(int n) {
  std::vector<double> p(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) p[static_cast<std::size_t>(i)] = static_cast<double>(i) / n;
  return p;
}

}  // namespace

// A series of 3 harmonics sampled at 11 uneven phases is its own least-squares fit: the
// coefficients come back to round-off and the points lie on it.
TEST(FourierFit, ASeriesSampledAtUnevenPointsIsRecoveredExactly) {
  const std::vector<double> phases = {0.0, 0.04, 0.13, 0.2, 0.33, 0.41, 0.5, 0.62, 0.71, 0.85, 0.93};
  const auto series = [](double s) {
    return 0.7 + 1.3 * std::cos(kTwoPi * s) - 0.4 * std::sin(kTwoPi * s) + 0.25 * std::cos(2 * kTwoPi * s) +
           0.1 * std::sin(3 * kTwoPi * s);
  };
  std::vector<double> values;
  for (double s : phases) values.push_back(series(s));
  const FourierFit fit = fit_fourier_series(phases, values, 3);
  EXPECT_NEAR(fit.mean, 0.7, 1e-12);
  ASSERT_EQ(fit.cos_coeffs.size(), 3u);
  EXPECT_NEAR(fit.cos_coeffs[0], 1.3, 1e-12);
  EXPECT_NEAR(fit.sin_coeffs[0], -0.4, 1e-12);
  EXPECT_NEAR(fit.cos_coeffs[1], 0.25, 1e-12);
  EXPECT_NEAR(fit.sin_coeffs[1], 0.0, 1e-12);
  EXPECT_NEAR(fit.cos_coeffs[2], 0.0, 1e-12);
  EXPECT_NEAR(fit.sin_coeffs[2], 0.1, 1e-12);
  EXPECT_LT(fit.residual_largest, 1e-12);
  EXPECT_NEAR(fourier_series_value(fit, 0.37), series(0.37), 1e-12);
}

// At n evenly spaced points the basis is orthogonal: a_k = (2/n) Σ v_i cos 2πk s_i,
// b_k = (2/n) Σ v_i sin 2πk s_i, the mean the points' mean (the discrete Fourier transform),
// and the residual the rest of the values' variance (Parseval).
TEST(FourierFit, AtEvenPointsTheFitIsTheDiscreteFourierTransform) {
  const int n = 40, harmonics = 5;
  const std::vector<double> phases = even_phases(n);
  std::mt19937 random(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> values;
  for (int i = 0; i < n; ++i) values.push_back(normal(random));
  const FourierFit fit = fit_fourier_series(phases, values, harmonics);
  double mean = 0.0;
  for (double v : values) mean += v / n;
  EXPECT_NEAR(fit.mean, mean, 1e-12);
  double explained = mean * mean;
  for (int k = 1; k <= harmonics; ++k) {
    double a = 0.0, b = 0.0;
    for (int i = 0; i < n; ++i) {
      a += 2.0 / n * values[i] * std::cos(kTwoPi * k * phases[i]);
      b += 2.0 / n * values[i] * std::sin(kTwoPi * k * phases[i]);
    }
    EXPECT_NEAR(fit.cos_coeffs[k - 1], a, 1e-12) << "k = " << k;
    EXPECT_NEAR(fit.sin_coeffs[k - 1], b, 1e-12) << "k = " << k;
    explained += (a * a + b * b) / 2.0;
  }
  double total = 0.0;
  for (double v : values) total += v * v / n;
  EXPECT_NEAR(fit.residual_rms, std::sqrt(total - explained), 1e-12);
}

// 2N + 1 coefficients need as many points; points that cover a fifth of the cycle leave a
// series of 5 harmonics undetermined (it could swing anywhere in the rest).
TEST(FourierFit, TooFewPointsOrPointsOnAPartOfTheCycleAreRefused) {
  EXPECT_THROW(fit_fourier_series(even_phases(6), std::vector<double>(6, 1.0), 3), std::invalid_argument);
  EXPECT_NO_THROW(fit_fourier_series(even_phases(7), std::vector<double>(7, 1.0), 3));
  std::vector<double> bunched;
  for (int i = 0; i < 30; ++i) bunched.push_back(0.2 * i / 30.0);
  EXPECT_THROW(fit_fourier_series(bunched, std::vector<double>(30, 1.0), 5), std::invalid_argument);
}

// The spline through 200 points of sin 2πs accelerates as the sine does: rms (2π)²/√2, to
// the spline's error O(h²) (2.7e-4 relative at h = 1/200: (2πh)²/12).
TEST(TableScatter, TheSplinesRmsAccelerationOfASineIsTheSines) {
  const std::vector<double> phases = even_phases(200);
  std::vector<double> values;
  for (double s : phases) values.push_back(std::sin(kTwoPi * s));
  EXPECT_NEAR(spline_rms_acceleration(phases, values), kTwoPi * kTwoPi / std::sqrt(2.0),
              3e-4 * kTwoPi * kTwoPi);
}

// Eq. 8's sweep as 1000 points rounded to 0.01 deg (a table printed with two decimals): the
// points scatter about the series by the rounding's q/sqrt(12) = 0.00289 deg (uniform error),
// nearly all of the spline's acceleration is that scatter, and one harmonic leaves the points
// as far. The same points unrounded: no scatter to speak of.
TEST(TableScatter, ATableRoundedToTwoDecimalsAcceleratesWithItsRounding) {
  const std::vector<double> phases = even_phases(1000);
  std::vector<double> rounded, exact;
  for (double s : phases) {
    exact.push_back(eq8_sweep(s));
    rounded.push_back(std::round(eq8_sweep(s) * 100.0) / 100.0);
  }
  const auto scatter = measure_table_scatter(phases, rounded);
  ASSERT_TRUE(scatter.has_value());
  EXPECT_EQ(scatter->harmonics, 24);  // min(1000 / 4, kScatterMaxHarmonics)
  EXPECT_NEAR(scatter->scatter_rms, 0.01 / std::sqrt(12.0) * std::sqrt(1.0 - 49.0 / 1000.0),
              0.1 * 0.01 / std::sqrt(12.0));
  EXPECT_GT(scatter->scatter_share, 0.95);
  EXPECT_GT(scatter->spline_acceleration / scatter->series_acceleration, 5.0);
  EXPECT_EQ(flapsim::mbd::fewest_harmonics_within_scatter(phases, rounded, *scatter), 1);
  // The series' rms acceleration is the motion's: 50 (2π)² / √2 deg/cycle².
  EXPECT_NEAR(scatter->series_acceleration, 50.0 * kTwoPi * kTwoPi / std::sqrt(2.0),
              0.01 * 50.0 * kTwoPi * kTwoPi);
  const auto clean = measure_table_scatter(phases, exact);
  ASSERT_TRUE(clean.has_value());
  EXPECT_LT(clean->scatter_share, 1e-3);
}

// Too few points to tell scatter from motion, and a constant table, are not measured.
TEST(TableScatter, FewPointsOrAConstantTableAreNotMeasured) {
  EXPECT_FALSE(measure_table_scatter(even_phases(7), {0, 1, 2, 3, 2, 1, 0}).has_value());
  EXPECT_FALSE(measure_table_scatter(even_phases(12), std::vector<double>(12, 3.0)).has_value());
}
