// The shipped MAV film-wing example (cases/mav_film_wing.toml, wings/mav_film_wing.toml)
// must be a working design: check and run end with exit status 0 and without a warning.
// Before (25 µm film, now wings/mav_film_wing_25um.toml): its chain's torsion modes, 13.2
// and 25.7 Hz, lay at the 12 Hz wingbeat and twice it, check and run warned, the film spun
// about the leading-edge rod (tip twisted 164°) and the run stopped with exit status 3 at
// step 33. The 125 µm film puts the chain's first mode at 41.9 Hz (docs/reduction.md).
// The whole case (3 cycles of 80 steps) runs here: about 2 s.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_file.hpp"

namespace {

using flapsim::test::FlapsimOutcome;
using flapsim::test::json_number;
using flapsim::test::run_flapsim_capturing_stderr;
using flapsim::test::read_text;
using flapsim::test::ScratchDir;

const std::string kSource = FLAPSIM_SOURCE_DIR;

/// Dickinson et al. 1999's fit of the translational lift coefficient (α in degrees).
double quasi_steady_cl(double alpha_deg) {
  return 0.225 + 1.58 * std::sin((2.13 * alpha_deg - 7.20) * std::numbers::pi / 180.0);
}

TEST(MavFilmWingCase, ChecksAndRunsToTheEndWithoutAWarning) {
  ScratchDir dir("mav_film_wing_case");
  const std::string case_file = kSource + "/cases/mav_film_wing.toml";
  const FlapsimOutcome check = run_flapsim_capturing_stderr(dir.path(), "check " + case_file);
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_EQ(check.err.find("warning"), std::string::npos) << check.err;

  const auto out = dir / "run";
  const FlapsimOutcome run = run_flapsim_capturing_stderr(dir.path(), "run " + case_file + " --vtk-every 0 -o " + out.string());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
  const std::string summary = read_text(out / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"ok\""), std::string::npos) << summary;
  EXPECT_EQ(json_number(summary, "steps"), 240.0);  // 3 cycles x 80 steps, all of them
  const double bend = json_number(summary, "peak_tip_bend_deg"), twist = json_number(summary, "peak_tip_twist_deg");
  const double cl = json_number(summary, "mean_CL");
  std::printf("[ value ] mav_film_wing: peak tip bend %.2f deg, twist %.2f deg, mean CL %.4f, mean lift %.4g N\n", bend,
              twist, cl, json_number(summary, "mean_lift_N"));
  // The joint springs hold to 30° (sin θ/θ = 0.955; run's large-deflection rule,
  // docs/case_file.md, "Warnings"); the warning's absence above says the same, this says why.
  EXPECT_LT(bend, 30.0);
  EXPECT_LT(twist, 30.0);
  // The base holds the chord normal to the stroke plane (rotation 90°): a rigid wing gives
  // no mean lift by symmetry (flapsim run with kind = "rigid": -4.7e-18). The lift comes
  // from the film pitching back about the rod: positive. Upper bound: with the tip twisted
  // under 30° every section meets the air at 60…120°, where the translational coefficient
  // of [Dickinson et al. 1999] is at most CL(60°) = 1.59; referred to the mean speed at r2
  // (summary's reference_kind flapping_r2: U = 4 Φ f r2) a sinusoidal sweep adds
  // mean(φ̇²)/mean(|φ̇|)² = π²/8.
  EXPECT_GT(cl, 0.0);
  EXPECT_LT(cl, quasi_steady_cl(60.0) * std::numbers::pi * std::numbers::pi / 8.0);
}

TEST(MavFilmWingCase, TheFirstDesignWithA25MicrometreFilmIsWarnedNearResonance) {
  // The lesson kept in wings/mav_film_wing_25um.toml: the same case on it is warned before
  // the run (its chain's first modes within 0.82…1.41 f and 1.63…2.83 f).
  ScratchDir dir("mav_film_wing_25um_case");
  std::string text = read_text(kSource + "/cases/mav_film_wing.toml");
  const std::string wing_line = "wing = \"../wings/mav_film_wing.toml\"";
  ASSERT_NE(text.find(wing_line), std::string::npos);
  text.replace(text.find(wing_line), wing_line.size(), "wing = \"" + kSource + "/wings/mav_film_wing_25um.toml\"");
  std::ofstream(dir / "case.toml") << text;
  const FlapsimOutcome check = run_flapsim_capturing_stderr(dir.path(), "check " + (dir / "case.toml").string());
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.err.find("(torsion), "), std::string::npos) << check.err;
  EXPECT_NE(check.err.find("wingbeat frequency"), std::string::npos) << check.err;
}

// The FEM case as shipped runs through its first wingbeat, the reversal at half of it where a
// film's coupling is hardest: at 80 steps a wingbeat it stopped at step 42 (the coupling not
// converged in 3 x 50 sub-iterations) from 1 Dec (the older wake's hold taken later in a step
// moved its path) until 2 Dec, unseen, as no test ran it (docs/fsi.md, "The MAV case's
// mesh"). One wingbeat of the case, its every other key as shipped: exit 0, all its steps, and
// the film pitching about the rod within the ±22–24° every mesh gave (that section's table).
TEST(MavFilmWingCase, TheFemCaseRunsThroughItsFirstWingbeat) {
  ScratchDir dir("mav_film_wing_fem_case");
  std::string text = read_text(kSource + "/cases/mav_film_wing_25um_fem.toml");
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"wing = \"../wings/", "wing = \"" + kSource + "/wings/"},
        {"\ncycles = 5", "\ncycles = 1"}}) {
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
  }
  std::ofstream(dir / "case.toml") << text;
  const auto out = dir / "run";
  const FlapsimOutcome run = run_flapsim_capturing_stderr(
      dir.path(), "run " + (dir / "case.toml").string() + " --vtk-every 0 -o " + out.string());
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string summary = read_text(out / "summary.json");
  const double steps_per_cycle = json_number(summary, "steps"),
               twist = json_number(summary, "peak_tip_twist_deg");
  std::printf(
      "[ value ] mav_film_wing_25um_fem, one wingbeat: %.0f steps, peak tip twist %.2f deg, mean lift %.4g "
      "N\n",
      steps_per_cycle, twist, json_number(summary, "mean_lift_N"));
  EXPECT_EQ(steps_per_cycle, 100.0);  // the case's steps_per_cycle, all of them
  EXPECT_GT(twist, 15.0);
  EXPECT_LT(twist, 30.0);
}

// Its FEM case takes the first-order ∂Γ/∂t into its lattice (numerics.circulation_rate =
// "bdf1": chosen when BDF2 grew a sawtooth at 160 steps a wingbeat, and its convergence was
// measured with it; docs/fsi.md "Film wings", "Split steps: the unsteady load held"); the 75
// mm film wing's case keeps the default BDF2.
TEST(MavFilmWingCase, TheFemCaseTakesTheFirstOrderCirculationRateIntoItsLattice) {
  const flapsim::io::Case mav = flapsim::io::load_case_file(kSource + "/cases/mav_film_wing_25um_fem.toml");
  EXPECT_EQ(mav.numerics.circulation_rate, flapsim::io::CirculationRate::Bdf1);
  EXPECT_TRUE(flapsim::app::build_fsi_setup(mav, {}).model.lattice.first_order_circulation_rate);
  const flapsim::io::Case film = flapsim::io::load_case_file(kSource + "/cases/film_wing_fem.toml");
  EXPECT_FALSE(flapsim::app::build_fsi_setup(film, {}).model.lattice.first_order_circulation_rate);
}

}  // namespace
