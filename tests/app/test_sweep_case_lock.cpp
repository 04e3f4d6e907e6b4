// A sweep's case folders are locked while their case runs, as `flapsim run` locks its
// folder (pipeline/io/folder_lock.hpp). Before, sweep_runner.cpp ran each case without the
// lock: a `flapsim run ... -o SWEEP/00_0` started during the sweep ran too; the folder mixed
// one run's history.csv with the other's summary.json, or both exited 0 and sweep.csv
// listed 00_0 as ok while the folder held the other run.
#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "pipeline/io/folder_lock.hpp"
#include "robustness_helpers.hpp"
#include "signal_helpers.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim::test;

const std::string kInUse = "another flapsim command is writing into this folder now";

TEST(SweepCaseLock, ARunIntoACaseFolderUnderWayIsRefused) {
  ScratchDir dir("sweep_case_lock_run");
  // 40 cycles of 24 steps: the case is under way for seconds after its history.csv first
  // holds 21 rows (published every 20), time for the run below to start and stop.
  std::string c = tiny_plate_case(24);
  c.replace(c.find("cycles = 1"), 10, "cycles = 40");
  std::ofstream(dir / "case.toml") << c;
  const fs::path out = dir / "sweep";
  const fs::path history = out / "00_0" / "history.csv";
  FlapsimOutcome run;
  bool ran = false;
  const auto under_way = [&] {
    const std::string h = read_text(history);
    if (std::count(h.begin(), h.end(), '\n') <= 21) return false;
    run = run_flapsim_capturing_stderr(dir.path(), "run " + (dir / "case.toml").string() + " -q -o " +
                                                       (out / "00_0").string());
    ran = true;
    return true;
  };
  ::setenv("OMP_NUM_THREADS", "1", 1);
  const int sweep = signal_flapsim_when({"sweep", (dir / "case.toml").string(), "--vary", "kinematics.rotation_phase=0",
                                         "-q", "-o", out.string()},
                                        under_way, SIGTERM, std::chrono::milliseconds(20), std::chrono::seconds(120));
  ASSERT_TRUE(ran) << "the sweep's case was not seen under way (sweep status " << sweep << ")";
  EXPECT_EQ(run.status, 4) << run.err;
  EXPECT_NE(run.err.find(kInUse), std::string::npos) << run.err;
  // The sweep, stopped by SIGTERM, wrote its own case's files; the refused run wrote none.
  EXPECT_EQ(sweep, 143);
  const std::string summary = read_text(out / "00_0" / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"interrupted\""), std::string::npos) << summary;
  const std::string h = read_text(history);
  const double steps = json_number(summary, "steps");
  EXPECT_EQ(static_cast<double>(std::count(h.begin(), h.end(), '\n') - 1), steps)
      << "history.csv and summary.json of one run";
}

TEST(SweepCaseLock, ACaseWhoseFolderIsInUseIsNotRun) {
  ScratchDir dir("sweep_case_lock_busy");
  std::ofstream(dir / "case.toml") << tiny_plate_case(12);
  const fs::path out = dir / "sweep";
  fs::create_directories(out / "00_0");
  {
    // This process stands for a `flapsim run -o SWEEP/00_0` under way.
    const flapsim::io::FolderLock other(out / "00_0", "run");
    ASSERT_TRUE(other.held());
    const FlapsimOutcome r = run_flapsim_capturing_stderr(
        dir.path(), "sweep " + (dir / "case.toml").string() + " --vary kinematics.rotation_phase=0,0.1 -j 1 -o " +
                        out.string());
    EXPECT_EQ(r.status, 0) << r.err;
  }
  const SweepTable table = read_sweep_table((out / "sweep.csv").string());
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].at("status"), "error");
  EXPECT_NE(table.rows[0].at("message").find(kInUse), std::string::npos) << table.rows[0].at("message");
  EXPECT_TRUE(fs::is_empty(out / "00_0")) << "nothing written into the folder in use";
  EXPECT_EQ(table.rows[1].at("status"), "ok");
  EXPECT_TRUE(fs::exists(out / table.rows[1].at("folder") / "summary.json"));
}

}  // namespace
