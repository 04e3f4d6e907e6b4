// A run whose progress goes to a log (stderr not a terminal: a batch job, `make` output)
// prints a whole line every log interval, not only the final line (pipeline/app/progress).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "common/file_contents.hpp"
#include "pipeline/app/progress.hpp"

using flapsim::app::ProgressLine;
using flapsim::test::file_contents;

TEST(ProgressLogLines, ALongRunInALogPrintsALineEachIntervalAndTheFinalLine) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressLine p(3, f, ProgressLine::Mode::final_only);
    p.set_log_interval(std::chrono::milliseconds(20));  // 30 s in a real run
    for (int i = 1; i <= 3; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(40));  // a step longer than the interval
      p.update(i, i * 0.01, "CL=2");
    }
    p.finish();
  }
  const std::string out = file_contents(f);
  std::fclose(f);
  // Three steps each past the interval: a line for each of the first two, then the final
  // one (the last step's own line would repeat it); no carriage returns.
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 3) << out;
  EXPECT_EQ(out.find('\r'), std::string::npos);
  EXPECT_EQ(out.rfind("step 1/3  t=0.0100 s  CL=2  (", 0), 0u) << out;
  // The lines before the end say the time left (2 steps left after the first, 1 after the
  // second: about 2 and 1 times the ~40 ms a step); the final line only the wall time.
  EXPECT_NE(out.find(" s left)\nstep 2/3"), std::string::npos) << out;
  EXPECT_NE(out.find(" s left)\nstep 3/3"), std::string::npos) << out;
  const std::size_t last = out.rfind("step 3/3");
  ASSERT_NE(last, std::string::npos) << out;
  EXPECT_EQ(out.find("left", last), std::string::npos) << out;
  EXPECT_NE(out.find("s wall)\n", last), std::string::npos) << out;
}

// The time left: the wall time so far scaled by the steps left over the steps done, in
// seconds, minutes or hours; nothing before the first step or after the last.
TEST(ProgressLogLines, TheTimeLeftScalesTheWallTimeByTheStepsLeft) {
  EXPECT_EQ(ProgressLine::time_left(10.0, 100, 400), "~30 s left");        // 10 s × 300/100
  EXPECT_EQ(ProgressLine::time_left(30.0, 100, 400), "~1.5 min left");     // 90 s
  EXPECT_EQ(ProgressLine::time_left(600.0, 100, 1000), "~1.5 h left");     // 5400 s
  EXPECT_EQ(ProgressLine::time_left(60.0, 40, 400), "~9.0 min left");      // 540 s
  EXPECT_EQ(ProgressLine::time_left(5.0, 0, 400), "");
  EXPECT_EQ(ProgressLine::time_left(5.0, 400, 400), "");
  EXPECT_EQ(ProgressLine::time_left(0.0, 10, 400), "");
}

// A run whose steps slow down (a film's FEM steps that start to split) says so: the steps
// left go at the slower of the whole run's pace and the recent one (progress.hpp).
TEST(ProgressLogLines, TheTimeLeftTakesTheSlowerOfTheRunsPaceAndTheRecentOne) {
  EXPECT_EQ(ProgressLine::time_left(10.0, 100, 400, 1.0), "~5.0 min left");  // 1 s/step × 300
  EXPECT_EQ(ProgressLine::time_left(10.0, 100, 400, 0.05), "~30 s left");    // the run's 0.1 s/step
  EXPECT_EQ(ProgressLine::time_left(10.0, 100, 400, 0.0), "~30 s left");     // no recent pace yet
  // The dragonfly-like 25 um film of the 5 Dec note: 161 s for 94 of 100 steps, the last
  // three 12 s each; the run's pace alone said "~10 s left".
  EXPECT_EQ(ProgressLine::time_left(161.1, 94, 100, 12.0), "~72 s left");
  EXPECT_EQ(ProgressLine::time_left(5.0, 400, 400, 1.0), "");
}

