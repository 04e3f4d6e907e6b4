// The shed leading edge's sheet merged with each merge spread over several releases
// (numerics.sheet_merge_spread_steps; uvlm/leading_edge_sheet.hpp, "Merging the older
// rings"; docs/uvlm.md, "Merging the sheet's older rings"): in a hover the sheet stays within
// a chord of the wing, and a merge done at once (the default) moves the sheet's velocity at
// the wing within one step, which the wing's circulation answers with ρ ∂Γ/∂t ∝ 1/Δt: a spike
// in the lift.
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

TEST(ShedMergeSpread, TheRigidHoversLiftStaysSmoothInEveryWingbeatWithItsMergesSpreadOverFourReleases) {
  // cases/rotation_phase_rigid.toml (the rigid hawkmoth hover, δψ = 0, 4 wingbeats of 100
  // steps) with `leading_edge = "shed"`, merged from 8 steps old (the default) and each merge
  // spread over 4 releases. Roughness of each wingbeat from the 2nd (steps 100–199, …),
  // measured 1 Dec: spread 0.96, 0.75, 0.91; at once (the default) 1.84, 3.06, 2.38; never
  // merged 0.92, 0.87, 0.77 (docs/uvlm.md's table); `separated` 0.04. Bound: 1.4, between the
  // spread and the at-once runs' every wingbeat (one realisation each of a flow that meets
  // its own sheet).
  flapsim::test::ScratchDir dir("shed_merge_spread");
  std::string toml = flapsim::test::shipped_case_text("rotation_phase_rigid");
  toml = std::regex_replace(toml, std::regex("\nvtk_every = 10"), "\nvtk_every = 0");
  toml = std::regex_replace(toml, std::regex("\\[numerics\\]\n"),
                            "[numerics]\nleading_edge = \"shed\"\nsheet_merge_spread_steps = 4\n");
  ASSERT_NE(toml.find("\ncycles = 4"), std::string::npos) << "cases/rotation_phase_rigid.toml has changed";
  ASSERT_NE(toml.find("steps_per_cycle = 100"), std::string::npos);
  ASSERT_NE(toml.find("vtk_every = 0"), std::string::npos);
  std::ofstream(dir / "case.toml") << toml;
  ASSERT_EQ(
      flapsim::test::run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 0);
  const std::vector<double> cl = flapsim::test::read_history_csv(dir / "out" / "history.csv").column("CL");
  ASSERT_EQ(cl.size(), 400u);
  for (std::size_t beat = 1; beat < 4; ++beat) {
    const double r =
        flapsim::test::second_difference_rms(cl, 100 * beat, std::min<std::size_t>(100 * beat + 100, 399));
    std::printf("[ value ] wingbeat %zu: roughness of CL %.3f\n", beat + 1, r);
    EXPECT_LT(r, 1.4) << "wingbeat " << beat + 1;
  }
}
