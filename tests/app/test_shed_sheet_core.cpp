// The leading-edge sheet's own core (numerics.sheet_core_radius; docs/uvlm.md, "The sheet's
// core"): in a hover the wing sweeps back through the sheet it shed, and with the wake's
// core (0.2 mean chords in cases/bench_hover.toml) the shedding each step needs to hold the
// LESP, and with it ∂Γ/∂t and the lift, jumps from step to step from the first reversal on;
// a sheet core of 0.5 mean chords keeps the lift as smooth as in the first half-stroke.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "history_csv.hpp"
#include "history_roughness.hpp"
#include "shipped_case_text.hpp"

namespace {

/// The roughness of a lift history [mN] over steps [first, last) (history_roughness.hpp).
constexpr auto roughness = flapsim::test::second_difference_rms;

/// Lift [mN] of each step of cases/bench_hover.toml (the rigid hawkmoth hover, free wake,
/// 100 steps a wingbeat) flown for 2 wingbeats with a shed leading edge, its sheet unmerged,
/// and `numerics` added; `completes`: whether the run must end with exit status 0.
std::vector<double> hover_lift_mn(const std::string& folder, const std::string& numerics, bool completes) {
  flapsim::test::ScratchDir dir(folder);
  std::string toml = flapsim::test::shipped_case_text("bench_hover");
  toml = std::regex_replace(toml, std::regex("cycles = 3"), "cycles = 2");
  toml = std::regex_replace(toml, std::regex("\\[numerics\\]\n"),
                            "[numerics]\nleading_edge = \"shed\"\nsheet_merge_steps = 0\n" + numerics);
  EXPECT_NE(toml.find("cycles = 2"), std::string::npos);
  std::ofstream(dir / "case.toml") << toml;
  const auto outcome =
      flapsim::test::run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  if (completes) {
    EXPECT_EQ(outcome.status, 0) << outcome.err;
  }
  std::vector<double> lift = flapsim::test::read_history_csv(dir / "out" / "history.csv").column("lift_N");
  for (double& l : lift) l *= 1e3;
  return lift;
}

}  // namespace

TEST(ShedSheetCore, ASheetCoreOfHalfAChordKeepsTheHoversLiftSmoothWhereTheWingMeetsItsSheet) {
  // Measured (29 Nov): the roughness of steps 1–45 (the first half-stroke, before the wing
  // meets its sheet) 0.233 mN with the wake's core (0.2 mean chords) and 0.230 with 0.5; of
  // steps 50–150 (the second half-stroke and the start of the third) 15.7 and 0.50 mN. The
  // bounds: 0.5 and 1.0 mN, twice what the smooth runs measured; 3 mN, a fifth of the rough
  // run's (docs/uvlm.md, "Why the shed hover's lift is rough: the sheet's core").
  // (With the wake's core the run stops at step 192, the lattice diverged: test
  // DivergedForce.TheRigidHoverWithAShedLeadingEdge…; here only its first 150 steps count.)
  const std::vector<double> fine = hover_lift_mn("sheet_core_wake", "", false);
  const std::vector<double> wide = hover_lift_mn("sheet_core_half_chord", "sheet_core_radius = 0.5\n", true);
  ASSERT_GE(fine.size(), 151u);
  ASSERT_EQ(wide.size(), 200u);
  std::printf("[ value ] roughness of steps 1-45: %.3f (core 0.2), %.3f (0.5) mN; of steps 50-150: %.3f, %.3f mN\n",
              roughness(fine, 1, 45), roughness(wide, 1, 45), roughness(fine, 50, 150), roughness(wide, 50, 150));
  EXPECT_LT(roughness(fine, 1, 45), 0.5);
  EXPECT_LT(roughness(wide, 1, 45), 0.5);
  EXPECT_GT(roughness(fine, 50, 150), 3.0);
  EXPECT_LT(roughness(wide, 50, 150), 1.0);
}
