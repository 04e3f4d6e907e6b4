// flapsim optimize records each run's warnings as a sweep does, and says when the optimum's
// run was warned: an optimum whose chain swung beyond the small rotations its joint springs
// represent maximised a result that is not the wing's (docs/optimize.md, "Warnings").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "optimize_test_helpers.hpp"
#include "pipeline/app/optimize/evaluation_table.hpp"
#include "pipeline/app/optimize/optimize_report.hpp"
#include "sweep_test_helpers.hpp"

namespace {

namespace fs = std::filesystem;
using namespace flapsim;

TEST(OptimizeWarnings, AnOptimumWhoseChainSwungBeyondItsRangeSaysSoAndWhatToConstrain) {
  // The flexible rotation-phase case (40 steps, 2 cycles) with the documented placeholder chain
  // (cases/chains/hawkmoth_10_bodies.toml: first bending 56.8 Hz, near twice the 26.1 Hz
  // wingbeat, which check and run warn of): its tip bends 39–42° at δψ −0.05 … 0.05 (1 Dec),
  // beyond the 30° of its small-rotation springs. The optimisation ran such points without a
  // word; each now carries its warnings, and the optimum's says what to constrain.
  const test::ScratchDir dir("optimize_warnings");
  const std::string text = test::shortened_case("rotation_phase_flexible", 40, 2);
  ASSERT_FALSE(text.empty())
      << "cases/rotation_phase_flexible.toml no longer has the keys this test shortens";
  std::ofstream(dir / "case.toml") << text;
  const std::string common =
      "optimize " + (dir / "case.toml").string() + " --chain " + FLAPSIM_SOURCE_DIR +
      "/cases/chains/hawkmoth_10_bodies.toml --vary kinematics.rotation_phase=-0.05:0.05"
      " --maximize mean_lift_N";
  const auto outcome = test::run_flapsim_capturing_stderr(
      dir.path(), common + " --max-evaluations 3 -o " + (dir / "out").string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const test::SweepTable table = test::read_sweep_table((dir / "out" / "evaluations.csv").string());
  ASSERT_EQ(table.rows.size(), 3u);
  for (const auto& row : table.rows) {
    EXPECT_NE(row.at("warnings").find("lies near twice the wingbeat frequency"), std::string::npos)
        << row.at("warnings");
    EXPECT_GT(std::stod(row.at("peak_tip_bend_deg")), 30.0);
  }
  EXPECT_NE(outcome.err.find("the optimum's run was warned"), std::string::npos) << outcome.err;
  const std::string report = test::read_text(dir / "out" / "report.md");
  EXPECT_NE(report.find("**The optimum's run was warned**"), std::string::npos) << report;
  EXPECT_NE(report.find("large deflection: tip bend"), std::string::npos) << report;
  EXPECT_NE(report.find("`--constraint peak_tip_twist_deg<=30`"), std::string::npos) << report;
  EXPECT_NE(report.find("ok (warned) **optimum** |"), std::string::npos) << report;
  // The constraint it names is one the search takes: here no point meets it (exit 2).
  const auto constrained = test::run_flapsim_capturing_stderr(
      dir.path(),
      common + " --constraint 'peak_tip_bend_deg<=30' --max-evaluations 2 -o " + (dir / "held").string());
  EXPECT_EQ(constrained.status, 2) << constrained.err;
  EXPECT_NE(constrained.err.find("no evaluated point satisfies peak_tip_bend_deg<=30"), std::string::npos)
      << constrained.err;
}

TEST(OptimizeWarnings, AnOptimumWithoutWarningsSaysNothingAndOneWithOthersOnlyThatTheyStand) {
  optimize::Evaluation e;
  e.status = "ok";
  e.results.set("peak_tip_bend_deg", 12.0);
  e.results.set("peak_tip_twist_deg", 8.0);
  EXPECT_EQ(optimize::evaluation_notes(e), "");
  // A setup warning alone: noted, and the advice does not speak of the chain's range.
  e.results.set("warnings", std::string("the far wake's cycles are outside the measured range"));
  EXPECT_EQ(optimize::evaluation_notes(e), "the far wake's cycles are outside the measured range");
  EXPECT_EQ(optimize::optimum_warning_advice(e).find("peak_tip"), std::string::npos);
  // A twist beyond 30° (app::large_deflection_note): the constraints that keep the search where the chain
  // holds.
  e.results.set("peak_tip_twist_deg", 31.0);
  EXPECT_NE(optimize::evaluation_notes(e).find("large deflection"), std::string::npos);
  EXPECT_NE(optimize::optimum_warning_advice(e).find("--constraint peak_tip_twist_deg<=30"),
            std::string::npos);
}

}  // namespace
