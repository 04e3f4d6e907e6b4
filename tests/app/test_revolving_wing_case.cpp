// A revolving wing written as users write it (docs/kinematics.md, "A revolving wing"):
// [kinematics] revolution = { rate_deg_per_s, ramp_s } runs, its coefficients refer to the
// steady revolution's speed at r2·R, and a revolution without a rate is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>

#include "app/history_csv.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

using flapsim::test::read_text;
using flapsim::test::run_flapsim;

const std::string kSource = FLAPSIM_SOURCE_DIR;

std::string revolving_case(const std::string& revolution) {
  return "name = \"revolve\"\nwing = \"" + kSource +
         "/wings/flat_plate.toml\"\n"
         "[kinematics]\nfrequency_hz = 2.0\nsweep = 0.0\nrotation = 45.0\n" +
         revolution +
         "\n"
         "[structure]\nkind = \"rigid\"\n"
         "[numerics]\nsteps_per_cycle = 40\ncycles = 1\nchordwise_panels = 3\nspanwise_panels = 6\n"
         "[output]\nvtk_every = 0\n";
}

TEST(RevolvingWingCase, RunsAndRefersItsCoefficientsToTheSteadyRevolution) {
  // wings/flat_plate.toml: R = 40 mm from the pivot, uniform chord, so r2 = 1/√3 (the radius
  // of gyration of a rectangle from its end). At Ω = 720°/s the reference speed is
  // Ω r2 R = 4π · 0.040 / √3 = 0.29022 m/s, reached after the 0.1 s ramp; one period of
  // 0.5 s is one revolution.
  flapsim::test::ScratchDir dir("revolving_case");
  std::ofstream(dir / "case.toml") << revolving_case(
      "revolution = { rate_deg_per_s = -720.0, ramp_s = 0.1 }");
  ASSERT_EQ(
      run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string(), dir / "run.txt"),
      0);
  // The report has no rotation phase for a wing that never reverses (it printed "base nan").
  const std::string report = read_text(dir / "run.txt");
  EXPECT_NE(report.find("mean lift (last cycle)"), std::string::npos) << report;
  EXPECT_EQ(report.find("rotation phase"), std::string::npos) << report;
  const std::string summary = read_text(dir / "out" / "summary.json");
  const double r2 = flapsim::test::json_number(summary, "r2");
  EXPECT_NEAR(r2, 1.0 / std::sqrt(3.0), 1e-6);
  const double expected = 4.0 * std::numbers::pi * 0.040 * r2;
  EXPECT_NEAR(flapsim::test::json_number(summary, "reference_speed_m_s"), expected, 1e-9 * expected);
  // Leading edge first at 45°: the wing lifts.
  EXPECT_GT(flapsim::test::json_number(summary, "mean_lift_N"), 0.0);
}

// A ramp longer than a cycle (frequency_hz only sets the time unit of a revolving wing):
// the diverged-force bound took the wing's fastest speed over the first cycle alone, where
// the wing has hardly started, and counted no force of its acceleration; such runs stopped
// as "the lattice has diverged" (exit 3) at forces of nanonewtons (here: ramps of 0.5 s and
// 5 s at 26.1 Hz, 10⁶ s at 2 Hz; the shipped Robofly case with a 2 s ramp at step 87). The
// bound now samples the last cycle too and adds the wing's added-mass force
// (diverged_force.hpp); the runs complete and the wing lifts.
TEST(RevolvingWingCase, ARampLongerThanACycleRunsToTheEnd) {
  for (const auto& [ramp, frequency] : {std::pair{"0.5", "26.1"}, {"5.0", "26.1"}, {"1e6", "2.0"}}) {
    flapsim::test::ScratchDir dir(std::string("revolving_long_ramp_") + ramp);
    std::string text =
        revolving_case(std::string("revolution = { rate_deg_per_s = -720.0, ramp_s = ") + ramp + " }");
    text.replace(text.find("cycles = 1"), 10, "cycles = 2");
    text.replace(text.find("frequency_hz = 2.0"), 18, std::string("frequency_hz = ") + frequency);
    std::ofstream(dir / "case.toml") << text;
    const auto r = flapsim::test::run_flapsim_capturing_stderr(
        dir.path(), "run " + (dir / "case.toml").string() + " -o " + (dir / "out").string());
    EXPECT_EQ(r.status, 0) << "ramp " << ramp << " s: " << r.err;
    EXPECT_GT(flapsim::test::json_number(read_text(dir / "out" / "summary.json"), "mean_lift_N"), 0.0)
        << ramp;
  }
}

