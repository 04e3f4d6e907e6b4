// Messages and notices at the far ends of the inputs:
// - a number beyond the cap every number key has (|value| <= 1e300, wings::Bounds) says the
//   cap. Before: `far_wake_cycles = 1e308` read "out of range: must be >= 0", which it is;
// - an error echoes a 2 MB value cut, not whole (before: 2 MB on stderr);
// - `run -q` of a run estimated over an hour still prints the estimate. Before, -q hid it
//   and a 170-day run started silently.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "robustness_helpers.hpp"

namespace {

using namespace flapsim::test;

TEST(LongValuesAndRuns, ANumberBeyondTheCapIsToldTheCap) {
  ScratchDir dir("cap_message");
  // far_wake_cycles states only ">= 0"; 1e308 is beyond the cap of 1e300 all keys share.
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 1, 0, "far_wake_cycles = 1e308\n");
  const FlapsimOutcome r = run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "case.toml").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("case.toml:16: key 'numerics.far_wake_cycles': value 1e+308 out of range: must be >= 0, a "
                       "number of magnitude at most 1e300"),
            std::string::npos)
      << r.err;
}

TEST(LongValuesAndRuns, AHugeValueIsCutInTheMessage) {
  ScratchDir dir("long_value");
  // A 2 MB choice value: the reader's message names the value it did not expect.
  const std::string value(2'000'000, 'x');
  std::ofstream(dir / "case.toml") << replace_once(small_plate_case("rigid", 1, 0), "kind = \"rigid\"",
                                                   "kind = \"" + value + "\"");
  const FlapsimOutcome r = run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "case.toml").string());
  EXPECT_EQ(r.status, 2) << r.err.substr(0, 500);
  EXPECT_NE(r.err.find("key 'structure.kind'"), std::string::npos) << r.err.substr(0, 500);
  EXPECT_LT(r.err.size(), 2000u) << r.err.substr(0, 500);
  // The echoed word is the value in quotes and a semicolon, 2,000,003 bytes, less the 200
  // kept before the cut and the 60 after it.
  EXPECT_NE(r.err.find("...[1999743 bytes cut]..."), std::string::npos) << r.err.substr(0, 500);
}

TEST(LongValuesAndRuns, QuietRunStillPrintsTheEstimateOfARunOverAnHour) {
  ScratchDir dir("quiet_estimate");
  // 2e4 cycles of 24 steps (4.8e5 steps) on a 10 x 10 lattice with its wake cut at 200
  // rows: each step sums ~1e7 Biot-Savart interactions (every one of the wake's 201 x 11
  // nodes against its ~4400 segments), ~5e12 in all: over two hours at the fastest nominal
  // throughput, 6e8 per second (app::estimate_run). The run is stopped (SIGTERM) once it
  // has started.
  std::ofstream(dir / "case.toml")
      << replace_once(replace_once(small_plate_case("rigid", 20000, 0, "wake_max_rows = 200\n"),
                                   "chordwise_panels = 3", "chordwise_panels = 10"),
                      "spanwise_panels = 4", "spanwise_panels = 10");
  const std::string err = (dir / "err.txt").string();
  // The run claims its folder (flapsim_outputs.toml) after it has printed the estimate.
  const std::string manifest = (dir / "out" / "flapsim_outputs.toml").string();
  const std::string cmd = "FLAPSIM_QUIET=1 OMP_NUM_THREADS=1 '" + std::string(FLAPSIM_BINARY) + "' run '" +
                          (dir / "case.toml").string() + "' -q -o '" + (dir / "out").string() + "' > /dev/null 2> '" +
                          err + "' & pid=$!; i=0; while [ $i -lt 1200 ] && ! [ -e '" + manifest +
                          "' ] && kill -0 $pid 2> /dev/null; do sleep 0.1; i=$((i+1)); done; kill -TERM $pid; wait $pid";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143) << read_text(err);
  const std::string text = read_text(err);
  EXPECT_NE(text.find("estimate: 480000 steps"), std::string::npos) << text;
  EXPECT_TRUE(text.find(" h (one thread") != std::string::npos || text.find(" days (one thread") != std::string::npos)
      << "a run of hours: " << text;
}

}  // namespace
