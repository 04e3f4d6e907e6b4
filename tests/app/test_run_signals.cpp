// SIGINT and SIGTERM during a run (issue: up to 19 computed steps lost, no summary.json):
// the step under way is finished, history.csv holds every step, summary.json says
// "interrupted", the exit status is 128 + signal (130, 143).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "signal_helpers.hpp"

namespace fs = std::filesystem;
using namespace flapsim::test;

namespace {

// Starts `flapsim run CASE -o OUT -q`, waits until history.csv has rows, sends the signal
// and returns the exit status (-1 if it did not exit normally).
int interrupted_run(const ScratchDir& dir, int signal_number) {
  // 24 x 200 steps with a wake of at most 12 rows: long enough to be interrupted.
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 200, 0, "wake_max_rows = 12\n");
  return signal_flapsim_once_history_grows({"run", (dir / "case.toml").string(), "-o", (dir / "out").string(), "-q"},
                                           dir / "out" / "history.csv", signal_number);
}

// "steps": N of summary.json.
long summary_steps(const std::string& summary) {
  const auto at = summary.find("\"steps\": ");
  return at == std::string::npos ? -1 : std::strtol(summary.c_str() + at + 9, nullptr, 10);
}

void expect_interrupted_outputs(const ScratchDir& dir) {
  const std::string summary = read_text(dir / "out" / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"interrupted\""), std::string::npos) << summary;
  // Every computed step is in history.csv: one row per step of the summary.
  const std::string history = read_text(dir / "out" / "history.csv");
  const long rows = static_cast<long>(std::count(history.begin(), history.end(), '\n')) - 1;
  EXPECT_GT(rows, 20);
  EXPECT_EQ(rows, summary_steps(summary)) << summary;
  EXPECT_LT(rows, 24 * 200);
  EXPECT_TRUE(dir.temporaries().empty());
  EXPECT_NE(read_text(dir / "out" / "flapsim_outputs.toml").find("interrupted"), std::string::npos);
}

TEST(RunSignals, SigintFinishesTheStepWritesTheSummaryAndExits130) {
  ScratchDir dir("run_sigint");
  EXPECT_EQ(interrupted_run(dir, SIGINT), 130);
  expect_interrupted_outputs(dir);
}

TEST(RunSignals, SigtermFinishesTheStepWritesTheSummaryAndExits143) {
  ScratchDir dir("run_sigterm");
  EXPECT_EQ(interrupted_run(dir, SIGTERM), 143);
  expect_interrupted_outputs(dir);
}

}  // namespace
