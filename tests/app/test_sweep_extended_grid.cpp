// A sweep run again with its grid extended at the start: the case folders are named by
// index and values (`01_-0.1`), so every earlier case gets a new index; its results are
// found by their inputs hash, moved to the new folder and kept, not run again
// (pipeline/app/sweep/earlier_cases; docs/sweeps.md, "Resuming a sweep").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

std::set<std::string> sub_folders(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_directory()) names.insert(e.path().filename().string());
  return names;
}

TEST(SweepExtendedGrid, CasesOfTheEarlierGridAreKeptUnderTheirNewIndex) {
  const test::ScratchDir dir("sweep_extended");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  const std::string base = "sweep " + (dir / "case.toml").string() + " -j 1 -q -o " + (dir / "out").string();
  ASSERT_EQ(test::run_flapsim(base + " --vary kinematics.rotation_phase=-0.1:0.1:0.1"), 0);
  EXPECT_EQ(sub_folders(dir / "out"), (std::set<std::string>{"00_-0.1", "01_0", "02_0.1"}));
  const std::string summary_0 = test::read_text(dir / "out" / "01_0" / "summary.json");

  // One value more at the start: -0.2 is case 0, the three earlier cases become 1..3.
  ASSERT_EQ(test::run_flapsim(base + " --vary kinematics.rotation_phase=-0.2:0.1:0.1"), 0);
  const auto table = test::read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_EQ(table.rows.size(), 4u);
  EXPECT_EQ(table.rows[0].at("message"), "");  // the new case ran
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(table.rows[i].at("message"), "kept") << i;
  // Only the new grid's folders: the earlier ones were moved, none left beside them.
  EXPECT_EQ(sub_folders(dir / "out"), (std::set<std::string>{"00_-0.2", "01_-0.1", "02_0", "03_0.1"}));
  EXPECT_EQ(test::read_text(dir / "out" / "02_0" / "summary.json"), summary_0);  // not run again
}

}  // namespace

namespace {

// Two rows of a case table with the same inputs hash (a rigid wing's joint springs' factor,
// which it has none of: rows 1 and 2; the flexible rows make the factor a key the sweep uses,
// and values given twice are refused since 6 Dec): the second case, its folder deleted, must
// run again into its own folder, not take the first case's folder away (which the first
// row's "kept" names).
TEST(SweepExtendedGrid, ACaseNeverTakesTheFolderOfAnotherCaseOfTheSameSweep) {
  const test::ScratchDir dir("sweep_same_rows");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  std::ofstream(dir / "cases.csv") << "structure.kind,structure.bodies,spring_scale\nrigid,1,1\nrigid,1,2\n"
                                      "flexible,3,1\nflexible,3,2\n";
  const std::string args = "sweep " + (dir / "case.toml").string() + " --cases " + (dir / "cases.csv").string() +
                           " -j 1 -q -o " + (dir / "out").string();
  ASSERT_EQ(test::run_flapsim(args), 0);
  const std::set<std::string> folders = sub_folders(dir / "out");
  ASSERT_EQ(folders.size(), 4u);
  const std::string second = *std::next(folders.begin());  // row 2, rigid with the factor 2
  ASSERT_EQ(second.rfind("01_", 0), 0u) << second;
  fs::remove_all(dir / "out" / second);
  ASSERT_EQ(test::run_flapsim(args), 0);
  EXPECT_EQ(sub_folders(dir / "out"), folders);
  const auto table = test::read_sweep_table((dir / "out" / "sweep.csv").string());
  ASSERT_EQ(table.rows.size(), 4u);
  EXPECT_EQ(table.rows[0].at("message"), "kept");
  EXPECT_EQ(table.rows[1].at("message"), "");  // ran again
  EXPECT_EQ(table.rows[1].at("folder"), second);
}

}  // namespace
