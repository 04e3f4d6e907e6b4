// A wing that only revolves has no wingbeat: its frequency_hz sets the time unit of its
// cycles (docs/kinematics.md, "A revolving wing"). The resonance warnings compared the
// chain's modes with that unit: the 25 um MAV film wing (wings/mav_film_wing_25um.toml, 8
// bodies) revolving with frequency_hz = 13 was warned that its 13.2 Hz torsion mode "lies near
// the wingbeat frequency 13 Hz ... 39 times its static deflection", a warning that moved with
// the chosen time unit. Revolving, no resonance warning; the same wing flapping at 13 Hz is
// warned (the warning still fires where a wingbeat drives the wing).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

std::string film_case(const std::string& motion) {
  return "name = \"film\"\nwing = \"" + std::string(FLAPSIM_SOURCE_DIR) +
         "/wings/mav_film_wing_25um.toml\"\n"
         "[kinematics]\nfrequency_hz = 13.0\nrotation = 50.0\n" +
         motion +
         "[structure]\nkind = \"flexible\"\nbodies = 8\n"
         "[numerics]\nsteps_per_cycle = 40\ncycles = 2\nchordwise_panels = 4\nspanwise_panels = 6\n";
}

TEST(RevolvingResonance, AWingThatOnlyRevolvesIsNotWarnedOfAWingbeatsResonance) {
  const flapsim::test::ScratchDir dir("revolving_resonance");
  std::ofstream(dir / "revolving.toml")
      << film_case("sweep = 0.0\nrevolution = { rate_deg_per_s = -360.0 }\n");
  std::ofstream(dir / "flapping.toml") << film_case("sweep = { cos_deg = [40.0] }\n");
  const auto revolving =
      flapsim::test::run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "revolving.toml").string());
  ASSERT_EQ(revolving.status, 0) << revolving.err;
  EXPECT_EQ(revolving.err.find("wingbeat frequency"), std::string::npos) << revolving.err;
  const auto flapping =
      flapsim::test::run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "flapping.toml").string());
  ASSERT_EQ(flapping.status, 0) << flapping.err;
  EXPECT_NE(flapping.err.find("lies near the wingbeat frequency 13 Hz"), std::string::npos) << flapping.err;
}

}  // namespace
