// flapsim optimize on the rigid rotation-phase study (issue 33): the optimum of the mean
// lift over δψ in [-0.25, 0.15] against the best point of a fine grid of the same runs.
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

// cases/rotation_phase_rigid.toml at 60 steps per cycle over 3 cycles (shipped: 100 × 4):
// a second per run, and a mean lift against δψ as smooth about its peak as the full case's
// (docs/optimize.md).
TEST(OptimizeRotationPhase, FindsTheRigidOptimumOfAFineGridWithinAFewEvaluations) {
  const test::ScratchDir dir("optimize_phase");
  const std::string text = test::shortened_case("rotation_phase_rigid", 60, 3);
  ASSERT_FALSE(text.empty()) << "cases/rotation_phase_rigid.toml no longer has the keys this test shortens";
  std::ofstream(dir / "case.toml") << text;

  // The reference: a grid of step 0.01 over the bounds, the same runs by flapsim sweep.
  ASSERT_EQ(test::run_flapsim("sweep " + (dir / "case.toml").string() +
                              " --vary kinematics.rotation_phase=-0.25:0.01:0.15 -q -o " + (dir / "grid").string()),
            0);
  const auto grid = test::read_sweep_table((dir / "grid" / "sweep.csv").string());
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

}  // namespace
