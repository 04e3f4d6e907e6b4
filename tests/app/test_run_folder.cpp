// The output folder of a run: one run per folder (no stale outputs of an earlier run,
// no replacing another command's files without --force), the case name never a path,
// and the estimate of a run that cannot fit in memory.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "robustness_helpers.hpp"

namespace fs = std::filesystem;
using namespace flapsim::test;

namespace {

int count_files(const fs::path& dir, const std::string& prefix) {
  int n = 0;
  if (!fs::exists(dir)) return 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().rfind(prefix, 0) == 0;
  return n;
}

TEST(RunFolder, AShorterRerunLeavesNoStaleSeriesFiles) {
  // The issue: 270 stale .vtp after a shorter rerun into the same folder.
  ScratchDir dir("run_folder_rerun");
  std::ofstream(dir / "long.toml") << small_plate_case("rigid", 2, 1);   // 48 steps
  std::ofstream(dir / "short.toml") << small_plate_case("rigid", 1, 6);  // 24 steps, every 6th
  const std::string out = " -o " + (dir / "out").string();
  ASSERT_EQ(run_flapsim("run " + (dir / "long.toml").string() + out), 0);
  EXPECT_EQ(count_files(dir / "out" / "vtk", "wing_"), 49);  // steps 0 (the initial pose) ... 48
  ASSERT_EQ(run_flapsim("run " + (dir / "short.toml").string() + out), 0);
  EXPECT_EQ(count_files(dir / "out" / "vtk", "wing_"), 5);  // steps 0, 6, 12, 18, 24
  EXPECT_EQ(count_files(dir / "out" / "vtk", "chain_"), 5);
  EXPECT_NE(read_text(dir / "out" / "flapsim_outputs.toml").find("complete"), std::string::npos);
}

TEST(RunFolder, ARerunRemovesTheDiskReserveAKilledRunLeft) {
  // A run killed by SIGKILL leaves its 64 KiB reserve (pipeline/io/output_manifest.cpp); a
  // rerun into the folder used to keep it for good.
  ScratchDir dir("run_folder_killed_reserve");
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 1, 0);
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / ".flapsim_outputs_reserve.tmp.999999999") << std::string(1024, '\0');
  ASSERT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 0);
  EXPECT_EQ(count_files(dir / "out", ".flapsim_outputs_reserve"), 0);
  EXPECT_TRUE(dir.temporaries().empty());
}

TEST(RunFolder, RunIntoAReduceFolderNeedsForce) {
  // run -o into a reduce folder replaced reduce's summary.json.
  ScratchDir dir("run_folder_clash");
  const std::string out = " -o " + (dir / "out").string();
  ASSERT_EQ(run_flapsim("reduce " + kSourceDir + "/tests/data/valid_tiny_wing.toml --bodies 2 --modes 4" + out), 0);
  const std::string reduce_summary = read_text(dir / "out" / "summary.json");
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 1, 0);
  EXPECT_EQ(run_flapsim("run " + (dir / "case.toml").string() + out), 4);
  EXPECT_EQ(read_text(dir / "out" / "summary.json"), reduce_summary);
  EXPECT_TRUE(fs::exists(dir / "out" / "chain.toml"));
  EXPECT_EQ(run_flapsim("run " + (dir / "case.toml").string() + out + " --force"), 0);
  EXPECT_FALSE(fs::exists(dir / "out" / "chain.toml"));
  EXPECT_NE(read_text(dir / "out" / "summary.json").find("\"status\": \"ok\""), std::string::npos);
}

TEST(RunFolder, ACaseNameThatIsAPathIsRefusedAndWritesNothing) {
  // name = "../../x" wrote outside out/ (the default folder is out/<name>).
  ScratchDir dir("run_folder_name");
  fs::create_directories(dir / "work");
  std::ofstream(dir / "work" / "case.toml")
      << replace_once(small_plate_case("rigid", 1, 0), "name = \"plate\"", "name = \"../../x\"");
  const std::string cmd = "cd '" + (dir / "work").string() + "' && exec";
  EXPECT_EQ(run_flapsim_in_shell(cmd, "run case.toml"), 2);
  EXPECT_FALSE(fs::exists(dir / "x"));
  EXPECT_FALSE(fs::exists(dir / "work" / "out"));
}

TEST(RunFolder, ARunThatCannotFitInMemoryIsRefusedBeforeItStarts) {
  // 10^8 steps with 1000 spanwise panels: a free wake of 10^11 panels, terabytes. The run
  // printed nothing and started (2e9 steps), or died of std::bad_alloc with exit 1.
  ScratchDir dir("run_folder_estimate");
  std::string c = small_plate_case("rigid", 100, 0);
  c = replace_once(c, "steps_per_cycle = 24", "steps_per_cycle = 1000000");
  c = replace_once(c, "spanwise_panels = 4", "spanwise_panels = 1000");
  std::ofstream(dir / "case.toml") << c;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string(),
                        dir / "stdout.txt"),
            2);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(60));
  EXPECT_FALSE(fs::exists(dir / "out"));
  // check says the same, with the estimate.
  EXPECT_EQ(run_flapsim("check " + (dir / "case.toml").string()), 2);
}

}  // namespace
