// flapsim optimize with three keys on the rigid hawkmoth (issue 33): rotation phase,
// rotation amplitude and stroke amplitude (array elements of the harmonic series, KEY[i]),
// the most lift per aerodynamic power that lifts at least what the case itself lifts,
// against the best point of a 5 x 5 x 5 grid of the same runs that lifts as much.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "optimize_test_helpers.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

// The varied keys of the problem: δψ, the first sine coefficient of α (the rotation
// amplitude, -45 deg in the case) and the first cosine coefficient of φ (the stroke
// amplitude, 50 deg); the grid's values are each range in 5 steps, the case's own among them.
constexpr const char* kPhase = "kinematics.rotation_phase";
constexpr const char* kRotation = "kinematics.rotation.sin_deg[0]";
constexpr const char* kStroke = "kinematics.sweep.cos_deg[0]";

// cases/rotation_phase_rigid.toml at 40 steps per cycle over 2 cycles (shipped: 100 x 4),
// a fraction of a second per run: its lift and lift per power at the case's own values lie
// within 0.5 % of the full case's (docs/optimize.md, "Three keys").
TEST(OptimizeThreeKeys, BeatsTheBestFeasiblePointOfAFiveCubedGridInUnderAThirdOfItsRuns) {
  const test::ScratchDir dir("optimize_three_keys");
  const std::string text = test::shortened_case("rotation_phase_rigid", 40, 2);
  ASSERT_FALSE(text.empty()) << "cases/rotation_phase_rigid.toml no longer has the keys this test shortens";
  std::ofstream(dir / "case.toml") << text;

  // The constraint: at least the case's own mean lift.
  ASSERT_EQ(test::run_flapsim("run " + (dir / "case.toml").string() + " -q -o " + (dir / "own").string()), 0);
  const std::string own_lift = test::summary_value(test::read_text(dir / "own" / "summary.json"), "mean_lift_N");
  ASSERT_FALSE(own_lift.empty());
  const double least_lift = std::stod(own_lift);  // [N]

  ASSERT_EQ(test::run_flapsim("sweep " + (dir / "case.toml").string() + " --vary " + kPhase + "=-0.2:0.1:0.2 --vary '" +
                              kRotation + "=-65:10:-25' --vary '" + kStroke + "=40:5:60' -j 2 -q -o " +
                              (dir / "grid").string()),
            0);
  const auto grid = test::read_sweep_table((dir / "grid" / "sweep.csv").string());
  ASSERT_EQ(grid.rows.size(), 125u);
  double grid_best = -INFINITY;  // [N/W]
  std::string grid_best_point;
  for (const auto& row : grid.rows) {
    ASSERT_EQ(row.at("status"), "ok");
    const double lift = std::stod(row.at("mean_lift_N"));
    // The grid holds the case's own point: the same inputs give the same lift.
    if (std::stod(row.at(kPhase)) == 0.0 && std::stod(row.at(kRotation)) == -45.0 && std::stod(row.at(kStroke)) == 50.0) {
      EXPECT_EQ(lift, least_lift);
    }
    const double per_power = std::stod(row.at("lift_per_power_N_W"));
    if (lift >= least_lift && per_power > grid_best) {
      grid_best = per_power;
      grid_best_point = row.at(kPhase) + ", " + row.at(kRotation) + ", " + row.at(kStroke);
    }
  }
  ASSERT_TRUE(std::isfinite(grid_best));

  ASSERT_EQ(test::run_flapsim("optimize " + (dir / "case.toml").string() + " --vary " + kPhase + "=-0.2:0.2 --vary '" +
                              kRotation + "=-65:-25' --vary '" + kStroke + "=40:60' --maximize lift_per_power_N_W" +
                              " --constraint 'mean_lift_N>=" + own_lift + "' --max-evaluations 41 -q -o " +
                              (dir / "opt").string()),
            0);
  const auto evaluations = test::read_sweep_table((dir / "opt" / "evaluations.csv").string());
  ASSERT_TRUE(evaluations.rectangular);
  // Issue 33: under a third of the grid's 125 runs.
  EXPECT_LT(3 * evaluations.rows.size(), grid.rows.size());

  // optimum.toml, with the amplitudes written into its arrays, runs to a point that meets the
  // constraint and gives more lift per power than the grid's best point that does.
  ASSERT_EQ(test::run_flapsim("run " + (dir / "opt" / "optimum.toml").string() + " -q -o " + (dir / "best").string()),
            0);
  const std::string summary = test::read_text(dir / "best" / "summary.json");
  EXPECT_GE(std::stod(test::summary_value(summary, "mean_lift_N")), least_lift);
  EXPECT_GT(std::stod(test::summary_value(summary, "lift_per_power_N_W")), grid_best)
      << "grid's best feasible point (" << kPhase << ", " << kRotation << ", " << kStroke << ") = " << grid_best_point;
  EXPECT_NE(test::read_text(dir / "opt" / "report.md").find("NLopt cobyla"), std::string::npos);
}

}  // namespace
