// SIGINT and SIGTERM during a sweep. Before: the sweep was killed at once (exit 143 with no
// message), the case under way left `history.csv.tmp.<pid>` beside a history.csv and no
// summary.json, and sweep.csv did not list it. Now, as for `flapsim run` (docs/reliability.md):
// the cases under way finish their step and write summary.json ("interrupted"), no further
// case starts, sweep.csv lists the case as "interrupted", the exit status is 128 + signal,
// and the same command again runs what is left.
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "robustness_helpers.hpp"

extern char** environ;

namespace fs = std::filesystem;
using namespace flapsim::test;

namespace {

// Starts a three-case sweep of a long run, one case at a time, waits until the first case's
// history.csv has rows, sends the signal; returns the exit status (-1: no normal exit).
int interrupted_sweep(const ScratchDir& dir, int signal_number) {
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 200, 0, "wake_max_rows = 12\n");
  const std::string binary = FLAPSIM_BINARY, case_file = (dir / "case.toml").string(),
                    out = (dir / "out").string();
  const char* argv[] = {binary.c_str(), "sweep", case_file.c_str(), "--vary", "kinematics.rotation_phase=-0.1,0,0.1",
                        "-j", "1", "-o", out.c_str(), "-q", nullptr};
  ::setenv("OMP_NUM_THREADS", "1", 1);
  pid_t pid = 0;
  if (::posix_spawn(&pid, binary.c_str(), nullptr, nullptr, const_cast<char**>(argv), environ) != 0) return -2;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return -3;  // ended before the signal
    const std::string h = read_text(dir / "out" / "00_-0.1" / "history.csv");
    if (std::count(h.begin(), h.end(), '\n') > 21) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, signal_number);
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
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

TEST(SweepSignals, SigtermFinishesTheRunningCaseStartsNoOtherAndExits143) {
  ScratchDir dir("sweep_sigterm");
  EXPECT_EQ(interrupted_sweep(dir, SIGTERM), 143);
  expect_interrupted_sweep(dir);
}

}  // namespace
