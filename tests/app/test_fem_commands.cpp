// `flapsim mesh` and `flapsim modes` end to end: their files, and exit status 2 with
// nothing written on bad input.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;
using flapsim::test::run_flapsim;

TEST(FemCommands, MeshAndModesWriteTheirFiles) {
  const flapsim::test::ScratchDir scratch("fem_commands");
  const fs::path dir = scratch / "out";
  const std::string wing = std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml";
  ASSERT_EQ(run_flapsim("mesh " + wing + " -o " + dir.string()), 0);
  EXPECT_TRUE(fs::exists(dir / "mesh.msh"));
  EXPECT_TRUE(fs::exists(dir / "mesh.vtu"));
  ASSERT_EQ(run_flapsim("modes " + wing + " -o " + dir.string() + " --modes 4"), 0);
  std::ifstream csv(dir / "modes.csv");
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_EQ(header, "mode,frequency_hz,kind");
  EXPECT_EQ(first.substr(0, 2), "1,");
  EXPECT_TRUE(fs::exists(dir / "fem.vtu"));
  // Bad input: exit status 2 and nothing written.
  const fs::path bad = scratch / "bad";
  EXPECT_EQ(run_flapsim("modes " + wing + " -o " + bad.string() + " --modes 0"), 2);
  EXPECT_EQ(run_flapsim("mesh " + (scratch / "missing.toml").string() + " -o " + bad.string()), 2);
  EXPECT_FALSE(fs::exists(bad / "modes.csv"));
}

}  // namespace
