// A run ended by an output error still says in summary.json how far it got. Before: a run
// whose history.csv could not be written (a full disk, a file-size limit) exited 4 and left
// no summary.json at all (only the manifest said "failed"). Now summary.json, small, is
// written with status "failed" and the error, and the exit status stays 4.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

TEST(OutputErrorSummary, ARunWhoseHistoryCannotBeWrittenStillWritesAFailedSummary) {
  ScratchDir dir("output_error_summary");
  // 3 cycles x 24 steps: history.csv grows past 16 KiB; the summary is under 3 KiB.
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 3, 0);
  const auto out = dir / "out";
  ASSERT_EQ(run_flapsim_with_file_limit("run " + (dir / "case.toml").string() + " -o " + out.string(), 32), 4);
  const std::string summary = read_text(out / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"failed\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("output error: cannot write"), std::string::npos) << summary;
  EXPECT_NE(summary.find("history.csv"), std::string::npos) << summary;
  EXPECT_TRUE(truncated_files(dir, out).empty());
  EXPECT_TRUE(dir.temporaries().empty());
  // history.csv keeps the rows it had published: fewer than the steps computed.
  const std::string history = read_text(out / "history.csv");
  EXPECT_LT(std::count(history.begin(), history.end(), '\n'), 3 * 24 + 1);
}

TEST(OutputErrorSummary, AnOutputErrorBeforeTheFirstStepStillWritesAFailedSummary) {
  // The series' files and run.pvsm (about 30 KiB) are written before the first step. Before:
  // an error there (a file-size limit of 8 KiB, a file named vtk where the frames go) exited 4
  // with no summary.json, though the summary (about 2 KiB) fits.
  ScratchDir dir("output_error_summary_start");
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 1, 1);
  const auto limited = dir / "limited";
  ASSERT_EQ(run_flapsim_with_file_limit("run " + (dir / "case.toml").string() + " -o " + limited.string(), 8),
            4);
  const std::string summary = read_text(limited / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"failed\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("run.pvsm"), std::string::npos) << summary;
  EXPECT_TRUE(truncated_files(dir, limited).empty());
  // A file where the frames' folder goes.
  const auto blocked = dir / "blocked";
  std::filesystem::create_directories(blocked);
  std::ofstream(blocked / "vtk") << "not a folder\n";
  ASSERT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + blocked.string()), 4);
  const std::string blocked_summary = read_text(blocked / "summary.json");
  EXPECT_NE(blocked_summary.find("\"status\": \"failed\""), std::string::npos) << blocked_summary;
  EXPECT_NE(blocked_summary.find("vtk"), std::string::npos) << blocked_summary;
  EXPECT_TRUE(dir.temporaries().empty());
}

}  // namespace
