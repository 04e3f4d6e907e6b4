// The case `make run` runs (cases/hover_flexible.toml) must give a result that does not
// hinge on round-off: its last-cycle mean lift is what a user reads first. With the wake
// cut to its newest 100 rows (the case before 26 Nov 2026) it did: joint springs scaled by
// 1 + 1e-9 and 1 − 1e-9 gave 8.2366 and 8.4246 mN (2.2 % apart; a gmsh element order had
// moved it by 0.36 %). With the wake convected as a whole after half a cycle
// (far_wake_cycles, as the phase study) the two give 8.42134 and 8.42133 mN (8.39845 mN
// both with the trailing-edge rule of issue 29). Here with the shipped chain
// cases/chains/hawkmoth_10_bodies.toml (no reduction needed): 7.02771 and 7.02758 mN
// (1.9e-5 apart; 7.03270 and 7.03285 mN, 2.2e-5, with the rule of issue 29); with the cut
// wake 6.7575 and 6.8491 mN (1.3e-2): bound 1e-3.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

const std::string kSource = FLAPSIM_SOURCE_DIR;

/// mean_lift_N of hover_flexible with the shipped 10-body hawkmoth chain, springs scaled by s.
double mean_lift(const flapsim::test::ScratchDir& dir, const std::string& s) {
  const auto out = dir / ("s" + s);
  EXPECT_EQ(flapsim::test::run_flapsim("run " + kSource + "/cases/hover_flexible.toml --chain " + kSource +
                                       "/cases/chains/hawkmoth_10_bodies.toml --vtk-every 0 --spring-scale " + s +
                                       " -o " + out.string()),
            0);
  return flapsim::test::json_number(flapsim::test::read_text(out / "summary.json"), "mean_lift_N");
}

}  // namespace

TEST(HoverFlexibleCase, ItsMeanLiftDoesNotHingeOnRoundOff) {
  flapsim::test::ScratchDir dir("hover_flexible_round_off");
  const double up = mean_lift(dir, "1.000000001"), down = mean_lift(dir, "0.999999999");
  std::printf("[ value ] hover_flexible mean lift, springs x (1 +- 1e-9): %.6g and %.6g N (%.2g relative)\n", up, down,
              up / down - 1.0);
  ASSERT_TRUE(std::isfinite(up) && std::isfinite(down));
  EXPECT_GT(down, 0.0);
  EXPECT_NEAR(up / down, 1.0, 1e-3);  // springs 2e-9 apart
}