// Without a ramp the wing turns at Ω from t = 0 (docs/kinematics.md), and the reference
// speed is Ω r2 R: until 2 Dec the rate at t = 0 itself was 0, the reference speed (a mean
// of 720 samples of a period from t = 0) 719/720 of it, CL and CD 0.28 % high
// (cases/robofly_revolving.toml: 0.99418 against 2π · 0.25 · 0.63380 = 0.99556 m/s).
TEST(RevolvingWingCase, WithoutARampTheReferenceSpeedIsTheRevolutionsFromTheStart) {
  flapsim::test::ScratchDir dir("revolving_case_no_ramp");
  std::ofstream(dir / "case.toml") << revolving_case("revolution = { rate_deg_per_s = -720.0 }");
  ASSERT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 0);
  const std::string summary = read_text(dir / "out" / "summary.json");
  const double expected = 4.0 * std::numbers::pi * 0.040 * flapsim::test::json_number(summary, "r2");
  EXPECT_NEAR(flapsim::test::json_number(summary, "reference_speed_m_s"), expected, 1e-9 * expected);
}

// flapsim check's kinematics table of a revolving wing: the revolution's rate and ramp, and
// the instants labelled "at rest" (t = 0) and "revolving". Before, the table said "reversal"
// at t = 0 and "downstroke" at every other instant, the words of a flapping stroke.
TEST(RevolvingWingCase, CheckNamesTheRevolutionNotStrokes) {
  flapsim::test::ScratchDir dir("revolving_case_check");
  std::ofstream(dir / "case.toml") << revolving_case(
      "revolution = { rate_deg_per_s = -720.0, ramp_s = 0.1 }");
  ASSERT_EQ(run_flapsim("check " + (dir / "case.toml").string(), dir / "check.txt"), 0);
  const std::string said = read_text(dir / "check.txt");
  EXPECT_NE(said.find("revolution                   -720 deg/s after a ramp of 0.1 s, from rest"),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("at rest"), std::string::npos) << said;
  EXPECT_NE(said.find("revolving"), std::string::npos) << said;
  EXPECT_EQ(said.find("downstroke"), std::string::npos) << said;
  EXPECT_EQ(said.find("reversal"), std::string::npos) << said;
}

// A rigid wing's sections turn with its base: over three revolutions phi_tip_deg and
// phi_outer_deg read phi_base_deg (to round-off), past 360° as it does. Until 2 Dec 2026 the
// sections' angles were read into (−180°, 180°] (9, 99, −171, 0 where the base read 9, 459,
// 909, 2160), and a flexible wing's lag behind its base jumped by 360°.
TEST(RevolvingWingCase, ARigidWingsSectionsCountTheTurnsAsItsBase) {
  flapsim::test::ScratchDir dir("revolving_case_turns");
  std::string c = revolving_case("revolution = { rate_deg_per_s = 720.0 }");
  c.replace(c.find("cycles = 1"), 10, "cycles = 3");
  c.insert(c.find("[kinematics]"), "air = \"none\"\n");
  std::ofstream(dir / "case.toml") << c;
  ASSERT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 0);
  const flapsim::test::HistoryCsv h = flapsim::test::read_history_csv(dir / "out" / "history.csv");
  ASSERT_EQ(h.rows.size(), 120u);
  EXPECT_NEAR(h.at(120, "phi_base_deg"), 1080.0, 1e-9);  // 720°/s for 1.5 s
  for (long step = 1; step <= 120; ++step) {
    for (const char* section : {"phi_tip_deg", "phi_outer_deg"})
      ASSERT_NEAR(h.at(step, section), h.at(step, "phi_base_deg"), 1e-6) << section << " at step " << step;
    ASSERT_NEAR(h.at(step, "alpha_tip_deg"), h.at(step, "alpha_base_deg"), 1e-6) << "step " << step;
  }
}

TEST(RevolvingWingCase, ARevolutionWithoutARateIsRefusedNamingTheKey) {
  flapsim::test::ScratchDir dir("revolving_case_zero");
  std::ofstream(dir / "case.toml") << revolving_case("revolution = { rate_deg_per_s = 0.0 }");
  EXPECT_EQ(run_flapsim("check " + (dir / "case.toml").string()), 2);
  std::ofstream(dir / "ramp.toml") << revolving_case("revolution = { rate_deg_per_s = 90.0, ramp_s = -1.0 }");
  EXPECT_EQ(run_flapsim("check " + (dir / "ramp.toml").string()), 2);
}

}  // namespace
