// A sweep run again with --vtk-every (for pictures of cases an earlier run computed without
// them) runs the cases whose folders hold no ParaView series; it kept them all and wrote
// none (pipeline/app/sweep/sweep_runner; docs/sweeps.md, "Resuming a sweep").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/stiff_plate_wing.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

TEST(SweepKeptOutputs, ARerunAskingForParaViewSeriesRunsTheCasesThatHaveNone) {
  const test::ScratchDir dir("sweep_kept_vtk");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
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

// A case run again (here --force, without --vtk-every) starts from an empty folder: the
// earlier run's ParaView series stayed beside the new history.csv and summary.json.
TEST(SweepKeptOutputs, ACaseRunAgainLeavesNoEarlierSeriesBesideItsNewResults) {
  const test::ScratchDir dir("sweep_rerun_clears");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  const std::string base = "sweep " + (dir / "case.toml").string() +
                           " --vary kinematics.rotation_phase=0,0.1 -j 1 -q -o " + (dir / "out").string();
  ASSERT_EQ(test::run_flapsim(base + " --vtk-every 4"), 0);
  ASSERT_TRUE(fs::exists(dir / "out" / "00_0" / "chain.pvd"));
  ASSERT_EQ(test::run_flapsim(base + " --force"), 0);
  for (const char* folder : {"00_0", "01_0.1"}) {
    EXPECT_TRUE(fs::exists(dir / "out" / folder / "summary.json")) << folder;
    for (const char* stale : {"chain.pvd", "wing.pvd", "wake.pvd", "run.pvsm", "tip_path.vtp", "vtk"})
      EXPECT_FALSE(fs::exists(dir / "out" / folder / stale)) << folder << " " << stale;
  }
}

// The FEM's series is fem.pvd: a FEM sweep run again with --vtk-every looked for chain.pvd,
// found none, and ran every finished case again (a resumed sweep of films redid them all).
TEST(SweepKeptOutputs, AFemSweepWithItsSeriesIsKeptWhenRunAgain) {
  const test::ScratchDir dir("sweep_kept_vtk_fem");
  std::ofstream(dir / "wing.toml") << test::kStiffPlateWing;
  std::ofstream(dir / "case.toml")
      << "name = \"stiff_fem\"\nwing = \"wing.toml\"\n"
         "[kinematics]\nfrequency_hz = 26.1\nsweep = { mean_deg = 10.0, cos_deg = [20.0] }\n"
         "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n[structure]\nkind = \"fem\"\n"
         "[numerics]\nsteps_per_cycle = 24\ncycles = 1\nchordwise_panels = 3\nspanwise_panels = 4\n"
         "core_radius = 0.2\nrho_infinity = 0.0\n";
  const std::string command = "sweep " + (dir / "case.toml").string() +
                              " --vary kinematics.rotation_phase=0,0.1 -j 1 -q --vtk-every 4 -o " + (dir / "out").string();
  ASSERT_EQ(test::run_flapsim(command), 0);
  for (const auto& row : test::read_sweep_table((dir / "out" / "sweep.csv").string()).rows)
    EXPECT_TRUE(fs::exists(dir / "out" / row.at("folder") / "fem.pvd")) << row.at("folder");
  ASSERT_EQ(test::run_flapsim(command), 0);
  const auto table = test::read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_EQ(table.rows.size(), 2u);
  for (const auto& row : table.rows) EXPECT_EQ(row.at("message"), "kept") << row.at("folder");
}

// The case file's [output] vtk_every decides only which files a run writes, and a sweep's
// own --vtk-every replaces it for every case: editing it keeps every finished case. It was
// part of the inputs hash (io::input_hash), so the same sweep after the edit ran every case
// again. The series the sweep asks for are still checked: a case kept by its hash but run
// without them runs again when --vtk-every asks for them, and a case with series is kept
// when none are asked for.
TEST(SweepKeptOutputs, ACaseFileIntervalEditedKeepsEveryFinishedCase) {
  const test::ScratchDir dir("sweep_kept_interval");
  std::string text = test::tiny_plate_case(24);  // [output] vtk_every = 0
  std::ofstream(dir / "case.toml") << text;
  const std::string base = "sweep " + (dir / "case.toml").string() +
                           " --vary kinematics.rotation_phase=0,0.1 -j 1 -q -o " + (dir / "out").string();
  const auto messages_of_interval_sweep = [&dir] {
    std::vector<std::string> messages;
    for (const auto& row : test::read_sweep_table((dir / "out" / "sweep.csv").string()).rows)
      messages.push_back(row.at("message"));
    return messages;
  };
  ASSERT_EQ(test::run_flapsim(base), 0);
  ASSERT_EQ(messages_of_interval_sweep(), (std::vector<std::string>{"", ""}));  // both ran

  // The case's interval edited: the same inputs, every case kept.
  text.replace(text.find("vtk_every = 0"), 13, "vtk_every = 5");
  std::ofstream(dir / "case.toml") << text;
  ASSERT_EQ(test::run_flapsim(base), 0);
  EXPECT_EQ(messages_of_interval_sweep(), (std::vector<std::string>{"kept", "kept"}));

  // Series asked for: the cases kept by their hash have none, so they run and write them.
  ASSERT_EQ(test::run_flapsim(base + " --vtk-every 4"), 0);
  EXPECT_EQ(messages_of_interval_sweep(), (std::vector<std::string>{"", ""}));
  for (const char* folder : {"00_0", "01_0.1"})
    EXPECT_TRUE(fs::exists(dir / "out" / folder / "chain.pvd")) << folder;

  // No series asked for: the cases with series are kept (and keep their series).
  ASSERT_EQ(test::run_flapsim(base), 0);
  EXPECT_EQ(messages_of_interval_sweep(), (std::vector<std::string>{"kept", "kept"}));
  for (const char* folder : {"00_0", "01_0.1"})
    EXPECT_TRUE(fs::exists(dir / "out" / folder / "chain.pvd")) << folder;
}

}  // namespace
