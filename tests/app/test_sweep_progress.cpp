// A sweep shows the cases under way while they run, not only a line when a case ends
// (pipeline/app/sweep/sweep_progress.hpp). Before: a sweep of cases of many minutes each
// printed nothing for minutes (usertest5's notes).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#include "common/file_contents.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/sweep/sweep_progress.hpp"
#include "sweep_test_helpers.hpp"

using namespace flapsim;
using app::ProgressLine;
using sweep::SweepProgress;

// stderr to a file (a log, as a batch job's): with --log-every 0.1 s, a case of 384 steps
// (tiny plate, 48 steps per cycle, 8 cycles: ~1 s) shows "under way ... step k/384" lines
// before the line of its end.
TEST(SweepProgress, ALogGetsALineOnTheCaseUnderWayBeforeItEnds) {
  test::ScratchDir dir("sweep_progress_log");
  std::string text = test::tiny_plate_case(48);
  // The whole wake free (a hover's default far wake would end the case in 0.1 s).
  text.replace(text.find("cycles = 1"), 10, "cycles = 8\nfar_wake_cycles = 0.0");
  std::ofstream(dir / "case.toml") << text;
  const std::string cmd = "OMP_NUM_THREADS=1 '" + std::string(FLAPSIM_BINARY) + "' sweep " +
                          (dir / "case.toml").string() + " --vary kinematics.rotation_phase=0.05 -j 1 --log-every 0.1 -o " +
                          (dir / "out").string() + " > /dev/null 2> '" + (dir / "err.txt").string() + "'";
  const int status = std::system(cmd.c_str());
  const std::string err = test::read_text(dir / "err.txt");
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << err;
  const auto under_way = err.find("sweep 0/1 done; under way: 00_0.05 step ");
  const auto end = err.find("sweep 1/1  kinematics.rotation_phase = 0.05");
  ASSERT_NE(under_way, std::string::npos) << err;
  ASSERT_NE(end, std::string::npos) << err;
  EXPECT_LT(under_way, end) << err;
  EXPECT_NE(err.find("/384  ("), std::string::npos) << err;  // the case's own step count
  EXPECT_EQ(err.find('\r'), std::string::npos) << err;       // a log: whole lines only
}

// On a terminal the line is redrawn in place and cleared before a finished case's line.
TEST(SweepProgress, ALiveLineIsRedrawnAndClearedBeforeAFinishedLine) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    SweepProgress p(4, 1, 0, ProgressLine::Mode::live, std::chrono::seconds(30), f);
    p.started(2, "02_0.1");
    p.started(3, "03_0.2");
    p.step(2, 10, 100);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // two redraws at 5 Hz
    p.ended(2);
    p.print_line("sweep 2/4  done", 2);
  }
  const std::string out = test::file_contents(f);
  std::fclose(f);
  EXPECT_NE(out.find("\rsweep 1/4 done; under way: 02_0.1 step 10/100, 03_0.2 setup  ("), std::string::npos) << out;
  // Cleared (carriage return, blanks, carriage return), then the finished line whole.
  const auto done = out.find("sweep 2/4  done\n");
  ASSERT_NE(done, std::string::npos) << out;
  EXPECT_EQ(out[done - 1], '\r') << out;
  EXPECT_EQ(out[done - 2], ' ') << out;
}
