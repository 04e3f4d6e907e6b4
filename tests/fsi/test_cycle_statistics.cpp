// The statistics of a run's cycle means (pipeline/fsi/cycle_statistics.hpp), on a series
// whose cycle means are known: x(t) = m_k (1 − cos 2πt/T) in cycle k. The trapezoidal mean
// of cos over a whole period of uniform samples is 0, so cycle k's mean is m_k exactly
// (to round-off), and x is continuous (0 at every cycle's start).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "pipeline/fsi/cycle_statistics.hpp"

using flapsim::fsi::cycle_statistics;

namespace {

struct KnownCycleSeries {
  std::vector<double> t, x;
};

/// Samples at t = 0, Δt, … of x(t) = m_k (1 − cos 2πt/T) in cycle k (0-based), `steps` a cycle.
KnownCycleSeries series_with_cycle_means(const std::vector<double>& means, double period, int steps,
                                         int extra_steps = 0) {
  KnownCycleSeries s;
  const int total = static_cast<int>(means.size()) * steps + extra_steps;
  for (int i = 0; i <= total; ++i) {
    const double t = i * period / steps;
    const int k = std::min(i / steps, static_cast<int>(means.size()) - 1);
    s.t.push_back(t);
    s.x.push_back(means[k] * (1.0 - std::cos(2.0 * std::numbers::pi * t / period)));
  }
  return s;
}

}  // namespace

TEST(CycleStatistics, MeanDeviationAndStandardErrorOfTheCyclesFromTheSecondOn) {
  // Cycle means 100 (the start, left out), 2, 3, 5, 6. By hand: mean 4; deviations
  // −2, −1, 1, 2; sample standard deviation √(10/3) = 1.825742; standard error √(10/3)/2 =
  // 0.912871; lag-one correlation ((−2)(−1) + (−1)(1) + (1)(2))/10 = 0.3.
  const double period = 0.04;  // [s]
  const KnownCycleSeries s = series_with_cycle_means({100.0, 2.0, 3.0, 5.0, 6.0}, period, 50);
  const auto c = cycle_statistics(s.t, s.x, period, s.t.back(), 2);
  ASSERT_EQ(c.cycle_means.size(), 4u);
  EXPECT_NEAR(c.cycle_means[0], 2.0, 1e-12);
  EXPECT_NEAR(c.cycle_means[3], 6.0, 1e-12);
  EXPECT_NEAR(c.mean, 4.0, 1e-12);
  EXPECT_NEAR(c.deviation, std::sqrt(10.0 / 3.0), 1e-12);
  EXPECT_NEAR(c.standard_error, std::sqrt(10.0 / 3.0) / 2.0, 1e-12);
  EXPECT_NEAR(c.lag_one_correlation, 0.3, 1e-12);
  // Drift: i − ī = −1.5, −0.5, 0.5, 1.5; Σ(i − ī)(m − 4) = 3 + 0.5 + 0.5 + 3 = 7, Σ(i − ī)² = 5;
  // slope 1.4 a cycle, × 3 cycles = 4.2.
  EXPECT_NEAR(c.drift, 4.2, 1e-12);
}

// A run still settling: its cycle means approach their limit (a user's 12-cycle film wing,
// interrupted after 6: 3.23271, 3.20590, 3.20357, 3.19799, 3.19657 over cycles 2–6). The
// lag-one correlation reads 0.1216, as for independent cycles; the drift, by hand from the
// least-squares line (slope −0.008019 a cycle) over 4 cycles, is −0.032076: 4.9 standard
// errors (0.006570), where 5 independent cycles drift by √12 √(4/6) = 2.83 rms.
TEST(CycleStatistics, CyclesStillSettlingDriftByManyStandardErrors) {
  const double period = 0.04;
  const KnownCycleSeries s =
      series_with_cycle_means({100.0, 3.23271, 3.20590, 3.20357, 3.19799, 3.19657}, period, 48);
  const auto c = cycle_statistics(s.t, s.x, period, s.t.back(), 2);
  EXPECT_NEAR(c.lag_one_correlation, 0.121576, 1e-6);
  EXPECT_NEAR(c.drift, -0.032076, 1e-6);
  EXPECT_NEAR(c.standard_error, 0.0065702, 1e-6);
  EXPECT_GT(std::abs(c.drift), 1.7 * std::sqrt(12.0 * 4.0 / 6.0) * c.standard_error);
}

TEST(CycleStatistics, AnUnfinishedLastCycleIsLeftOutAndTooFewCyclesAreRefused) {
  // 30 steps into a sixth cycle (mean 50 so far): only the five whole cycles count.
  const double period = 0.04;
  const KnownCycleSeries s = series_with_cycle_means({100.0, 2.0, 3.0, 5.0, 6.0, 50.0}, period, 50, -20);
  const auto c = cycle_statistics(s.t, s.x, period, s.t.back(), 2);
  EXPECT_EQ(c.cycle_means.size(), 4u);
  EXPECT_NEAR(c.mean, 4.0, 1e-12);
  // From the fourth cycle on: 5 and 6.
  EXPECT_NEAR(cycle_statistics(s.t, s.x, period, s.t.back(), 4).mean, 5.5, 1e-12);
  // From the fifth: one cycle, no deviation to take.
  EXPECT_THROW(cycle_statistics(s.t, s.x, period, s.t.back(), 5), std::invalid_argument);
}

TEST(CycleStatistics, WholeCyclesCountsACycleThatEndsWithinRoundOffOfTheLastStep) {
  // 10 steps of 0.1 s summed (t_end 0.9999999999999999, below 1) are one cycle of 1 s; 0.99 s is none.
  double t = 0.0;
  for (int i = 0; i < 10; ++i) t += 0.1;
  EXPECT_LT(t, 1.0);
  EXPECT_EQ(flapsim::fsi::whole_cycles(1.0, t), 1);
  EXPECT_EQ(flapsim::fsi::whole_cycles(1.0, 0.99), 0);
  EXPECT_EQ(flapsim::fsi::whole_cycles(0.04, 0.4 + 1e-12), 10);
  EXPECT_EQ(flapsim::fsi::whole_cycles(0.0, 1.0), 0);  // no period: no cycles, not an overflow
}
