// flapsim sweep over MPI: `mpirun --oversubscribe -np 3` on a 5-case sweep gives the
// serial sweep's results, bit for bit (the cases are deterministic: rigid wing, one
// OpenMP thread), with the cases spread over at least two ranks; so do 2 ranks of 2
// worker threads each (threads of a rank taking turns in MPI).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/run_results.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;
using test::read_sweep_table;
using test::read_text;

// summary.json without its wall time (the one result that differs between two runs).
std::string without_wall_time(const std::string& json) {
  std::string out;
  std::size_t at = 0;
  for (std::size_t end; (end = json.find('\n', at)) != std::string::npos; at = end + 1) {
    const std::string line = json.substr(at, end - at);
    if (line.find("\"wall_time_s\"") == std::string::npos) out += line + "\n";
  }
  return out;
}

// The 5-case sweep (δψ = −0.1 … 0.1) serially into dir/serial and with `mpirun -np
// ranks`, `-j jobs` into dir/mpi; expects equal results; returns the ranks that ran cases.
std::set<std::string> compare_mpi_with_serial(const test::ScratchDir& dir, int ranks, int jobs) {
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(48);
  const std::string sweep =
      "sweep " + (dir / "case.toml").string() + " --vary kinematics.rotation_phase=-0.1:0.05:0.1 -o ";
  EXPECT_EQ(test::run_flapsim(sweep + (dir / "serial").string() + " -j 1"), 0);

  // Open MPI refuses to run as root unless told twice; --oversubscribe: any rank count on any core count.
  const std::string mpi = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 FLAPSIM_QUIET=1 "
                          "OMP_NUM_THREADS=1 timeout 300 mpirun --oversubscribe -np " +
                          std::to_string(ranks) + " '" + std::string(FLAPSIM_BINARY) + "' " + sweep +
                          (dir / "mpi").string() + " -j " + std::to_string(jobs) + " > '" +
                          (dir / "mpi.txt").string() + "' 2>&1";
  const int status = std::system(mpi.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(dir / "mpi.txt");

  const auto serial = read_sweep_table((dir / "serial" / "sweep.csv").string());
  const auto parallel = read_sweep_table((dir / "mpi" / "sweep.csv").string());
  EXPECT_TRUE(parallel.rectangular);
  EXPECT_EQ(parallel.header, serial.header);
  EXPECT_EQ(serial.rows.size(), 5u);
  EXPECT_EQ(parallel.rows.size(), 5u);
  std::set<std::string> used;
  for (std::size_t i = 0; i < 5 && i < serial.rows.size() && i < parallel.rows.size(); ++i) {
    const auto& s = serial.rows[i];
    const auto& p = parallel.rows[i];
    EXPECT_EQ(p.at("status"), "ok");
    used.insert(p.at("rank"));
    EXPECT_FALSE(p.at("host").empty());
    // Every result column but the wall time: the same text, i.e. the same double
    // (shortest round-trip form).
    for (const std::string& column : serial.header) {
      if (column == "wall_time_s" || column == "rank" || column == "host") continue;
      EXPECT_EQ(p.at(column), s.at(column)) << column << " of row " << i;
    }
    EXPECT_EQ(without_wall_time(read_text(dir / "mpi" / p.at("folder") / "summary.json")),
              without_wall_time(read_text(dir / "serial" / s.at("folder") / "summary.json")));
    EXPECT_EQ(read_text(dir / "mpi" / p.at("folder") / "history.csv"),
              read_text(dir / "serial" / s.at("folder") / "history.csv"));
  }
  return used;
}

TEST(SweepMpi, ThreeRanksGiveTheSerialResults) {
  const test::ScratchDir dir("sweep_mpi3");
  const auto ranks = compare_mpi_with_serial(dir, 3, 1);
  EXPECT_GE(ranks.size(), 2u) << "the cases all ran on one rank:\n" << read_text(dir / "mpi.txt");
}

TEST(SweepMpi, TwoRanksOfTwoThreadsGiveTheSerialResults) {
  const test::ScratchDir dir("sweep_mpi2x2");
  compare_mpi_with_serial(dir, 2, 2);
}

}  // namespace
