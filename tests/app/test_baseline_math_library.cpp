// The same results on any x86-64 CPU, the C library's math functions included
// (pipeline/app/cli/baseline_math_library.hpp; docs/performance.md, "The C library's math
// functions"). A CPU without FMA and AVX2 is emulated by hiding those features from glibc
// (GLIBC_TUNABLES glibc.cpu.hwcaps) and taking flapsim's SSE2 kernels (FLAPSIM_KERNEL=scalar):
// the flexible hover's history must be the same bytes as on this CPU. Before the program
// took the baseline builds itself, on a CPU with FMA the two histories differed from their
// 15th line on (the FMA builds of atan2, sin, exp … round some arguments differently).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

const std::string kBaselineSource = FLAPSIM_SOURCE_DIR;

// cases/hover_flexible.toml cut to one wingbeat without ParaView output, in DIR/case.toml.
std::string one_wingbeat_hover(const flapsim::test::ScratchDir& dir) {
  std::string toml = flapsim::test::read_text(kBaselineSource + "/cases/hover_flexible.toml");
  auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = toml.find(from);
    EXPECT_NE(at, std::string::npos) << "cases/hover_flexible.toml has changed: " << from;
    if (at != std::string::npos) toml.replace(at, from.size(), to);
  };
  replace("wing = \"../wings/hawkmoth.toml\"", "wing = \"" + kBaselineSource + "/wings/hawkmoth.toml\"");
  replace("cycles = 3", "cycles = 1");
  replace("vtk_every = 2", "vtk_every = 0");
  const std::string file = (dir / "case.toml").string();
  std::ofstream(file) << toml;
  return file;
}

TEST(BaselineMathLibrary, ACpuWithoutFmaOrAvx2GivesTheSameHistoryBytes) {
  const flapsim::test::ScratchDir dir("baseline_libm");
  const std::string file = one_wingbeat_hover(dir);
  const std::string chain = " --chain " + kBaselineSource + "/cases/chains/hawkmoth_10_bodies.toml";
  ASSERT_EQ(flapsim::test::run_flapsim("run " + file + chain + " -o " + (dir / "this_cpu").string()), 0);
  ASSERT_EQ(flapsim::test::run_flapsim_in_shell(
                "env GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX,-AVX2,-FMA,-FMA4,-AVX512F FLAPSIM_KERNEL=scalar",
                "run " + file + chain + " -o " + (dir / "old_cpu").string()),
            0);
  const std::string here = flapsim::test::read_text(dir / "this_cpu/history.csv");
  const std::string old = flapsim::test::read_text(dir / "old_cpu/history.csv");
  ASSERT_GT(here.size(), 10000u);  // 100 steps of history
  EXPECT_TRUE(here == old) << "the histories differ: the C library's math functions depend on the CPU";
}

}  // namespace
