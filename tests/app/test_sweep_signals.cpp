// SIGINT and SIGTERM during a sweep. Before: the sweep was killed at once (exit 143 with no
// message), the case under way left `history.csv.tmp.<pid>` beside a history.csv and no
// summary.json, and sweep.csv did not list it. Now, as for `flapsim run` (docs/reliability.md):
// the cases under way finish their step and write summary.json ("interrupted"), no further
// case starts, sweep.csv lists the case as "interrupted", the exit status is 128 + signal,
// and the same command again runs what is left.
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

// Starts a three-case sweep of a long run, one case at a time, waits until the first case's
// history.csv has rows, sends the signal; returns the exit status (-1: no normal exit).
// `extra_numerics`: more [numerics] lines (a key the case file warns about).
int interrupted_sweep(const ScratchDir& dir, int signal_number, const std::string& extra_numerics = "") {
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 200, 0,
                                                       "wake_max_rows = 12\n" + extra_numerics);
  return signal_flapsim_once_history_grows(
      {"sweep", (dir / "case.toml").string(), "--vary", "kinematics.rotation_phase=-0.1,0,0.1", "-j", "1", "-o",
       (dir / "out").string(), "-q"},
      dir / "out" / "00_-0.1" / "history.csv", signal_number);
}

void expect_interrupted_sweep(const ScratchDir& dir) {
  const std::string summary = read_text(dir / "out" / "00_-0.1" / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"interrupted\""), std::string::npos) << summary;
  const std::string table = read_text(dir / "out" / "sweep.csv");
  EXPECT_NE(table.find("00_-0.1,interrupted,"), std::string::npos) << table;
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 2) << table;  // header and the one case
  EXPECT_FALSE(fs::exists(dir / "out" / "01_0")) << "a case started after the signal";
  EXPECT_TRUE(dir.temporaries().empty());
}

TEST(SweepSignals, SigintFinishesTheRunningCaseStartsNoOtherAndExits130) {
  ScratchDir dir("sweep_sigint");
  EXPECT_EQ(interrupted_sweep(dir, SIGINT), 130);
  expect_interrupted_sweep(dir);
}

// The interrupted case's row keeps the case's own warnings after "interrupted by SIGINT …",
// as a failed case's does (docs/sweeps.md, the message column: "a warning of the files as
// written is in every row"); before 5 Dec it held the interruption alone.
TEST(SweepSignals, AnInterruptedCasesRowKeepsItsWarnings) {
  ScratchDir dir("sweep_sigint_warned");
  EXPECT_EQ(interrupted_sweep(dir, SIGINT, "far_wake_cycles = 1\n"), 130);
  const std::string table = read_text(dir / "out" / "sweep.csv");
  const auto row = table.find("00_-0.1,interrupted,");
  ASSERT_NE(row, std::string::npos) << table;
  const std::string line = table.substr(row, table.find('\n', row) - row);
  EXPECT_NE(line.find("interrupted by SIGINT"), std::string::npos) << line;
  EXPECT_NE(line.find("; numerics.far_wake_cycles: far_wake_cycles = 1"), std::string::npos) << line;
}

TEST(SweepSignals, SigtermFinishesTheRunningCaseStartsNoOtherAndExits143) {
  ScratchDir dir("sweep_sigterm");
  EXPECT_EQ(interrupted_sweep(dir, SIGTERM), 143);
  expect_interrupted_sweep(dir);
}

// A large grid is checked case by case (~10 ms each) before any runs; a signal then was acted
// on only after the last check (a 2000-case grid exited 16.6 s after SIGTERM, a 100 000-case
// one ran on for minutes). 4000 cases, SIGTERM 1 s in: exit 143 within 5 s, nothing run.
TEST(SweepSignals, SigtermWhileTheCasesAreCheckedEndsTheSweepAtOnce) {
  ScratchDir dir("sweep_sigterm_checking");
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 1, 0);
  const int status = signal_flapsim_when(
      {"sweep", (dir / "case.toml").string(), "--vary", "kinematics.frequency_hz=20:0.001:23.999", "-o",
       (dir / "out").string(), "-q"},
      [] { return true; }, SIGTERM, std::chrono::milliseconds(50), std::chrono::seconds(5),
      std::chrono::milliseconds(1000), std::chrono::seconds(5));
  EXPECT_EQ(status, 143);
  EXPECT_FALSE(fs::exists(dir / "out" / "sweep.csv"));
}

}  // namespace
