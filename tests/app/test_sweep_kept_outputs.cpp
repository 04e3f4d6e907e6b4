// A sweep run again with --vtk-every (for pictures of cases an earlier run computed without
// them) runs the cases whose folders hold no ParaView series; it kept them all and wrote
// none (pipeline/app/sweep/sweep_runner; docs/sweeps.md, "Resuming a sweep").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

TEST(SweepKeptOutputs, ARerunAskingForParaViewSeriesRunsTheCasesThatHaveNone) {
  const test::ScratchDir dir("sweep_kept_vtk");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(8);
  const std::string base = "sweep " + (dir / "case.toml").string() +
                           " --vary kinematics.rotation_phase=0,0.1 -j 1 -q -o " + (dir / "out").string();
  ASSERT_EQ(test::run_flapsim(base), 0);
  EXPECT_FALSE(fs::exists(dir / "out" / "00_0" / "chain.pvd"));

  ASSERT_EQ(test::run_flapsim(base + " --vtk-every 4"), 0);
  const auto table = test::read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_EQ(table.rows.size(), 2u);
  for (const auto& row : table.rows) {
    EXPECT_EQ(row.at("message"), "") << row.at("folder");  // ran, not "kept"
    for (const char* series : {"chain.pvd", "wing.pvd", "wake.pvd"})
      EXPECT_TRUE(fs::exists(dir / "out" / row.at("folder") / series)) << row.at("folder") << " " << series;
  }
  // Now that they have their series, the same command keeps them.
  ASSERT_EQ(test::run_flapsim(base + " --vtk-every 4"), 0);
  for (const auto& row : test::read_sweep_table((dir / "out" / "sweep.csv").string()).rows)
    EXPECT_EQ(row.at("message"), "kept") << row.at("folder");
}

}  // namespace
