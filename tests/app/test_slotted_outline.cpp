// An outline with a gap along the chord (a slot from the tip): the vortex lattice spans each
// section from its leading to its trailing edge (uvlm/planform_grid.hpp) and would cover the
// slot. Before: a run in air went ahead with 400 mm² of panels on a 300 mm² wing (only a
// warning). Now a case in air refuses such a wing as bad input naming the wing file, the
// line and the key of the outline (exit status 2; docs/wing_file.md), while the FEM stages,
// which follow the outline, and a run in vacuum accept it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_file.hpp"
#include "robustness_helpers.hpp"
#include "wings/loader/input_error.hpp"

using namespace flapsim::test;

namespace {

// A 10 x 40 mm plate with a 4 mm slot from y = 15 mm to the tip: gap 4 x 25 = 100 mm² of a
// 10 x 40 - 100 = 300 mm² wing, 33.3 %.
const char* const kForkedWing =
    "name = \"forked\"\nlength_unit = \"mm\"\n[planform]\n"
    "outline = [[2.0, 0.0], [2.0, 40.0], [-1.0, 40.0], [-1.0, 15.0], [-5.0, 15.0], [-5.0, 40.0], [-8.0, 40.0], "
    "[-8.0, 0.0]]\nclamp_y = 0.5\n"
    "[materials.pet]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.38\ndensity = 1390.0\n"
    "[membrane]\nthickness = 0.1\nmaterial = \"pet\"\n";

std::string forked_case(const ScratchDir& dir, const std::string& head = "") {
  std::ofstream(dir / "forked.toml") << kForkedWing;
  return replace_once(small_plate_case("rigid", 1, 0, "", head), kSourceDir + "/wings/flat_plate.toml",
                      (dir / "forked.toml").string());
}

TEST(SlottedOutline, ARunInAirRefusesItNamingTheWingFileLineAndKey) {
  ScratchDir dir("slotted_air");
  std::ofstream(dir / "case.toml") << forked_case(dir);
  const flapsim::io::Case c = flapsim::io::load_case_file((dir / "case.toml").string());
  try {
    flapsim::app::build_fsi_setup(c, {});
    FAIL() << "a slotted outline was accepted for a run in air";
  } catch (const flapsim::InputError& e) {
    EXPECT_EQ(e.file(), (dir / "forked.toml").string());
    EXPECT_EQ(e.line(), 4);
    EXPECT_EQ(e.key(), "planform.outline");
    EXPECT_NE(e.message().find("from y = 15 to 40 mm a line along the chord crosses the outline 4 times"),
              std::string::npos) << e.what();
    EXPECT_NE(e.message().find("33.3333 % of the wing's area"), std::string::npos) << e.what();
  }
  EXPECT_EQ(run_flapsim("check " + (dir / "case.toml").string()), 2);
  EXPECT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(SlottedOutline, TheWingItselfAndARunInVacuumAreAccepted) {
  ScratchDir dir("slotted_vacuum");
  std::ofstream(dir / "case.toml") << forked_case(dir, "air = \"none\"\n");
  EXPECT_EQ(run_flapsim("check " + (dir / "forked.toml").string()), 0);  // a warning only
  const flapsim::io::Case c = flapsim::io::load_case_file((dir / "case.toml").string());
  EXPECT_NO_THROW(flapsim::app::build_fsi_setup(c, {}));
}

}  // namespace
