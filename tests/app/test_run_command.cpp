// `flapsim run` and `flapsim sweep` as users run them: outputs of a small rigid case,
// exit status 2 for a flexible case without a chain (nothing written), exit status 3
// with valid outputs when the chain diverges, and a two-value sweep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "robustness_helpers.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {

using flapsim::test::read_text;
using flapsim::test::run_flapsim;

const std::string kSource = FLAPSIM_SOURCE_DIR;

// The flat plate of wings/flat_plate.toml with eq. 8 kinematics, 3 x 4 panels, one cycle
// of 24 steps: seconds even under ASan.
std::string plate_case(const std::string& kind, const std::string& extra = "") {
  return "name = \"plate\"\nwing = \"" + kSource + "/wings/flat_plate.toml\"\n" + extra +
         "[kinematics]\nfrequency_hz = 26.1\nrotation_phase = -0.1\n"
         "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"
         "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
         "[structure]\nkind = \"" + kind + "\"\n" + (kind == "flexible" ? "bodies = 2\n" : "") +
         "[numerics]\nsteps_per_cycle = 24\ncycles = 1\nchordwise_panels = 3\nspanwise_panels = 4\n"
         "core_radius = 0.2\n[output]\nvtk_every = 6\n";
}

TEST(FsiRunCommand, RigidCaseWritesHistorySummaryAndSeries) {
  flapsim::test::ScratchDir dir("fsi_run_rigid");
  std::ofstream(dir / "case.toml") << plate_case("rigid");
  ASSERT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 0);
  for (const char* f : {"history.csv", "summary.json", "wing.pvd", "wake.pvd", "chain.pvd"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  const std::string summary = read_text(dir / "out" / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"ok\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"mean_lift_N\""), std::string::npos);
  // The measured base rotation phase is the case's δψ = −0.1 (phase_analysis on eq. 8;
  // 24 samples per cycle leave an interpolation error well under 1e-3).
  const auto at = summary.find("\"base_rotation_phase\": ");
  ASSERT_NE(at, std::string::npos) << summary;
  EXPECT_NEAR(std::strtod(summary.c_str() + at + 23, nullptr), -0.1, 1e-3) << summary;
  EXPECT_TRUE(dir.temporaries().empty());
}

TEST(FsiRunCommand, MissingChainFileIsBadInputAndWritesNothing) {
  flapsim::test::ScratchDir dir("fsi_run_nochain");
  std::ofstream(dir / "case.toml") << plate_case("flexible");
  EXPECT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " --chain " + (dir / "missing.toml").string() +
                    " -o " + (dir / "out").string()),
            2);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(FsiRunCommand, FlexibleCaseWithOnlyAWingIsReducedInProcess) {
  // structure.bodies = 2 bodies from the flat plate's FEM (fem + reduction, no files).
  flapsim::test::ScratchDir dir("fsi_run_reduce");
  std::ofstream(dir / "case.toml") << plate_case("flexible");
  ASSERT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 0);
  const std::string summary = read_text(dir / "out" / "summary.json");
  EXPECT_NE(summary.find("wing reduced in process (FEM + reduction, 2 bodies)"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"status\": \"ok\""), std::string::npos) << summary;
}

TEST(FsiRunCommand, DivergingChainExitsThreeAndKeepsItsOutputs) {
  // A two-body chain whose outer joint has almost no stiffness and a heavy tip flails
  // and the implicit step fails: exit status 3, summary "failed", history still a CSV.
  flapsim::test::ScratchDir dir("fsi_run_diverge");
  std::ofstream(dir / "chain.toml")
      << flapsim::test::kDivergingTwoBodyChain;
  std::string c = plate_case("flexible");
  c.replace(c.find("steps_per_cycle = 24"), 20, "steps_per_cycle = 4");
  c.replace(c.find("cycles = 1"), 10, "cycles = 40");
  std::ofstream(dir / "case.toml") << c;
  const int status = run_flapsim("run " + (dir / "case.toml").string() + " --chain " +
                             (dir / "chain.toml").string() + " -o " + (dir / "out").string());
  // Deterministic: this chain diverges on every run (measured: exit 3), so anything else fails.
  ASSERT_EQ(status, 3);
  EXPECT_NE(read_text(dir / "out" / "summary.json").find("\"status\": \"failed\""), std::string::npos);
  EXPECT_EQ(read_text(dir / "out" / "history.csv").rfind("t_s,", 0), 0u);
  EXPECT_TRUE(dir.temporaries().empty());
}

TEST(FsiSweepCommand, TwoValuesTwoFoldersOneTable) {
  flapsim::test::ScratchDir dir("fsi_sweep");
  std::ofstream(dir / "case.toml") << plate_case("rigid");
  ASSERT_EQ(run_flapsim("sweep " + (dir / "case.toml").string() +
                    " --vary kinematics.rotation_phase=-0.1,0.05 -j 2 -o " + (dir / "out").string()),
            0);
  const std::string table = read_text(dir / "out" / "sweep.csv");
  EXPECT_EQ(table.rfind("kinematics.rotation_phase,mean_lift_N", 0), 0u) << table;
  EXPECT_TRUE(fs::exists(dir / "out" / "00_-0.1" / "summary.json"));
  EXPECT_TRUE(fs::exists(dir / "out" / "01_0.05" / "summary.json"));
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 3);
}

}  // namespace
