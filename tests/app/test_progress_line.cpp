// The progress line of long runs on stderr (pipeline/app/progress).

#include "pipeline/app/progress.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "common/file_contents.hpp"

using flapsim::app::ProgressLine;
using flapsim::test::file_contents;

TEST(OutputProgress, LineFormat) {
  EXPECT_EQ(ProgressLine::format(120, 300, 0.046, "CL=1.93"), "step 120/300  t=0.0460 s  CL=1.93");
  EXPECT_EQ(ProgressLine::format(1, 10, 0.0, ""), "step 1/10  t=0.0000 s");
}

TEST(OutputProgress, NotATerminalPrintsOnlyTheFinalLine) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressLine p(300, f, ProgressLine::Mode::final_only);
    for (int i = 1; i <= 300; ++i) p.update(i, i * 1e-4, "iters=3");
    p.finish();
  }
  const std::string out = file_contents(f);
  std::fclose(f);
  EXPECT_EQ(out.find('\r'), std::string::npos);
  EXPECT_EQ(out.rfind("step 300/300  t=0.0300 s  iters=3  (", 0), 0u) << out;
  EXPECT_EQ(out.back(), '\n');
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1);
}

TEST(OutputProgress, LiveModeRedrawsInPlaceThrottled) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressLine p(1000, f, ProgressLine::Mode::live);
    for (int i = 1; i <= 1000; ++i) p.update(i, i * 1e-5);  // far faster than 5 Hz
  }  // the destructor prints the final line
  const std::string out = file_contents(f);
  std::fclose(f);
  const auto redraws = std::count(out.begin(), out.end(), '\r');
  EXPECT_GE(redraws, 2);   // the first update and the final line
  EXPECT_LT(redraws, 50);  // throttled: not one per step
  EXPECT_NE(out.find("step 1000/1000"), std::string::npos);
  EXPECT_EQ(out.back(), '\n');
}

TEST(OutputProgress, LiveLineShowsTheTimeLeftOnceTheRunHasAPace) {
  // Within its first second the live line shows no time left; after it, "~… left" (here
  // one step of four in ~1.1 s: about 3.3 s left).
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressLine p(4, f, ProgressLine::Mode::live);
    p.update(1, 0.001);
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    p.update(1, 0.001);
  }
  const std::string out = file_contents(f);
  std::fclose(f);
  const std::size_t second = out.find('\r', 1);
  ASSERT_NE(second, std::string::npos) << out;
  EXPECT_EQ(out.substr(0, second).find("left"), std::string::npos) << out;
  EXPECT_NE(out.find(" s left", second), std::string::npos) << out;
}

TEST(OutputProgress, QuietEnvironmentSilencesIt) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  const char* env = std::getenv("FLAPSIM_QUIET");
  const bool had = env != nullptr;
  const std::string saved = had ? env : "";
  ::setenv("FLAPSIM_QUIET", "1", 1);
  {
    ProgressLine p(10, f);
    EXPECT_EQ(p.mode(), ProgressLine::Mode::quiet);
    p.update(10, 0.1);
    p.finish();
  }
  if (had) ::setenv("FLAPSIM_QUIET", saved.c_str(), 1);
  else ::unsetenv("FLAPSIM_QUIET");
  // Without the variable, a regular file is not a terminal: final line only.
  ProgressLine q(10, f);
  const bool quiet_outside = had && saved == "1";
  EXPECT_EQ(q.mode(), quiet_outside ? ProgressLine::Mode::quiet : ProgressLine::Mode::final_only);
  q.update(10, 0.1);
  q.finish();
  EXPECT_EQ(file_contents(f).find("step 10/10"), quiet_outside ? std::string::npos : 0u);
  std::fclose(f);
}
