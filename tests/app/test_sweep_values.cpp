// The --vary argument of flapsim sweep and the case it makes for each value
// (pipeline/app/sweep/sweep_values).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pipeline/app/sweep/sweep_values.hpp"
#include "wings/input_error.hpp"

namespace {

using namespace flapsim;

TEST(SweepValues, RangesListsAndErrors) {
  const auto v = sweep::parse_variation("kinematics.rotation_phase=-0.10:0.05:0.10");
  EXPECT_EQ(v.key, "kinematics.rotation_phase");
  ASSERT_EQ(v.values.size(), 5u);  // −0.10, −0.05, 0, 0.05, 0.10 (inclusive)
  const double expected[5] = {-0.10, -0.05, 0.0, 0.05, 0.10};
  for (int i = 0; i < 5; ++i) EXPECT_EQ(v.values[static_cast<std::size_t>(i)], expected[i]);
  EXPECT_EQ(sweep::parse_variation("k=-0.20:0.05:0.10").values.size(), 7u);  // the rigid study
  EXPECT_EQ(sweep::parse_variation("k=3,1,2").values, (std::vector<double>{3, 1, 2}));
  EXPECT_THROW(sweep::parse_variation("k=0:0:1"), InputError);
  EXPECT_THROW(sweep::parse_variation("k=1:0.1:0"), InputError);
  EXPECT_THROW(sweep::parse_variation("k=a,b"), InputError);
  EXPECT_THROW(sweep::parse_variation("novalues"), InputError);
}

TEST(SweepValues, CaseIsReReadWithTheValue) {
  const std::string hover = std::string(FLAPSIM_SOURCE_DIR) + "/cases/hover.toml";
  const auto c = sweep::load_case_with(hover, "kinematics.rotation_phase", -0.15);
  EXPECT_DOUBLE_EQ(c.kinematics.rotation_phase, -0.15);
  EXPECT_EQ(sweep::load_case_with(hover, "numerics.cycles", 7).numerics.cycles, 7);
  // An integer key refuses a fraction; a value out of the case file's bounds is an input error.
  EXPECT_THROW(sweep::load_case_with(hover, "numerics.cycles", 2.5), InputError);
  EXPECT_THROW(sweep::load_case_with(hover, "kinematics.rotation_phase", 3.0), InputError);
  EXPECT_THROW(sweep::load_case_with(hover, "name.x", 1.0), InputError);
}

}  // namespace
