// The shipped MAV film-wing examples (cases/mav_film_wing.toml on the wing's 8-body chain,
// cases/mav_film_wing_fem.toml on its FEM; wings/mav_film_wing.toml) must run through: the
// FEM case without a warning, the chain case with the one warning that its chain is not the
// wing (reduce's static row −71.4 %: the chain lifts 1.86 × the FEM, docs/fsi.md, "The MAV
// film wing's chain against its FEM"); until 6 Dec the chain case was the example, unwarned.
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

// The number of "warning:" lines in a command's standard error.
int warnings_in(const std::string& err) {
  int n = 0;
  for (std::size_t at = err.find("warning:"); at != std::string::npos; at = err.find("warning:", at + 1)) ++n;
  return n;
}

TEST(MavFilmWingCase, ChecksAndRunsToTheEndWarnedThatItsChainIsNotTheWing) {
  ScratchDir dir("mav_film_wing_case");
  const std::string case_file = kSource + "/cases/mav_film_wing.toml";
  const std::string static_warning =
      "warning: the chain reduced in process responds to a static load otherwise than "
      "the FEM";
  const FlapsimOutcome check = run_flapsim_capturing_stderr(dir.path(), "check " + case_file);
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_EQ(warnings_in(check.err), 1) << check.err;
  EXPECT_NE(check.err.find(static_warning), std::string::npos) << check.err;

  const auto out = dir / "run";
  const FlapsimOutcome run = run_flapsim_capturing_stderr(dir.path(), "run " + case_file + " --vtk-every 0 -o " + out.string());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(warnings_in(run.err), 1) << run.err;
  EXPECT_NE(run.err.find(static_warning), std::string::npos) << run.err;
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

// The wing's answer: its own FEM (cases/mav_film_wing_fem.toml, 3.5 mm elements; 3 wingbeats
// about 15 s on one thread) runs without a warning, and the chain's lift is not the wing's:
// measured 6 Dec, FEM 1.984 mN (2.5 and 1.6 mm meshes 1.985, 1.980) against the chain's
// 3.688 mN (+86 %; 4 to 16 bodies 3.46–3.55 mN). The chain's static warning is there for a
// run that it changes: asserted beyond the warning's own 10 %.
TEST(MavFilmWingCase, TheFemCaseRunsWithoutAWarningAndTheChainLiftsOtherwise) {
  ScratchDir dir("mav_film_wing_fem_case");
  const std::string fem_case = kSource + "/cases/mav_film_wing_fem.toml";
  const FlapsimOutcome check = run_flapsim_capturing_stderr(dir.path(), "check " + fem_case);
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_EQ(warnings_in(check.err), 0) << check.err;
  const FlapsimOutcome fem = run_flapsim_capturing_stderr(
      dir.path(), "run " + fem_case + " --threads 1 --vtk-every 0 -q -o " + (dir / "fem").string());
  ASSERT_EQ(fem.status, 0) << fem.err;
  EXPECT_EQ(warnings_in(fem.err), 0) << fem.err;
  const std::string fem_summary = read_text(dir / "fem" / "summary.json");
  EXPECT_EQ(json_number(fem_summary, "steps"), 240.0);
  const double fem_cl = json_number(fem_summary, "mean_CL");
  EXPECT_GT(fem_cl, 0.0);  // the film's pitch about the rod lifts (the rigid wing: none, above)
  EXPECT_LT(fem_cl, quasi_steady_cl(60.0) * std::numbers::pi * std::numbers::pi / 8.0);
  EXPECT_LT(json_number(fem_summary, "peak_tip_twist_deg"), 30.0);

  const FlapsimOutcome chain = run_flapsim_capturing_stderr(
      dir.path(), "run " + kSource + "/cases/mav_film_wing.toml --threads 1 --vtk-every 0 -q -o " +
                      (dir / "chain").string());
  ASSERT_EQ(chain.status, 0) << chain.err;
  const double chain_cl = json_number(read_text(dir / "chain" / "summary.json"), "mean_CL");
  std::printf("[ value ] mav_film_wing: mean CL chain %.4f, FEM %.4f (chain / FEM %.3f)\n", chain_cl, fem_cl,
              chain_cl / fem_cl);
  EXPECT_GT(chain_cl / fem_cl - 1.0, 0.10);
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
