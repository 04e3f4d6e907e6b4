// The values of a `--vary KEY=start:step:stop` range are the decimal numbers the user meant
// (pipeline/app/sweep/sweep_values): start + i·step in binary floating point misses them by
// round-off, which must not reach the case, its folder name or sweep.csv.
#include <gtest/gtest.h>

#include <string>

#include "pipeline/app/sweep/sweep_values.hpp"

namespace {

using namespace flapsim;

// −0.3 + 3·0.1 = 5.551115123125783e-17 in IEEE doubles (0.1 and 0.3 are not exact): the
// fourth value of −0.3:0.1:0.1 is zero, and its folder label "0" (not "5.551115123e-17").
TEST(SweepRangeValues, AValueThatShouldBeZeroIsZero) {
  const auto v = sweep::parse_variation("kinematics.rotation_phase=-0.3:0.1:0.1");
  ASSERT_EQ(v.values.size(), 5u);
  EXPECT_EQ(v.values[3].value, 0.0);
  EXPECT_FALSE(std::signbit(v.values[3].value));
  EXPECT_EQ(sweep::value_label(v.values[3]), "0");
  // Downward: 0.3 − 3·0.1 = −5.55e-17, also zero (not "-0").
  const auto d = sweep::parse_variation("k=0.3:-0.1:-0.1");
  ASSERT_EQ(d.values.size(), 5u);
  EXPECT_EQ(sweep::value_label(d.values[3]), "0");
  // The other values are the decimals as typed (strtod of "-0.2", "-0.1", "0.1").
  EXPECT_EQ(v.values[1].value, -0.2);
  EXPECT_EQ(v.values[2].value, -0.1);
  EXPECT_EQ(v.values[4].value, 0.1);
  // A small but real value is kept: 1e-12:1e-12:3e-12 has no zero.
  const auto s = sweep::parse_variation("k=1e-12:1e-12:3e-12");
  ASSERT_EQ(s.values.size(), 3u);
  EXPECT_EQ(s.values[0].value, 1e-12);
}

}  // namespace
