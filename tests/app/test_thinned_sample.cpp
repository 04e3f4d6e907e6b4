// run.pvsm's colour ranges are percentiles over a whole run's frames; their sample is capped
// (pipeline/app/thinned_sample.hpp): a 16-wingbeat film run kept every wake cell of every
// frame, 38 MB more than the same run without frames.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "pipeline/app/thinned_sample.hpp"
#include "pipeline/io/pvsm_state.hpp"

using flapsim::app::ThinnedSample;

TEST(ThinnedSample, BelowItsLimitItKeepsEveryValueInOrder) {
  ThinnedSample s(100);
  std::vector<double> v(60);
  std::iota(v.begin(), v.end(), 1.0);
  s.add(v.begin(), v.end());
  EXPECT_EQ(s.values(), v);
  EXPECT_EQ(s.stride(), 1u);
}

TEST(ThinnedSample, AtItsLimitItKeepsAnEvenStrideOfEverythingOffered) {
  // 1000 values offered to a sample of at most 64: thinned at 64, 64 (stride 4), … until the
  // stride is 16: every 16th value from the first, 63 of them (0, 16, …, 992).
  ThinnedSample s(64);
  std::vector<double> v(1000);
  std::iota(v.begin(), v.end(), 0.0);
  for (std::size_t i = 0; i < v.size(); i += 7) s.add(v.begin() + i, v.begin() + std::min(v.size(), i + 7));
  EXPECT_EQ(s.stride(), 16u);
  ASSERT_EQ(s.values().size(), 63u);
  for (std::size_t k = 0; k < s.values().size(); ++k) EXPECT_EQ(s.values()[k], 16.0 * k) << k;
  EXPECT_LT(s.values().size(), 64u);
}

TEST(ThinnedSample, ThePercentileOfTheThinnedSampleIsTheWholeRunsWithinItsResolution) {
  // |Γ| of a growing wake: frame k has k cells of values spread over [0, 1). The 95th
  // percentile of 1.25e6 values (500 frames) from 2^16 of them: within 1e-3.
  ThinnedSample s(std::size_t{1} << 16);
  std::vector<double> all;
  for (int k = 1; k <= 5000; k += 10) {
    std::vector<double> frame(static_cast<std::size_t>(k));
    for (int i = 0; i < k; ++i) frame[static_cast<std::size_t>(i)] = std::fmod(0.618033988749895 * (i + 7 * k), 1.0);
    s.add(frame.begin(), frame.end());
    all.insert(all.end(), frame.begin(), frame.end());
  }
  std::vector<double> thinned = s.values();
  EXPECT_LT(thinned.size(), std::size_t{1} << 16);
  const double exact = flapsim::io::magnitude_percentile(all, 95.0);
  const double approx = flapsim::io::magnitude_percentile(thinned, 95.0);
  EXPECT_NEAR(approx, exact, 1e-3);
}
