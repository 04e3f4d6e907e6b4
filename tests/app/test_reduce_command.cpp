// `flapsim reduce` end to end: outputs written and readable, bad input exits 2
// with nothing written (STYLE/DESIGN: "Bad input and failures").

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "pipeline/chain_file.hpp"

namespace {

namespace fs = std::filesystem;

int run(const std::string& args) {
  const std::string cmd = std::string(FLAPSIM_BINARY) + " " + args + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("flapsim_reduce_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

TEST(ReduceCommand, WritesBeamChainReportAndVtp) {
  const fs::path dir = fresh_dir("ok");
  const std::string wing = std::string(FLAPSIM_SOURCE_DIR) + "/wings/hawkmoth.toml";
  ASSERT_EQ(run("reduce " + wing + " -o " + dir.string() + " --bodies 3"), 0);
  for (const char* f : {"beam.csv", "chain.toml", "reduction.vtp", "report.md", "summary.json"})
    EXPECT_TRUE(fs::is_regular_file(dir / f)) << f;
  // The chain file reads back with the run stage's reader: 3 bodies, sprung root,
  // and a total mass equal to the FEM's (summary.json, strip sums to round-off).
  const flapsim::mbd::ChainModel chain = flapsim::pipeline::read_chain_file((dir / "chain.toml").string());
  EXPECT_EQ(chain.num_bodies(), 3);
  std::ifstream in(dir / "summary.json");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const auto pos = s.find("\"fem_mass_kg\": ");
  ASSERT_NE(pos, std::string::npos);
  const double fem_mass = std::stod(s.substr(pos + 15));
  EXPECT_NEAR(chain.total_mass(), fem_mass, 1e-12 * fem_mass);
  fs::remove_all(dir);
}

TEST(ReduceCommand, MissingWingFileExitsTwoAndWritesNothing) {
  const fs::path dir = fresh_dir("bad");
  EXPECT_EQ(run("reduce /nonexistent/wing.toml -o " + dir.string()), 2);
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
