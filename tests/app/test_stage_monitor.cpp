// The progress of the long stages of `mesh`, `modes` and `reduce` (pipeline/app/stage_monitor.hpp).
// Before: a low-aspect-ratio wing's `reduce` ran for a minute without a word. Now a stage
// that lasts longer than a threshold (2 s in the commands; 30 ms here) is shown on stderr,
// rate-limited; short stages print nothing.
#include "pipeline/app/stage_monitor.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "common/scratch_dir.hpp"
#include "common/file_contents.hpp"

using flapsim::app::StageMonitor;
using flapsim::test::file_contents;
using namespace std::chrono_literals;

namespace {

StageMonitor::Options log_options(std::FILE* f) {
  StageMonitor::Options o;
  o.show_after = 30ms;
  o.log_interval = 60s;  // one line per stage here
  o.display = StageMonitor::Options::Display::log;
  o.stream = f;
  o.watch_signals = false;
  return o;
}

TEST(StageMonitor, ALongStageIsShownOnceAndAShortOneNot) {
  flapsim::test::ScratchDir dir("stage_monitor_log");
  flapsim::io::OutputFolderClaim claim(dir.path(), "reduce");
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    StageMonitor monitor(claim, 3, log_options(f));
    monitor.stage("FEM modes");
    std::this_thread::sleep_for(400ms);  // > show_after: shown, and only once (log_interval)
    monitor.stage("bar chain");           // ends at once: not shown
    monitor.done();
  }
  const std::string text = file_contents(f);
  std::fclose(f);
  // The stage's line while it ran, then its own time when it ended (a log said "2 s" for a
  // stage of 13.5 s): two lines, the second "done in" at least the 0.4 s slept.
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2) << text;
  EXPECT_EQ(text.rfind("reduce: FEM modes (stage 1 of 3): ", 0), 0u) << text;
  const auto done = text.find("reduce: FEM modes (stage 1 of 3): done in ");
  ASSERT_NE(done, std::string::npos) << text;
  EXPECT_GE(std::stod(text.substr(done + std::string("reduce: FEM modes (stage 1 of 3): done in ").size())),
            0.4)
      << text;
  EXPECT_EQ(text.find("bar chain"), std::string::npos) << text;
}

TEST(StageMonitor, ALogLineIsRepeatedAtMostOncePerInterval) {
  flapsim::test::ScratchDir dir("stage_monitor_rate");
  flapsim::io::OutputFolderClaim claim(dir.path(), "modes");
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  StageMonitor::Options o = log_options(f);
  o.log_interval = 200ms;
  {
    StageMonitor monitor(claim, 1, o);
    monitor.stage("FEM modes");
    std::this_thread::sleep_for(700ms);  // lines at ~30 ms, ~230, ~430, ~630 ms: at most 4
    monitor.done();                      // and the stage's time: at most 5
  }
  const std::string text = file_contents(f);
  std::fclose(f);
  const auto lines = std::count(text.begin(), text.end(), '\n');
  EXPECT_GE(lines, 3) << text;
  EXPECT_LE(lines, 5) << text;
  EXPECT_NE(text.find("modes: FEM modes (stage 1 of 1): done in "), std::string::npos) << text;
}

TEST(StageMonitor, QuietPrintsNothing) {
  flapsim::test::ScratchDir dir("stage_monitor_quiet");
  flapsim::io::OutputFolderClaim claim(dir.path(), "mesh");
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  StageMonitor::Options o = log_options(f);
  o.display = StageMonitor::Options::Display::quiet;
  {
    StageMonitor monitor(claim, 1, o);
    monitor.stage("meshing (gmsh)");
    std::this_thread::sleep_for(150ms);
  }
  EXPECT_EQ(file_contents(f), "");
  std::fclose(f);
}

}  // namespace