// The same in a run: a thousand steps at once, then steps of at least 30 ms (the log interval
// 20 ms, 30 s in a real run). After the second slow step the recent pace (30 ms a step or
// more) says minutes or hours for the 98,998 steps left; the run's pace would say about 6 s.
TEST(ProgressLogLines, ARunWhoseStepsSlowDownSaysSoWithinTwoLines) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressLine p(100000, f, ProgressLine::Mode::final_only);
    p.set_log_interval(std::chrono::milliseconds(20));
    for (int i = 1; i <= 1000; ++i) p.update(i, i * 1e-4);
    for (int i = 1001; i <= 1002; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(30));
      p.update(i, i * 1e-4);
    }
    p.finish();
  }
  const std::string out = file_contents(f);
  std::fclose(f);
  const std::size_t line = out.find("step 1002/100000");
  ASSERT_NE(line, std::string::npos) << out;
  const std::string text = out.substr(line, out.find('\n', line) - line);
  EXPECT_EQ(text.find(" s left"), std::string::npos) << text;
  EXPECT_TRUE(text.find(" min left") != std::string::npos || text.find(" h left") != std::string::npos)
      << text;
}

// A step that lasts longer than the log interval (a film's FEM step in many pieces, minutes)
// shows that it is under way, from the calls between its solves; a short step does not.
TEST(ProgressLogLines, AStepThatLastsShowsThatItIsUnderWay) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressLine p(3, f, ProgressLine::Mode::final_only);
    p.set_log_interval(std::chrono::milliseconds(50));  // 30 s in a real run
    p.update(1, 0.01, "CL=2");  // the first step done at once: no line yet
    p.step_under_way();         // step 2 has only begun: nothing
    std::this_thread::sleep_for(std::chrono::milliseconds(80));
    p.step_under_way();  // 80 ms into step 2: one line
    p.step_under_way();  // again at once: nothing
    p.finish();
  }
  const std::string out = file_contents(f);
  std::fclose(f);
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 2) << out;
  EXPECT_EQ(out.rfind("step 1/3  t=0.0100 s  CL=2  step 2 under way for 0 s  (", 0), 0u) << out;
}

// A coupled step that lasts says how far its coupling has come (fsi_run.cpp: lattice solves,
// the structure's change): a light film's first step in air ran for minutes showing the
// seconds alone. The detail is asked for only when the line is drawn.
TEST(ProgressLogLines, AStepThatLastsSaysHowFarItsCouplingHasCome) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  int asked = 0;
  const auto detail = [&] {
    ++asked;
    return std::string("37 lattice solves, structure change 0.0023 rad (tolerance 1e-06)");
  };
  {
    ProgressLine p(3, f, ProgressLine::Mode::final_only);
    p.set_log_interval(std::chrono::milliseconds(50));
    p.update(1, 0.01, "CL=2");
    p.step_under_way(detail);  // not drawn: not asked
    std::this_thread::sleep_for(std::chrono::milliseconds(80));
    p.step_under_way(detail);  // drawn
    p.finish();
  }
  const std::string out = file_contents(f);
  std::fclose(f);
  EXPECT_EQ(asked, 1);
  EXPECT_EQ(
      out.rfind("step 1/3  t=0.0100 s  CL=2  step 2 under way for 0 s: 37 lattice solves, structure change "
                "0.0023 rad (tolerance 1e-06)  (",
                0),
      0u)
      << out;
}

// The last step's interval line and the final line were both printed when the last step
// fell on an interval: the final line alone now.
TEST(ProgressLogLines, TheLastStepIsPrintedOnce) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressLine p(2, f, ProgressLine::Mode::final_only);
    p.set_log_interval(std::chrono::milliseconds(20));
    std::this_thread::sleep_for(std::chrono::milliseconds(40));
    p.update(1, 0.01);
    std::this_thread::sleep_for(std::chrono::milliseconds(40));
    p.update(2, 0.02);
    p.finish("mean lift 1 N");
  }
  const std::string out = file_contents(f);
  std::fclose(f);
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 2) << out;
  EXPECT_EQ(out.find("step 2/2  t=0.0200 s  ("), std::string::npos) << out;
  EXPECT_NE(out.find("step 2/2  t=0.0200 s  mean lift 1 N  ("), std::string::npos) << out;
}
