// Errors found after a case file is read (the run's setup and size) name the line of the
// key, as the reader's own errors do. Before: "case.toml: key 'numerics.cycles': the run
// needs about 59.3 GB of memory …" and "case.toml: key 'air.freestream': a vertical free
// stream …" without a line (io::Case kept no lines; now Case::key_lines).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

std::string check_stderr(const ScratchDir& dir, const std::string& case_text) {
  std::ofstream(dir / "case.toml") << case_text;
  const std::string err = (dir / "err.txt").string();
  const int status = std::system(("FLAPSIM_QUIET=1 OMP_NUM_THREADS=1 '" + std::string(FLAPSIM_BINARY) + "' check " +
                                  (dir / "case.toml").string() + " > /dev/null 2> " + err)
                                     .c_str());
  EXPECT_EQ(WEXITSTATUS(status), 2);
  return read_text(err);
}

const std::string kHead = "wing = \"" + kSourceDir +
                          "/wings/flat_plate.toml\"\n"                       // 1
                          "[kinematics]\n"                                   // 2
                          "frequency_hz = 20\n"                              // 3
                          "sweep = { cos_deg = [50.0] }\n"                   // 4
                          "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"  // 5
                          "[structure]\n"                                    // 6
                          "kind = \"rigid\"\n";                              // 7

TEST(CaseErrorLines, TheRunsSizeAndAVerticalFreeStreamNameTheirLines) {
  ScratchDir dir("case_error_lines");
  // 10^8 steps with every wake row kept: far beyond any machine's memory.
  const std::string big = check_stderr(dir, kHead + "[numerics]\nsteps_per_cycle = 1000000\ncycles = 100\n");
  EXPECT_NE(big.find("case.toml:10: key 'numerics.cycles': the run needs about"), std::string::npos) << big;
  const std::string vertical = check_stderr(dir, kHead + "[air]\nfreestream = [0.0, 0.0, -3.0]\n");
  EXPECT_NE(vertical.find("case.toml:9: key 'air.freestream': a vertical free stream"), std::string::npos)
      << vertical;
}

}  // namespace
