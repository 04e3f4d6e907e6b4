// flapsim optimize over MPI (issue 33): three starts under `mpirun --oversubscribe -np 3`
// find the optimum the serial command finds, byte for byte, with the evaluations spread
// over the ranks (the runs are deterministic: one OpenMP thread) — on a rigid plate, and on
// the flexible rotation-phase case with the rotation phase and the spring factor varied.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "optimize_test_helpers.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

std::set<std::string> hashes_of(const test::SweepTable& t) {
  std::set<std::string> out;
  for (const auto& row : t.rows) out.insert(row.at("inputs_hash"));
  return out;
}

// Runs `command` serially into dir/serial and on 3 ranks into dir/mpi; expects the same
// optimum.toml and evaluated points, and evaluations on at least `least_ranks` ranks.
// The scheduler hands the next start to whichever rank asks first (sweep::schedule_cases):
// each rank takes one of the 3 starts unless a start ends before the last rank has asked,
// which starts of a few milliseconds (the rigid plate) may do, starts of seconds not.
void compare_three_ranks_with_serial(const test::ScratchDir& dir, const std::string& command,
                                     std::size_t least_ranks) {
  ASSERT_EQ(test::run_flapsim(command + (dir / "serial").string()), 0);

  // Open MPI refuses to run as root unless told twice; --oversubscribe: any rank count on any core count.
  const std::string mpi = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 FLAPSIM_QUIET=1 "
                          "OMP_NUM_THREADS=1 timeout 300 mpirun --oversubscribe -np 3 '" +
                          std::string(FLAPSIM_BINARY) + "' " + command + (dir / "mpi").string() + " > '" +
                          (dir / "mpi.txt").string() + "' 2>&1";
  const int status = std::system(mpi.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << test::read_text(dir / "mpi.txt");

  EXPECT_EQ(test::read_text(dir / "mpi" / "optimum.toml"), test::read_text(dir / "serial" / "optimum.toml"));
  const auto serial = test::read_sweep_table((dir / "serial" / "evaluations.csv").string());
  const auto parallel = test::read_sweep_table((dir / "mpi" / "evaluations.csv").string());
  ASSERT_TRUE(parallel.rectangular);
  EXPECT_EQ(hashes_of(parallel), hashes_of(serial));  // the same points, whatever their order
  std::set<std::string> ranks;
  for (const auto& row : parallel.rows) ranks.insert(row.at("rank"));
  EXPECT_GE(ranks.size(), least_ranks) << "the starts ran on " << ranks.size() << " of 3 ranks";
  for (const auto& row : serial.rows) EXPECT_EQ(row.at("rank"), "0");
}

TEST(OptimizeMpi, ThreeStartsOnThreeRanksFindTheSerialOptimum) {
  const test::ScratchDir dir("optimize_mpi");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  compare_three_ranks_with_serial(dir, "optimize " + (dir / "case.toml").string() +
                                           " --vary kinematics.rotation_phase=-0.25:0.15 --vary "
                                           "kinematics.frequency_hz=20:30 --maximize mean_lift_N --starts 3 "
                                           "--max-evaluations 12 -q -o ",
                                  2);
}

// cases/rotation_phase_flexible.toml at 40 steps per cycle over 2 cycles (shipped: 100 × 6)
// with the shipped 10-body hawkmoth chain (no reduction), δψ in [-0.25, 0.15] and the
// spring factor in [1, 4]: under a second per run. A soft wing at some points fails to
// converge; that ends its start's search only (docs/optimize.md). Two of the starts take 10
// evaluations each (seconds): every rank runs one.
TEST(OptimizeMpi, TheFlexibleRotationPhaseAndSpringProblemOnThreeRanksFindsTheSerialOptimum) {
  const test::ScratchDir dir("optimize_mpi_flexible");
  const std::string text = test::shortened_case("rotation_phase_flexible", 40, 2);
  ASSERT_FALSE(text.empty()) << "cases/rotation_phase_flexible.toml no longer has the keys this test shortens";
  std::ofstream(dir / "case.toml") << text;
  const std::string chain = std::string(FLAPSIM_SOURCE_DIR) + "/cases/chains/hawkmoth_10_bodies.toml";
  compare_three_ranks_with_serial(dir, "optimize " + (dir / "case.toml").string() + " --chain " + chain +
                                           " --vary kinematics.rotation_phase=-0.25:0.15 --vary spring_scale=1:4"
                                           " --maximize mean_lift_N --starts 3 --max-evaluations 10 -q -o ",
                                  3);  // issue 33: evaluations on every rank
  // optimum.toml with the spring factor its header gives runs to the optimum's lift.
  const std::string optimum = test::read_text(dir / "serial" / "optimum.toml");
  const auto at = optimum.find("# Run with --spring-scale ");
  ASSERT_NE(at, std::string::npos);
  const std::string scale = optimum.substr(at + 26, optimum.find(' ', at + 26) - at - 26);
  ASSERT_EQ(test::run_flapsim("run " + (dir / "serial" / "optimum.toml").string() + " --spring-scale " + scale +
                              " -q -o " + (dir / "best").string()),
            0);
  double best = -INFINITY;
  for (const auto& row : test::read_sweep_table((dir / "serial" / "evaluations.csv").string()).rows)
    if (row.at("status") == "ok") best = std::max(best, std::stod(row.at("mean_lift_N")));
  EXPECT_EQ(std::stod(test::summary_value(test::read_text(dir / "best" / "summary.json"), "mean_lift_N")), best);
}

}  // namespace
