// A prescribed wake (numerics.free_wake = false) moves with the free stream only
// (uvlm::WakeModel::Prescribed), so in still air it stays where the trailing edge shed it and
// a flapping wing sweeps back through it: the case is warned, and with leading_edge =
// "shed" (whose sheet would never leave the leading edge's path) refused; a frozen far wake
// (frozen_wake_cycles) in still air is the same and warned too (pipeline/io/case_file.cpp,
// still_air_prescribed_wake, warn_frozen_wake_in_still_air; docs/case_file.md, free_wake and
// frozen_wake_cycles).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "shipped_case_text.hpp"

namespace {

/// The rigid hawkmoth hover (rigid_hover_case_text) with `numerics` lines added in place of
/// its free_wake (and of its far_wake_cycles if `numerics` sets it).
std::string rigid_hover(const std::string& numerics) {
  std::string toml =
      std::regex_replace(flapsim::test::rigid_hover_case_text(), std::regex("\nfree_wake = true"), "");
  if (numerics.find("far_wake_cycles") != std::string::npos)
    toml = std::regex_replace(toml, std::regex("\nfar_wake_cycles = 0.5"), "");
  return std::regex_replace(toml, std::regex("\\[numerics\\]\n"), "[numerics]\n" + numerics);
}

double last_cycle_cl(const flapsim::test::ScratchDir& dir, const std::string& name,
                     const std::string& numerics) {
  const std::string toml = rigid_hover(numerics);
  EXPECT_NE(toml.find("far_wake_cycles = "), std::string::npos) << "cases/hover.toml has changed";
  std::ofstream(dir / (name + ".toml")) << toml;
  EXPECT_EQ(
      flapsim::test::run_flapsim("run " + (dir / (name + ".toml")).string() + " -o " + (dir / name).string()),
      0)
      << name;
  return flapsim::test::json_number(flapsim::test::read_text(dir / name / "summary.json"), "mean_CL");
}

}  // namespace

TEST(StillAirPrescribedWake, TheRigidHoverLiftsLessWithAPrescribedWakeThanWithItsFreeWake) {
  // The numbers the warning quotes, measured 1 Dec: mean CL of the second cycle with
  // "separated" 2.45 with the prescribed wake and the case's far_wake_cycles = 0.5 (its part
  // older than half a cycle moves on with the far wake), 1.87 with the whole wake prescribed,
  // against 2.77 with the free wake. Each to 0.01, and the prescribed wakes' at least 5 % and
  // 20 % below the free one's (measured −11.5 %, −32.6 %).
  flapsim::test::ScratchDir dir("still_air_prescribed_wake");
  const double prescribed = last_cycle_cl(dir, "prescribed", "free_wake = false\n");
  const double whole = last_cycle_cl(dir, "whole", "free_wake = false\nfar_wake_cycles = 0\n");
  const double free = last_cycle_cl(dir, "free", "free_wake = true\n");
  std::printf("[ value ] mean CL of cycle 2: prescribed wake %.4f (whole wake %.4f), free wake %.4f\n",
              prescribed, whole, free);
  EXPECT_NEAR(prescribed, 2.45, 0.01);
  EXPECT_NEAR(whole, 1.87, 0.01);
  EXPECT_NEAR(free, 2.77, 0.01);
  EXPECT_LT(prescribed, 0.95 * free);
  EXPECT_LT(whole, 0.8 * free);
}

TEST(StillAirPrescribedWake, AFrozenFarWakeInTheRigidHoverLiftsLessThanAConvectedOne) {
  // The numbers the frozen-wake warning quotes, measured 1 Dec: cases/hover.toml as a rigid
  // wing, 4 cycles, "separated", mean CL of cycles 2-4 (summary.json settled_mean_CL) 2.30
  // with the rows older than half a cycle frozen against 2.77 with them convected
  // (far_wake_cycles = 0.5, the case). Each to 0.01; the frozen at least 10 % below.
  flapsim::test::ScratchDir dir("still_air_frozen_wake");
  auto settled = [&](const std::string& name, const std::string& numerics) {
    std::string toml = rigid_hover(numerics);
    toml = std::regex_replace(toml, std::regex("\ncycles = 2"), "\ncycles = 4");
    EXPECT_NE(toml.find("\ncycles = 4"), std::string::npos) << "cases/hover.toml has changed";
    std::ofstream(dir / (name + ".toml")) << toml;
    EXPECT_EQ(flapsim::test::run_flapsim("run " + (dir / (name + ".toml")).string() + " -o " +
                                         (dir / name).string()),
              0);
    return flapsim::test::json_number(flapsim::test::read_text(dir / name / "summary.json"),
                                      "settled_mean_CL");
  };
  const double frozen = settled("frozen", "far_wake_cycles = 0\nfrozen_wake_cycles = 0.5\n");
  const double far = settled("far", "");
  std::printf("[ value ] mean CL of cycles 2-4: frozen far wake %.4f, convected %.4f\n", frozen, far);
  EXPECT_NEAR(frozen, 2.30, 0.01);
  EXPECT_NEAR(far, 2.77, 0.01);
  EXPECT_LT(frozen, 0.9 * far);
}

TEST(StillAirPrescribedWake, AShedLeadingEdgeInStillAirWithAPrescribedWakeIsBadInput) {
  // Exit status 2 naming the file, the line of free_wake and the key, nothing written
  // (measured with the combination before it was refused: mean CL 4.71 with the case's far
  // wake, 8.45 without, against 2.99 with the free wake).
  flapsim::test::ScratchDir dir("still_air_prescribed_shed");
  const std::string toml = rigid_hover("leading_edge = \"shed\"\nfree_wake = false\n");
  std::ofstream(dir / "case.toml") << toml;
  int line = 1;
  for (std::size_t at = 0; at < toml.find("free_wake = false"); ++at) line += toml[at] == '\n';
  const auto r = flapsim::test::run_flapsim_capturing_stderr(
      dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("case.toml:" + std::to_string(line) + ": key 'numerics.free_wake'"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("set free_wake = true"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "history.csv"));
}
