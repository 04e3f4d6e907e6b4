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
  // Three steps each past the interval: three lines, then the final one; no carriage returns.
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 4) << out;
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
