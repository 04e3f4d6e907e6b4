// Periodic angle signals: harmonic series and periodic C² cubic splines, with
// their exact derivatives checked against the defining formulas, finite
// differences and the cubic-spline interpolation error bound.

#include "mbd/periodic_signal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

using flapsim::mbd::AngleSample;
using flapsim::mbd::PeriodicSignal;

namespace {

constexpr double kPi = std::numbers::pi;

// Central differences of the value and of the rate, step ds in cycles.
void expect_derivatives_match_finite_differences(const PeriodicSignal& sig, double s,
                                                 double ds, double tol) {
  const AngleSample c = sig.at_phase(s);
  const AngleSample p = sig.at_phase(s + ds), m = sig.at_phase(s - ds);
  const double rate_fd = (p.value - m.value) / (2.0 * ds);
  const double acc_fd = (p.rate - m.rate) / (2.0 * ds);
  const double acc_fd2 = (p.value - 2.0 * c.value + m.value) / (ds * ds);
  const double scale_rate = 1.0 + std::abs(c.rate);
  const double scale_acc = 1.0 + std::abs(c.acceleration);
  EXPECT_NEAR(c.rate, rate_fd, tol * scale_rate) << "s = " << s;
  EXPECT_NEAR(c.acceleration, acc_fd, tol * scale_acc) << "s = " << s;
  EXPECT_NEAR(c.acceleration, acc_fd2, 1e3 * tol * scale_acc) << "s = " << s;
}

std::vector<double> uneven_phases() { return {0.0, 0.07, 0.2, 0.31, 0.45, 0.52, 0.7, 0.81, 0.93}; }
std::vector<double> uneven_values() { return {0.3, 0.9, 1.2, 0.4, -0.5, -0.8, -0.1, 0.2, 0.1}; }

}  // namespace

TEST(PeriodicSignal, DefaultIsZero) {
  const AngleSample a = PeriodicSignal().at_phase(0.37);
  EXPECT_EQ(a.value, 0.0);
  EXPECT_EQ(a.rate, 0.0);
  EXPECT_EQ(a.acceleration, 0.0);
}

// is_constant decides whether a rotation phase can shift anything (io::input_hash and the
// case warning of pipeline/io/case_file.cpp): a mean alone or a table of equal values is
// constant; one harmonic or one differing table value is not.
TEST(PeriodicSignal, IsConstantOnlyWithoutHarmonicsOrWithEqualTableValues) {
  using flapsim::mbd::PeriodicSignal;
  EXPECT_TRUE(PeriodicSignal().is_constant());
  EXPECT_TRUE(PeriodicSignal::harmonic(0.5, {0.0}, {}).is_constant());
  EXPECT_FALSE(PeriodicSignal::harmonic(0.5, {0.0, 0.1}, {}).is_constant());
  EXPECT_FALSE(PeriodicSignal::harmonic(0.0, {}, {1e-9}).is_constant());
  EXPECT_TRUE(PeriodicSignal::tabulated({0.0, 0.3, 0.6}, {0.2, 0.2, 0.2}).is_constant());
  EXPECT_FALSE(PeriodicSignal::tabulated({0.0, 0.3, 0.6}, {0.2, 0.2, 0.21}).is_constant());
}

TEST(PeriodicSignal, HarmonicMatchesItsSeriesAndExactDerivatives) {
  // value = m + a1 cos 2πs + a2 cos 4πs + b1 sin 2πs (definition in periodic_signal.hpp);
  // d/ds and d²/ds² written out by hand.
  const double m = 0.2, a1 = 0.8, a2 = -0.15, b1 = 0.3;
  const PeriodicSignal sig = PeriodicSignal::harmonic(m, {a1, a2}, {b1});
  for (double s : {-1.3, 0.0, 0.125, 0.4, 0.77, 2.9}) {
    const double w = 2 * kPi;
    const AngleSample a = sig.at_phase(s);
    EXPECT_NEAR(a.value, m + a1 * std::cos(w * s) + a2 * std::cos(2 * w * s) + b1 * std::sin(w * s), 1e-14);
    EXPECT_NEAR(a.rate, -a1 * w * std::sin(w * s) - a2 * 2 * w * std::sin(2 * w * s) + b1 * w * std::cos(w * s), 1e-12);
    EXPECT_NEAR(a.acceleration, -a1 * w * w * std::cos(w * s) - a2 * 4 * w * w * std::cos(2 * w * s) -
                                    b1 * w * w * std::sin(w * s), 1e-10);
    expect_derivatives_match_finite_differences(sig, s, 1e-5, 1e-6);  // O(ds²) truncation ~1e-7
  }
}

