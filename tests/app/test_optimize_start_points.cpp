// The starts of a multi-start flapsim optimize: the Halton sequence (Halton 1960), whose
// points in base b are the radical inverses of 1, 2, 3, ... (van der Corput's sequence in
// base 2: 1/2, 1/4, 3/4, 1/8, ...), scaled into the bounds.
#include <gtest/gtest.h>

#include <vector>

#include "pipeline/app/optimize/start_points.hpp"

namespace {

using flapsim::optimize::radical_inverse;
using flapsim::optimize::start_points;

TEST(OptimizeStartPoints, RadicalInversesAreTheVanDerCorputSequence) {
  // Base 2: 1 = 1b -> 0.1b, 2 = 10b -> 0.01b, 3 = 11b -> 0.11b, 4 = 100b -> 0.001b, 6 = 110b -> 0.011b.
  EXPECT_DOUBLE_EQ(radical_inverse(1, 2), 0.5);
  EXPECT_DOUBLE_EQ(radical_inverse(2, 2), 0.25);
  EXPECT_DOUBLE_EQ(radical_inverse(3, 2), 0.75);
  EXPECT_DOUBLE_EQ(radical_inverse(4, 2), 0.125);
  EXPECT_DOUBLE_EQ(radical_inverse(6, 2), 0.375);
  // Base 3: 1 -> 0.1 = 1/3, 2 -> 0.2 = 2/3, 3 = 10 -> 0.01 = 1/9, 5 = 12 -> 0.21 = 2/3 + 1/9.
  EXPECT_DOUBLE_EQ(radical_inverse(1, 3), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(radical_inverse(2, 3), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(radical_inverse(3, 3), 1.0 / 9.0);
  EXPECT_DOUBLE_EQ(radical_inverse(5, 3), 2.0 / 3.0 + 1.0 / 9.0);
  EXPECT_EQ(radical_inverse(0, 2), 0.0);
}

TEST(OptimizeStartPoints, TheFirstStartIsTheCasesOwnThenHaltonPointsInTheBounds) {
  const std::vector<double> lo{-0.25, 20.0}, hi{0.15, 30.0}, own{0.0, 26.1};
  const auto starts = start_points(own, lo, hi, 4);
  ASSERT_EQ(starts.size(), 4u);
  EXPECT_EQ(starts[0], own);
  // Halton point k: (radical inverse of k in base 2, in base 3), scaled into the bounds.
  EXPECT_DOUBLE_EQ(starts[1][0], -0.25 + 0.5 * 0.4);
  EXPECT_DOUBLE_EQ(starts[1][1], 20.0 + 10.0 / 3.0);
  EXPECT_DOUBLE_EQ(starts[2][0], -0.25 + 0.25 * 0.4);
  EXPECT_DOUBLE_EQ(starts[2][1], 20.0 + 20.0 / 3.0);
  EXPECT_DOUBLE_EQ(starts[3][0], -0.25 + 0.75 * 0.4);
  EXPECT_DOUBLE_EQ(starts[3][1], 20.0 + 10.0 / 9.0);
  EXPECT_EQ(start_points(own, lo, hi, 1).size(), 1u);
}

}  // namespace
