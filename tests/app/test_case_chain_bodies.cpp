// structure.bodies is checked against the chain a flexible case runs with: a case that
// says 3 bodies run with a 2-body chain is bad input (exit status 2, nothing written),
// named by the case file, the line and the key.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace fs = std::filesystem;
using flapsim::test::read_text;

namespace {

const std::string kSource = FLAPSIM_SOURCE_DIR;

TEST(CaseChainBodies, BodiesThatDisagreeWithTheChainAreBadInput) {
  flapsim::test::ScratchDir dir("case_chain_bodies");
  // A two-body chain (the format of docs/multibody.md).
  std::ofstream(dir / "chain.toml")
      << "root = \"rigid\"\n"
         "[[bodies]]\nlength = 0.02\nmass = 1e-5\ncenter_of_mass = [0, 0.01, 0]\n"
         "inertia = [[4e-10,0,0],[0,1e-11,0],[0,0,4e-10]]\n"
         "[[bodies]]\nlength = 0.02\nmass = 1e-5\ncenter_of_mass = [0, 0.01, 0]\n"
         "inertia = [[4e-10,0,0],[0,1e-11,0],[0,0,4e-10]]\n"
         "[bodies.joint]\nbend_stiffness = 1e-3\ntwist_stiffness = 1e-3\n";
  const auto write_case = [&](int bodies) {
    std::ofstream(dir / "case.toml")
        << "name = \"plate\"\n"                                                 // 1
           "wing = \"" + kSource + "/wings/flat_plate.toml\"\n"                 // 2
           "[kinematics]\nfrequency_hz = 26.1\n"                                // 3, 4
           "sweep = { mean_deg = 10.0, cos_deg = [50.0] }\n"                    // 5
           "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"                // 6
           "[structure]\nkind = \"flexible\"\n"                                 // 7, 8
           "bodies = " + std::to_string(bodies) + "\n"                          // 9
           "[numerics]\nsteps_per_cycle = 8\ncycles = 1\nchordwise_panels = 2\nspanwise_panels = 2\n";
  };
  write_case(3);
  const fs::path err = dir / "stderr.txt";
  const std::string cmd = "FLAPSIM_QUIET=1 OMP_NUM_THREADS=1 '" + std::string(FLAPSIM_BINARY) + "' run '" +
                          (dir / "case.toml").string() + "' --chain '" + (dir / "chain.toml").string() +
                          "' -o '" + (dir / "out").string() + "' > /dev/null 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string message = read_text(err);
  EXPECT_NE(message.find("case.toml:9: key 'structure.bodies'"), std::string::npos) << message;
  EXPECT_NE(message.find("has 2"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(dir / "out"));
  // With the chain's number of bodies the same case runs.
  write_case(2);
  EXPECT_EQ(flapsim::test::run_flapsim("run " + (dir / "case.toml").string() + " --chain " +
                                       (dir / "chain.toml").string() + " -o " + (dir / "out").string()),
            0);
}

}  // namespace