TEST(PeriodicSignal, HarmonicIsPeriodic) {
  const PeriodicSignal sig = PeriodicSignal::harmonic(0.1, {0.5, 0.2, 0.05}, {0.3, -0.1});
  for (double s : {0.0, 0.21, 0.66}) {
    const AngleSample a = sig.at_phase(s), b = sig.at_phase(s + 3.0), c = sig.at_phase(s - 2.0);
    EXPECT_NEAR(a.value, b.value, 1e-12);
    EXPECT_NEAR(a.rate, c.rate, 1e-10);
    EXPECT_NEAR(a.acceleration, b.acceleration, 1e-8);
  }
}

TEST(PeriodicSignal, SplinePassesThroughItsKnotsInEveryPeriod) {
  const auto ph = uneven_phases();
  const auto val = uneven_values();
  const PeriodicSignal sig = PeriodicSignal::tabulated(ph, val);
  for (std::size_t i = 0; i < ph.size(); ++i)
    for (int k : {-2, 0, 1, 5}) EXPECT_NEAR(sig.at_phase(ph[i] + k).value, val[i], 1e-12) << i << " " << k;
}

TEST(PeriodicSignal, SplineIsPeriodicC2AcrossKnotsAndThePeriodEnd) {
  // C²: value, d/ds and d²/ds² have no jump at any knot, including the wrap from
  // the last knot to the first one of the next period. Across a gap of 2ε the
  // jump of a C² quantity is O(ε) times the next derivative; a C¹-only spline
  // would jump in d²/ds² by O(1).
  const auto ph = uneven_phases();
  const PeriodicSignal sig = PeriodicSignal::tabulated(ph, uneven_values());
  const double eps = 1e-9;
  std::vector<double> joints(ph.begin(), ph.end());
  joints.push_back(1.0);  // the end of the period = first knot (0) of the next one
  for (double s : joints) {
    const AngleSample l = sig.at_phase(s - eps), r = sig.at_phase(s + eps);
    EXPECT_NEAR(l.value, r.value, 1e-7) << "s = " << s;
    EXPECT_NEAR(l.rate, r.rate, 1e-6) << "s = " << s;
    EXPECT_NEAR(l.acceleration, r.acceleration, 1e-4) << "s = " << s;
  }
  // A table not starting at phase 0: the wrap is between 0.95 and 1.1.
  const PeriodicSignal shifted = PeriodicSignal::tabulated({0.1, 0.4, 0.6, 0.95}, {1.0, -0.5, 0.3, 0.8});
  for (double s : {0.1, 1.1, 0.95, 0.0, 1.0}) {
    const AngleSample l = shifted.at_phase(s - eps), r = shifted.at_phase(s + eps);
    EXPECT_NEAR(l.value, r.value, 1e-7) << "s = " << s;
    EXPECT_NEAR(l.rate, r.rate, 1e-6) << "s = " << s;
    EXPECT_NEAR(l.acceleration, r.acceleration, 1e-4) << "s = " << s;
  }
}

TEST(PeriodicSignal, SplineDerivativesMatchFiniteDifferences) {
  const PeriodicSignal sig = PeriodicSignal::tabulated(uneven_phases(), uneven_values());
  for (double s : {0.01, 0.13, 0.26, 0.5, 0.6, 0.75, 0.88, 0.97, 1.33, -0.42})
    expect_derivatives_match_finite_differences(sig, s, 1e-6, 1e-6);
}

