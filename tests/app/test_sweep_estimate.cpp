// A sweep says what its cases will take before they run, each estimated as `flapsim run`
// estimates it (app::estimate_run), one thread a case (pipeline/app/sweep/sweep_runner.cpp).
// Before: a sweep printed no estimate at all, where `flapsim run` of each of its cases did
// (a sweep of 14 long hovers gave no hint of hours against minutes).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

#include "common/file_contents.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/resource_estimate.hpp"
#include "pipeline/io/case_file.hpp"
#include "sweep_test_helpers.hpp"

using namespace flapsim;

namespace {

int run_sweep_into(const test::ScratchDir& dir, const std::string& args) {
  const std::string cmd = "OMP_NUM_THREADS=1 '" + std::string(FLAPSIM_BINARY) + "' sweep " +
                          (dir / "case.toml").string() + " " + args + " -o " + (dir / "out").string() +
                          " > /dev/null 2> '" + (dir / "err.txt").string() + "'";
  return std::system(cmd.c_str());
}

}  // namespace

TEST(SweepEstimate, TheCasesToRunAreEstimatedAsRunEstimatesEachAndNoneWhenAllAreKept) {
  test::ScratchDir dir("sweep_estimate");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  // Two cases of 24 and 48 steps a cycle on one thread: their one-thread times add up.
  int status = run_sweep_into(dir, "--vary numerics.steps_per_cycle=24,48 -j 1");
  std::string err = test::read_text(dir / "err.txt");
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << err;
  double total = 0.0, longest = 0.0;
  for (const char* steps : {"24", "48"}) {
    const io::Case c =
        io::load_case_file((dir / "case.toml").string(), {{"numerics.steps_per_cycle", steps}});
    const double s = app::estimate_run(c, 1).seconds;
    total += s;
    longest = std::max(longest, s);
  }
  const std::string expected = "sweep: estimate: 2 cases to run, of the order of " +
                               app::seconds_text(total) + " of one thread's time in all (the longest " +
                               app::seconds_text(longest) + "), about " + app::seconds_text(total) +
                               " on 1 thread\n";
  EXPECT_NE(err.find(expected), std::string::npos) << "expected: " << expected << "got: " << err;
  // The estimate comes before the first case's line.
  EXPECT_LT(err.find("sweep: estimate:"), err.find("sweep 1/2")) << err;
  // Run again: both cases are kept from the first run, none to run, no estimate.
  status = run_sweep_into(dir, "--vary numerics.steps_per_cycle=24,48 -j 1");
  err = test::read_text(dir / "err.txt");
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << err;
  EXPECT_NE(err.find("2 of 2 cases kept"), std::string::npos) << err;
  EXPECT_EQ(err.find("sweep: estimate:"), std::string::npos) << err;
  // -q: no estimate either.
  status = run_sweep_into(dir, "--vary numerics.steps_per_cycle=24,96 -j 1 -q");
  err = test::read_text(dir / "err.txt");
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << err;
  EXPECT_EQ(err.find("sweep: estimate:"), std::string::npos) << err;
}
