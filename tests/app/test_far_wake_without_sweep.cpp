// A case whose wing does not sweep (`sweep = 1.0`: a constant angle, the span axis keeps
// one direction) with a convected far wake (`far_wake_cycles`). The far wake moves with
// momentum theory's v_i = sqrt(T / (2 rho A)), A the disk the span sweeps
// (app::stroke_disk_area: Phi R^2 / 2 with stroke angle Phi = 0 here, so A = 0). Before,
// `check` exited 0 and `run` exited 4 with "system error: vortex lattice: a convected far
// wake needs a disk area..." (no file, line or key, no summary.json). Now both refuse the
// case as bad input at the key: exit 2, nothing written (docs/case_file.md, far_wake_cycles).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "robustness_helpers.hpp"

namespace {

using namespace flapsim::test;

TEST(FarWakeWithoutSweep, CheckAndRunRefuseItAtTheKey) {
  ScratchDir dir("far_wake_no_sweep");
  // far_wake_cycles is line 16 of the case (small_plate_case: core_radius on line 15).
  std::ofstream(dir / "case.toml") << replace_once(small_plate_case("rigid", 1, 0, "far_wake_cycles = 0.5\n"),
                                                   "sweep = { mean_deg = 10.0, cos_deg = [50.0] }", "sweep = 1.0");
  const std::string where = (dir / "case.toml").string() + ":16: key 'numerics.far_wake_cycles'";
  const FlapsimOutcome check = run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "case.toml").string());
  EXPECT_EQ(check.status, 2) << check.err;
  EXPECT_NE(check.err.find(where), std::string::npos) << check.err;
  const FlapsimOutcome run =
      run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_NE(run.err.find(where), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "summary.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "history.csv"));
  // The same wing sweeping (the shipped plate's +-50 deg) runs with its far wake.
  std::ofstream(dir / "sweeping.toml") << small_plate_case("rigid", 1, 0, "far_wake_cycles = 0.5\n");
  EXPECT_EQ(run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "sweeping.toml").string()).status, 0);
}

}  // namespace
