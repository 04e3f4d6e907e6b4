// flapsim optimize on the rigid rotation-phase study (issue 33): the optimum of the mean
// lift over δψ in [-0.25, 0.15] against the best point of a fine grid of the same runs, and
// the most lift per power with a constraint on the lift against the grid's best point that
// meets it.
#include <gtest/gtest.h>

#include <algorithm>
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

// cases/rotation_phase_rigid.toml at 60 steps per cycle over 3 cycles (shipped: 100 × 4):
// a second per run, and a mean lift against δψ as smooth about its peak as the full case's
// (docs/optimize.md).
// The shortened case as dir/case.toml and the reference: a grid of step 0.01 over the
// bounds, the same runs by flapsim sweep (41 rows, each "ok").
test::SweepTable fine_grid(const test::ScratchDir& dir) {
  const std::string text = test::shortened_case("rotation_phase_rigid", 60, 3);
  EXPECT_FALSE(text.empty()) << "cases/rotation_phase_rigid.toml no longer has the keys this test shortens";
  std::ofstream(dir / "case.toml") << text;
  EXPECT_EQ(test::run_flapsim("sweep " + (dir / "case.toml").string() +
                              " --vary kinematics.rotation_phase=-0.25:0.01:0.15 -q -o " + (dir / "grid").string()),
            0);
  return test::read_sweep_table((dir / "grid" / "sweep.csv").string());
}

TEST(OptimizeRotationPhase, FindsTheRigidOptimumOfAFineGridWithinAFewEvaluations) {
  const test::ScratchDir dir("optimize_phase");
  const auto grid = fine_grid(dir);
  ASSERT_EQ(grid.rows.size(), 41u);
  double grid_phase = NAN, grid_lift = -INFINITY;
  for (const auto& row : grid.rows) {
    ASSERT_EQ(row.at("status"), "ok");
    const double lift = std::stod(row.at("mean_lift_N"));
    if (lift > grid_lift) grid_lift = lift, grid_phase = std::stod(row.at("kinematics.rotation_phase"));
  }
  // The peak lies inside the bounds (advanced rotation), not at an end of the grid.
  ASSERT_GT(grid_phase, -0.25);
  ASSERT_LT(grid_phase, 0.15);

  ASSERT_EQ(test::run_flapsim("optimize " + (dir / "case.toml").string() +
                              " --vary kinematics.rotation_phase=-0.25:0.15 --maximize mean_lift_N -q -o " +
                              (dir / "opt").string()),
            0);
  const auto evaluations = test::read_sweep_table((dir / "opt" / "evaluations.csv").string());
  ASSERT_TRUE(evaluations.rectangular);
  EXPECT_LE(evaluations.rows.size(), 15u);  // issue 33: at most 15 evaluations
  EXPECT_GE(evaluations.rows.size(), 3u);   // BOBYQA's first model needs 2n + 1 = 3 points

  // optimum.toml runs, and is the best evaluated point: the same inputs give the same lift.
  ASSERT_EQ(test::run_flapsim("run " + (dir / "opt" / "optimum.toml").string() + " -q -o " + (dir / "best").string()),
            0);
  const std::string summary = test::read_text(dir / "best" / "summary.json");
  const double phase = std::stod(test::summary_value(summary, "rotation_phase"));
  const double lift = std::stod(test::summary_value(summary, "mean_lift_N"));
  double best_lift = -INFINITY;
  for (const auto& row : evaluations.rows) best_lift = std::max(best_lift, std::stod(row.at("mean_lift_N")));
  EXPECT_EQ(lift, best_lift);

  // Issue 33: within 0.005 of the fine grid's optimum.
  EXPECT_NEAR(phase, grid_phase, 0.005) << "grid optimum " << grid_phase << " (" << grid_lift << " N), optimum "
                                         << lift << " N";
}

// Maximise lift per aerodynamic power subject to a mean lift of at least 7 mN (COBYLA, the
// default with a constraint): the optimum meets the constraint and is at least as good as
// the grid's best point that meets it, in fewer evaluations than the grid's 41 runs.
TEST(OptimizeRotationPhase, TheConstrainedOptimumBeatsTheGridsBestFeasiblePoint) {
  const test::ScratchDir dir("optimize_phase_constrained");
  const auto grid = fine_grid(dir);
  ASSERT_EQ(grid.rows.size(), 41u);
  constexpr double kLeastLift = 0.007;  // [N]
  double grid_best = -INFINITY;
  for (const auto& row : grid.rows)
    if (std::stod(row.at("mean_lift_N")) >= kLeastLift)
      grid_best = std::max(grid_best, std::stod(row.at("lift_per_power_N_W")));
  ASSERT_TRUE(std::isfinite(grid_best)) << "no grid point lifts 7 mN";

  ASSERT_EQ(test::run_flapsim("optimize " + (dir / "case.toml").string() +
                              " --vary kinematics.rotation_phase=-0.25:0.15 --maximize lift_per_power_N_W"
                              " --constraint 'mean_lift_N>=0.007' -q -o " + (dir / "opt").string()),
            0);
  const auto evaluations = test::read_sweep_table((dir / "opt" / "evaluations.csv").string());
  EXPECT_LT(evaluations.rows.size(), 41u);
  ASSERT_EQ(test::run_flapsim("run " + (dir / "opt" / "optimum.toml").string() + " -q -o " + (dir / "best").string()),
            0);
  const std::string summary = test::read_text(dir / "best" / "summary.json");
  EXPECT_GE(std::stod(test::summary_value(summary, "mean_lift_N")), kLeastLift);
  EXPECT_GE(std::stod(test::summary_value(summary, "lift_per_power_N_W")), grid_best);
  EXPECT_NE(test::read_text(dir / "opt" / "report.md").find("NLopt cobyla"), std::string::npos);
}

}  // namespace
