// flapsim optimize over MPI (issue 33): three starts under `mpirun --oversubscribe -np 3`
// find the optimum the serial command finds, byte for byte, with the evaluations spread
// over the ranks (the runs are deterministic: rigid wing, one OpenMP thread).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

std::set<std::string> hashes_of(const test::SweepTable& t) {
  std::set<std::string> out;
  for (const auto& row : t.rows) out.insert(row.at("inputs_hash"));
  return out;
}

TEST(OptimizeMpi, ThreeStartsOnThreeRanksFindTheSerialOptimum) {
  const test::ScratchDir dir("optimize_mpi");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(24);
  const std::string command = "optimize " + (dir / "case.toml").string() +
                              " --vary kinematics.rotation_phase=-0.25:0.15 --vary kinematics.frequency_hz=20:30"
                              " --maximize mean_lift_N --starts 3 --max-evaluations 12 -q -o ";
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
  EXPECT_GE(ranks.size(), 2u) << "the starts ran on one rank only";
  for (const auto& row : serial.rows) EXPECT_EQ(row.at("rank"), "0");
}

}  // namespace