TEST(PeriodicSignal, SplineOfSineIsWithinTheCubicSplineErrorBound) {
  // For a periodic cubic spline interpolant of a smooth periodic f on knots of
  // spacing h: |f − s| ≤ 5/384 h⁴ max|f⁗| (Hall & Meyer, J. Approx. Theory 16, 1976).
  // f = sin 2πs, 40 knots: bound = 5/384 (1/40)⁴ (2π)⁴ ≈ 7.9e-6.
  const int n = 40;
  std::vector<double> ph(n), val(n);
  for (int i = 0; i < n; ++i) {
    ph[i] = static_cast<double>(i) / n;
    val[i] = std::sin(2 * kPi * ph[i]);
  }
  const PeriodicSignal sig = PeriodicSignal::tabulated(ph, val);
  const double h = 1.0 / n;
  const double bound = 5.0 / 384.0 * std::pow(h, 4) * std::pow(2 * kPi, 4);
  double max_err = 0.0, max_rate_err = 0.0;
  for (int k = 0; k <= 4000; ++k) {
    const double s = k / 4000.0;
    const AngleSample a = sig.at_phase(s);
    max_err = std::max(max_err, std::abs(a.value - std::sin(2 * kPi * s)));
    max_rate_err = std::max(max_rate_err, std::abs(a.rate - 2 * kPi * std::cos(2 * kPi * s)));
  }
  EXPECT_LE(max_err, bound);
  EXPECT_GT(max_err, 0.0);
  // Derivative bound of the same paper: |f' − s'| ≤ (√3/216 + 1/24) h³ max|f⁗| ≈ 1.4e-3.
  EXPECT_LE(max_rate_err, (std::sqrt(3.0) / 216.0 + 1.0 / 24.0) * std::pow(h, 3) * std::pow(2 * kPi, 4));
}

// A finely sampled measured wingbeat: 20 000 knots of unequal spacing (a sampled cycle's
// jitter). The second derivatives were solved densely (8000 knots took 46 s in
// `flapsim check`, 200 000 ran out of memory; 20 000 would need 3.2 GB); the cyclic
// tridiagonal solve is O(n). The spline of sin 2πs is exact to its error bound with the
// largest spacing, and its acceleration is −(2π)² sin 2πs to that bound's second-derivative
// part, (3/8) h² max|f⁗| (Hall & Meyer 1976), with round-off's share of 1/h² · 1e-14.
TEST(PeriodicSignal, SplineOfManyUnequalKnotsIsSolvedAndAccurate) {
  const int n = 20000;
  std::vector<double> ph(n), val(n);
  double h_max = 0.0;
  for (int i = 0; i < n; ++i) {
    ph[i] = (i + 0.3 * std::sin(7.0 * i)) / n;  // spacing (1 ± 0.6)/n
    val[i] = std::sin(2 * kPi * ph[i]);
  }
  for (int i = 0; i < n; ++i) h_max = std::max(h_max, (i + 1 < n ? ph[i + 1] : ph[0] + 1.0) - ph[i]);
  const PeriodicSignal sig = PeriodicSignal::tabulated(ph, val);
  const double f4 = std::pow(2 * kPi, 4);
  double max_err = 0.0, max_acc_err = 0.0;
  for (int k = 0; k <= 7919; ++k) {
    const double s = k / 7919.0;
    const AngleSample a = sig.at_phase(s);
    max_err = std::max(max_err, std::abs(a.value - std::sin(2 * kPi * s)));
    max_acc_err = std::max(max_acc_err, std::abs(a.acceleration + 4 * kPi * kPi * std::sin(2 * kPi * s)));
  }
  EXPECT_LE(max_err, 5.0 / 384.0 * std::pow(h_max, 4) * f4 + 1e-14);
  EXPECT_LE(max_acc_err, 3.0 / 8.0 * std::pow(h_max, 2) * f4 + 1e-14 / (h_max * h_max));
}

TEST(PeriodicSignal, SplineOfConstantIsConstant) {
  const PeriodicSignal sig = PeriodicSignal::tabulated({0.0, 0.3, 0.5, 0.9}, {0.7, 0.7, 0.7, 0.7});
  for (double s : {0.0, 0.15, 0.95, 3.3}) {
    const AngleSample a = sig.at_phase(s);
    EXPECT_NEAR(a.value, 0.7, 1e-14);
    EXPECT_NEAR(a.rate, 0.0, 1e-12);
    EXPECT_NEAR(a.acceleration, 0.0, 1e-10);
  }
}

TEST(PeriodicSignal, BadTablesAreRejected) {
  EXPECT_THROW(PeriodicSignal::tabulated({0.0, 0.5}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(PeriodicSignal::tabulated({0.0, 0.5, 0.7}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(PeriodicSignal::tabulated({0.0, 0.5, 0.5}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(PeriodicSignal::tabulated({0.0, 0.6, 0.5}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(PeriodicSignal::tabulated({0.0, 0.5, 1.0}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(PeriodicSignal::tabulated({-0.1, 0.5, 0.7}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(PeriodicSignal::tabulated({0.0, 0.5, 0.7}, {1.0, NAN, 3.0}), std::invalid_argument);
}
