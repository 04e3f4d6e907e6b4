// flapsim sweep over MPI: `mpirun --oversubscribe -np 3` on a 5-case sweep gives the
// serial sweep's results, bit for bit (the cases are deterministic: rigid wing, one
// OpenMP thread), with the cases spread over at least two ranks.
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

TEST(SweepMpi, ThreeRanksGiveTheSerialResults) {
  const test::ScratchDir dir("sweep_mpi");
  std::ofstream(dir / "case.toml") << test::tiny_plate_case(48);
  const std::string sweep =
      "sweep " + (dir / "case.toml").string() + " --vary kinematics.rotation_phase=-0.1:0.05:0.1 -j 1 -o ";
  ASSERT_EQ(test::run_flapsim(sweep + (dir / "serial").string()), 0);

  // Open MPI refuses to run as root unless told twice; --oversubscribe: 3 ranks on any core count.
  const std::string mpi =
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 FLAPSIM_QUIET=1 "
      "OMP_NUM_THREADS=1 timeout 300 mpirun --oversubscribe -np 3 '" +
      std::string(FLAPSIM_BINARY) + "' " + sweep + (dir / "mpi").string() + " > '" +
      (dir / "mpi.txt").string() + "' 2>&1";
  const int status = std::system(mpi.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(dir / "mpi.txt");

  const auto serial = read_sweep_table((dir / "serial" / "sweep.csv").string());
  const auto parallel = read_sweep_table((dir / "mpi" / "sweep.csv").string());
  ASSERT_TRUE(parallel.rectangular);
  EXPECT_EQ(parallel.header, serial.header);
  ASSERT_EQ(serial.rows.size(), 5u);
  ASSERT_EQ(parallel.rows.size(), 5u);
  std::set<std::string> ranks;
  for (std::size_t i = 0; i < 5; ++i) {
    const auto& s = serial.rows[i];
    const auto& p = parallel.rows[i];
    EXPECT_EQ(p.at("status"), "ok");
    ranks.insert(p.at("rank"));
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
  EXPECT_GE(ranks.size(), 2u) << "the cases all ran on one rank:\n" << read_text(dir / "mpi.txt");
}

}  // namespace
