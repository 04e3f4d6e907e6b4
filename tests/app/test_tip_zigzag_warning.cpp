// A structure that rings at the time step's rate ends "ok" on a motion that is the
// integrator's, not the wing's: its tip's bend or twist turns back at two steps in a row.
// summary.json records the largest such zigzag (largest_tip_zigzag_deg, _step;
// pipeline/app/step_zigzag.hpp) and the report warns of one beyond 1 deg (docs/fsi.md, "A tip
// that zigzags from step to step"). Before 5 Dec a 40 × 10 mm plate of a 50 µm film on its FEM
// (ρ∞ = 0.9) zigzagged by 5.9 deg from step 64 of 80, its mean drive power −6.4 mW against
// its chain's +1.4 mW, and ended "ok" with no word of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "app/history_csv.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/run_results.hpp"
#include "pipeline/app/step_zigzag.hpp"

namespace {

using namespace flapsim;

constexpr double kDeg = std::numbers::pi / 180.0;

// A smooth motion turns back once at each extreme, never at two steps in a row: 25° cos 2πs
// at 40 steps a cycle has none. Alternating ±2° added from sample 30 on: the zigzag is half
// the smallest of three alternating steps, 4° ± the cosine's step.
TEST(TipZigzag, ASmoothMotionHasNoneAndAnAlternationIsMeasured) {
  std::vector<double> smooth, rung;
  for (int i = 0; i < 80; ++i) {
    const double x = 25.0 * kDeg * std::cos(2.0 * std::numbers::pi * i / 40.0);
    smooth.push_back(x);
    rung.push_back(x + (i >= 30 ? (i % 2 ? 2.0 : -2.0) * kDeg : 0.0));
  }
  EXPECT_EQ(app::largest_step_zigzag(smooth).step, 0);
  EXPECT_EQ(app::largest_step_zigzag(smooth).amplitude, 0.0);
  const app::StepZigzag z = app::largest_step_zigzag(rung);
  // Largest at the cosine's extremes (samples 41 and 81, phase 0), where its steps are
  // smallest: the three steps are 4° ± 25°(1 − cos 2π/40), half the smallest 1.8461°.
  EXPECT_NEAR(z.amplitude / kDeg, 0.5 * (4.0 - 25.0 * (1.0 - std::cos(2.0 * std::numbers::pi / 40.0))), 1e-9);
  EXPECT_GE(z.step, 31);
  // Exact on a series written out: steps +1, −0.5, +2.5, −1 → half of 0.5 at its first turn (sample 2).
  const app::StepZigzag written = app::largest_step_zigzag({0.0, 1.0, 0.5, 3.0, 2.0});
  EXPECT_DOUBLE_EQ(written.amplitude, 0.25);
  EXPECT_EQ(written.step, 2);
}

// An angle through ±180° (3.0, 3.1, then −3.1 rad) has not turned back: steps modulo 2π.
TEST(TipZigzag, AnAngleThroughHalfATurnIsNoTurnBack) {
  EXPECT_EQ(app::largest_step_zigzag({3.0, 3.1, -3.1, -3.0, -2.9}).step, 0);
}

app::RunResults zigzag_results(double degrees) {
  app::RunResults r;
  r.set("case", "plate");
  r.set("largest_tip_zigzag_deg", degrees);
  r.set("largest_tip_zigzag_step", 75L);
  return r;
}

TEST(TipZigzag, TheReportWarnsOfAZigzagBeyondOneDegree) {
  const std::string warned = app::run_report(zigzag_results(5.86));
  EXPECT_NE(warned.find("warning: the wing's tip zigzags from step to step, by up to 5.86 deg"),
            std::string::npos)
      << warned;
  EXPECT_NE(warned.find("the largest at step 75"), std::string::npos) << warned;
  EXPECT_NE(warned.find("Lower numerics.rho_infinity"), std::string::npos) << warned;
  // 0.48°: the largest of the shipped studies' chains (step_zigzag.hpp); a rigid wing has none.
  EXPECT_EQ(app::run_report(zigzag_results(0.48)).find("zigzags"), std::string::npos);
  app::RunResults rigid;
  rigid.set("case", "plate");
  EXPECT_EQ(app::run_report(rigid).find("zigzags"), std::string::npos);
}

// A 60 × 5 mm plate of a 50 µm film on a spar, its 6-body chain flapped at 20 Hz, 40 steps a
// cycle: with ρ∞ = 0.9 its tip's twist rings with 3–4 steps a period (its torsion above what
// the steps resolve) and zigzags by 1.33 deg, warned; with ρ∞ = 0.5 by 0.26 deg (measured 5
// Dec). The summary's value is the history's largest zigzag.
TEST(TipZigzag, AChainWhoseTwistRingsAtTheStepsRateIsWarnedAndLowerRhoInfinityDampsIt) {
  test::ScratchDir dir("tip_zigzag");
  std::ofstream(dir / "slender.toml")
      << "name = \"slender\"\nlength_unit = \"mm\"\n[planform]\n"
         "outline = [[2.5, 0.0], [2.5, 60.0], [-2.5, 60.0], [-2.5, 0.0]]\nclamp_y = 0.5\n"
         "[materials.film]\nyoungs_modulus = 4.0e9\npoisson_ratio = 0.3\ndensity = 1400.0\n"
         "[membrane]\nthickness = 0.05\nmaterial = \"film\"\n[mesh]\nelement_size = 1.0\n"
         "[[veins]]\nname = \"spar\"\npoints = [[2.0, 0.0], [2.0, 58.0]]\nouter_diameter = [0.8, 0.4]\n"
         "wall = [0.1, 0.05]\nmaterial = \"film\"\n";
  for (const double rho : {0.9, 0.5}) {
    const std::string name = rho > 0.7 ? "rho09" : "rho05";
    std::ofstream(dir / (name + ".toml"))
        << "name = \"" << name << "\"\nwing = \"" << (dir / "slender.toml").string()
        << "\"\nlength_unit = \"mm\"\n[kinematics]\nfrequency_hz = 20.0\nrotation_phase = 0.0\n"
           "sweep = { mean_deg = 0.0, cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
           "[structure]\nkind = \"flexible\"\nbodies = 6\n[numerics]\nrho_infinity = "
        << rho
        << "\nsteps_per_cycle = 40\ncycles = 2\nchordwise_panels = 4\nspanwise_panels = 8\n"
           "[output]\nvtk_every = 0\n";
    ASSERT_EQ(test::run_flapsim("run " + (dir / (name + ".toml")).string() + " -o " + (dir / name).string(),
                                dir / (name + ".txt")),
              0);
    const test::HistoryCsv h = test::read_history_csv(dir / name / "history.csv");
    std::vector<double> bend, twist;
    for (double b : h.column("tip_bend_deg")) bend.push_back(b * kDeg);
    for (double t : h.column("tip_twist_deg")) twist.push_back(t * kDeg);
    const double largest =
        std::max(app::largest_step_zigzag(bend).amplitude, app::largest_step_zigzag(twist).amplitude);
    const std::string summary = test::read_text(dir / name / "summary.json");
    // history.csv's angles are printed to 17 digits: the same zigzag to round-off.
    EXPECT_NEAR(test::json_number(summary, "largest_tip_zigzag_deg"), largest / kDeg, 1e-9);
    const bool warned = test::read_text(dir / (name + ".txt")).find("tip zigzags") != std::string::npos;
    if (rho > 0.7) {
      EXPECT_NEAR(largest / kDeg, 1.33, 0.1);
      EXPECT_TRUE(warned);
    } else {
      EXPECT_LT(largest / kDeg, 0.5);
      EXPECT_FALSE(warned);
    }
  }
}

}  // namespace
