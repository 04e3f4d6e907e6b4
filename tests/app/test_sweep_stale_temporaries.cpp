// A case of a sweep killed by SIGKILL leaves its temporaries ("history.csv.tmp.<pid>", frames
// "vtk/wing_000004.vtp.tmp.<pid>"): no process is left to remove them. The sweep run again
// runs that case (its summary.json is missing) and must leave a clean folder, as `flapsim run`
// does when it claims a folder (docs/sweeps.md, "Resuming a sweep"; issue: the temporaries
// stayed after a successful resume).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

TEST(SweepStaleTemporaries, AResumedCaseLeavesNoTemporaryOfTheKilledRun) {
  const test::ScratchDir dir("sweep_stale_tmp");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(8);
  const std::string sweep = "sweep " + (dir / "case.toml").string() +
                            " --vary kinematics.rotation_phase=0,0.1 -j 1 -q --vtk-every 4 -o " +
                            (dir / "out").string();
  ASSERT_EQ(test::run_flapsim(sweep), 0);
  // What SIGKILL leaves: the case without its summary, temporaries of a dead process.
  const fs::path killed = dir / "out" / "00_0";
  fs::remove(killed / "summary.json");
  const std::string pid = "4194300";  // above the kernel's default pid_max: never a live process
  std::ofstream(killed / ("history.csv.tmp." + pid)) << "t_s\n0\n";
  std::ofstream(killed / "vtk" / ("wing_000004.vtp.tmp." + pid)) << "<VTKFile";
  std::ofstream(killed / ("summary.json.tmp." + pid)) << "{";

  ASSERT_EQ(test::run_flapsim(sweep), 0);
  EXPECT_TRUE(fs::exists(killed / "summary.json"));
  for (const auto& f : fs::recursive_directory_iterator(killed))
    EXPECT_EQ(f.path().filename().string().find(".tmp."), std::string::npos) << f.path();
}

}  // namespace
