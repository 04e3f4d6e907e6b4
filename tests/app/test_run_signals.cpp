// SIGINT and SIGTERM during a run (issue: up to 19 computed steps lost, no summary.json):
// the step under way is finished, history.csv holds every step, summary.json says
// "interrupted", the exit status is 128 + signal (130, 143).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "shipped_case_text.hpp"
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

// "mean_window_cycles": X of summary.json (NaN if absent).
double window_cycles(const std::string& summary) {
  const auto at = summary.find("\"mean_window_cycles\": ");
  return at == std::string::npos ? std::nan("") : std::strtod(summary.c_str() + at + 22, nullptr);
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
  // The means cover the last cycle of 24 steps (or what was run of the first).
  EXPECT_NEAR(window_cycles(summary), std::min(1.0, static_cast<double>(rows) / 24.0), 1e-9) << summary;
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

// A run stopped within its first cycle: its "last-cycle" means cover what was run (a run
// stopped at step 32 of an 80-step cycle gave mean_CL 3.683 against 2.866 complete), and
// summary.json says how much (before, no key told it).
TEST(RunSignals, ARunStoppedWithinItsFirstCycleSaysWhatItsMeansCover) {
  ScratchDir dir("run_sigint_first_cycle");
  std::string text = small_plate_case("rigid", 1, 0, "wake_max_rows = 12\n");
  text.replace(text.find("steps_per_cycle = 24"), 20, "steps_per_cycle = 4800");
  std::ofstream(dir / "case.toml") << text;
  EXPECT_EQ(signal_flapsim_once_history_grows(
                {"run", (dir / "case.toml").string(), "-o", (dir / "out").string(), "-q"},
                dir / "out" / "history.csv", SIGINT),
            130);
  const std::string summary = read_text(dir / "out" / "summary.json");
  const long steps = summary_steps(summary);
  ASSERT_GT(steps, 20) << summary;
  ASSERT_LT(steps, 4800) << summary;
  EXPECT_NEAR(window_cycles(summary), steps / 4800.0, 1e-9) << summary;
}

// A complete run's means cover one whole cycle: summary.json says 1 and the report notes
// nothing. The window T was computed as t_end − (t_end − T): at 20 Hz with 1 or 5 cycles of
// 24 steps (as at 25 and 30 Hz, and 26.1 Hz with 5) it came out 0.9999999999999998, and
// `flapsim run` said the run had ended within its first cycle.
TEST(RunSignals, ACompleteRunsMeansCoverOneWholeCycle) {
  for (const int cycles : {1, 5}) {
    ScratchDir dir("run_whole_cycle_" + std::to_string(cycles));
    std::ofstream(dir / "case.toml") << replace_once(small_plate_case("rigid", cycles, 0),
                                                     "frequency_hz = 26.1", "frequency_hz = 20.0");
    ASSERT_EQ(run_flapsim("run '" + (dir / "case.toml").string() + "' -o '" + (dir / "out").string() + "'",
                          dir / "stdout.txt"),
              0);
    EXPECT_EQ(window_cycles(read_text(dir / "out" / "summary.json")), 1.0) << cycles << " cycles";
    EXPECT_EQ(read_text(dir / "stdout.txt").find("ended within its first cycle"), std::string::npos)
        << read_text(dir / "stdout.txt");
  }
}

// A step that lasts minutes: the 75 mm film wing's FEM (wings/film_wing_75mm_25um.toml, the
// case cases/film_wing_fem.toml) at 4 steps a wingbeat splits its first step into up to 256
// pieces, each solved again at every sub-iteration (docs/fsi.md, "Step halving of the FEM");
// before, SIGTERM waited for the step's end and `timeout` had to kill the run.
TEST(RunSignals, SigtermWithinALongFemStepStopsItAtTheNextSolve) {
  ScratchDir dir("run_sigterm_fem_step");
  std::string text = shipped_case_text("film_wing_fem");
  const auto at = text.find("\nsteps_per_cycle = ");
  ASSERT_NE(at, std::string::npos);
  text.replace(at + 1, text.find('\n', at + 1) - at - 1, "steps_per_cycle = 4");
  std::ofstream(dir / "case.toml") << text;
  ::setenv("OMP_NUM_THREADS", "1", 1);
  const fs::path history = dir / "out" / "history.csv";
  const auto started = [&] { return fs::exists(history); };  // the setup done, the first step begun
  // Signalled 2 s into the first step, the run ends within 30 s (a step's one piece, 25
  // Newton iterations on 335 nodes, takes well under that).
  const int status = signal_flapsim_when({"run", (dir / "case.toml").string(), "-o", (dir / "out").string(), "-q"},
                                         started, SIGTERM, std::chrono::milliseconds(20), std::chrono::seconds(120),
                                         std::chrono::milliseconds(2000), std::chrono::seconds(30));
  EXPECT_EQ(status, 143);
  const std::string summary = read_text(dir / "out" / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"interrupted\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("during step 1 of 20"), std::string::npos) << summary;
  EXPECT_EQ(summary_steps(summary), 0) << summary;
  const std::string rows = read_text(history);
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 1) << "the header alone: the step was dropped";
  EXPECT_TRUE(dir.temporaries().empty());
}

}  // namespace
