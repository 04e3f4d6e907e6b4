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
  EXPECT_NE(out.find("s wall)\nstep 2/3"), std::string::npos) << out;
}
