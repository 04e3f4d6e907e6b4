// Lua et al.'s flapping wing (cases/lua_rigid.toml, eq. 7 of the rotation-phase paper) with
// the shed leading edge, over many cycles (docs/uvlm.md, "Lua et al.'s hover over many
// cycles"). The wing meets the sheet it shed at every reversal and its cycles do not
// repeat: their mean CL scatters by 7–8 % from cycle to cycle. The result is the mean
// over the cycles from the second on, summary.json's settled_mean_CL, known to within its
// standard error.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "shipped_case_text.hpp"

TEST(LuaShedManyCycles, TheMeanLiftOverThirtyCyclesIsWithinFivePercentOfTheMeasurement) {
  // Lua et al. (Exp. Fluids 2010) measured a mean CL of 2.08 on this wing and motion (RP
  // §2, Fig. 8); issue 30 asks `shed` for 5 %. Measured (1 Dec): at 50 steps a cycle and 30
  // cycles the mean of cycles 2–30 is 2.1448 (+3.1 %), its standard error 0.0300 (1.4 %), the
  // cycles' standard deviation 0.1615 (7.5 %); over 60 cycles 2.159, at 100 steps a cycle
  // 2.179; over 150 cycles 2.146 (50 steps), 2.188 (100), 2.133 (200) (docs/uvlm.md). The
  // standard error below 2 % of the mean makes the 5 % a statement about the model, not
  // about the cycles that happened to be run.
  flapsim::test::ScratchDir dir("lua_shed_many_cycles");
  std::string toml = flapsim::test::shipped_case_text("lua_rigid");
  toml = std::regex_replace(toml, std::regex("\nsteps_per_cycle = 100"), "\nsteps_per_cycle = 50");
  toml = std::regex_replace(toml, std::regex("\ncycles = 6 "), "\ncycles = 30 ");
  toml = std::regex_replace(toml, std::regex("\nvtk_every = 10"), "\nvtk_every = 0");
  toml = std::regex_replace(toml, std::regex("\\[numerics\\]\n"), "[numerics]\nleading_edge = \"shed\"\n");
  ASSERT_NE(toml.find("steps_per_cycle = 50"), std::string::npos);
  ASSERT_NE(toml.find("cycles = 30 "), std::string::npos);
  std::ofstream(dir / "case.toml") << toml;
  ASSERT_EQ(flapsim::test::run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 0);
  const std::string summary = flapsim::test::read_text(dir / "out" / "summary.json");
  EXPECT_EQ(flapsim::test::json_number(summary, "settled_cycles"), 29.0);
  const double cl = flapsim::test::json_number(summary, "settled_mean_CL");
  const double error = flapsim::test::json_number(summary, "settled_CL_standard_error");
  EXPECT_NEAR(cl, 2.08, 0.05 * 2.08);
  EXPECT_LT(error, 0.02 * cl);
  // The cycles do scatter (else the last cycle's mean would do): by more than 3 %.
  EXPECT_GT(flapsim::test::json_number(summary, "cycle_CL_deviation"), 0.03 * cl);
}
