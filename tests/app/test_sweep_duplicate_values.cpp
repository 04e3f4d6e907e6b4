// A sweep's value given twice ran its case twice, in two folders (01_12, 02_12), without a
// word; a wing file named by two paths beside a third wing did the same, and two paths alone
// were refused as "the run does not use the key" (a user's sweeps, 6 Dec). Now refused at the
// key, naming the duplicate (pipeline/app/sweep/keys_that_change_nothing.cpp), nothing run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "sweep_test_helpers.hpp"

using namespace flapsim;

TEST(SweepDuplicateValues, AValueGivenTwiceOrOneFileByTwoPathsIsRefused) {
  const test::ScratchDir dir("sweep_duplicates");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(8);
  std::filesystem::copy_file(std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml", dir / "mine.toml");
  const auto sweep = [&](const std::string& vary) {
    return test::run_flapsim_capturing_stderr(
        dir.path(),
        "sweep " + (dir / "case.toml").string() + " --vary " + vary + " -o " + (dir / "out").string());
  };
  for (const std::string vary : {"kinematics.frequency_hz=10,12,12", "kinematics.frequency_hz=12,12.0"}) {
    const auto out = sweep(vary);
    EXPECT_EQ(out.status, 2) << vary << ": " << out.err;
    EXPECT_NE(out.err.find("key 'kinematics.frequency_hz'"), std::string::npos) << out.err;
    EXPECT_NE(out.err.find("12 is given twice: its case would run twice; give each value once"),
              std::string::npos)
        << out.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out")) << vary;
  }
  const std::string mine = (dir / "mine.toml").string();
  const auto paths = sweep("wing=" + mine + "," + dir.path().string() + "/./mine.toml," + FLAPSIM_SOURCE_DIR +
                           "/wings/hawkmoth.toml");
  EXPECT_EQ(paths.status, 2) << paths.err;
  EXPECT_NE(paths.err.find("give the same inputs"), std::string::npos) << paths.err;
  EXPECT_NE(paths.err.find("give one of them"), std::string::npos) << paths.err;
  // Distinct values run.
  EXPECT_EQ(sweep("kinematics.frequency_hz=10,12").status, 0);
}
