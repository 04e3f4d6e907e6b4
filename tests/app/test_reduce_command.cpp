// `flapsim reduce` end to end: outputs written and readable, bad input exits 2
// with nothing written (docs/output_files.md, "Bad input writes nothing").

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/io/chain_file.hpp"

namespace {

namespace fs = std::filesystem;
using flapsim::test::read_text;
using flapsim::test::run_flapsim;
using flapsim::test::ScratchDir;

TEST(ReduceCommand, WritesBeamChainReportAndVtp) {
  const ScratchDir scratch("reduce_ok");
  const fs::path dir = scratch / "out";
  const std::string wing = std::string(FLAPSIM_SOURCE_DIR) + "/wings/hawkmoth.toml";
  ASSERT_EQ(run_flapsim("reduce " + wing + " -o " + dir.string() + " --bodies 3"), 0);
  for (const char* f : {"beam.csv", "chain.toml", "reduction.vtm", "reduction/stations.vtp", "reduction/joints.vtp", "report.md", "summary.json"})
    EXPECT_TRUE(fs::is_regular_file(dir / f)) << f;
  // The chain file reads back with the run stage's reader: 3 bodies, sprung root,
  // and a total mass equal to the FEM's (summary.json, strip sums to round-off).
  const flapsim::mbd::ChainModel chain = flapsim::io::read_chain_file((dir / "chain.toml").string());
  EXPECT_EQ(chain.num_bodies(), 3);
  const std::string s = read_text(dir / "summary.json");
  const auto pos = s.find("\"fem_mass_kg\": ");
  ASSERT_NE(pos, std::string::npos);
  const double fem_mass = std::stod(s.substr(pos + 15));
  EXPECT_NEAR(chain.total_mass(), fem_mass, 1e-12 * fem_mass);
  // report.md states the stiffness the reduction builds, K = (T C T^T)^-1 with chord slopes
  // (reduction/joint_stiffness.hpp), not the fitted-slope K = (D C_rr D^T)^-1 of a first
  // version (docs/reduction.md, "Why chord slopes").
  const std::string report = read_text(dir / "report.md");
  EXPECT_NE(report.find("K = (T C T^T)^-1"), std::string::npos);
  EXPECT_EQ(report.find("C_rr"), std::string::npos);
}

TEST(ReduceCommand, MissingWingFileExitsTwoAndWritesNothing) {
  const ScratchDir scratch("reduce_bad");
  EXPECT_EQ(run_flapsim("reduce /nonexistent/wing.toml -o " + (scratch / "out").string()), 2);
  EXPECT_FALSE(fs::exists(scratch / "out"));
}

}  // namespace
