// A run with leading_edge = "shed" whose sheet came apart near the wing without driving the
// force past the diverged-force bound ends "ok": its report warns of it from the largest
// step-to-step change of C_L after the start (summary.json largest_CL_jump, _step;
// kSheetApartClJump, pipeline/app/run_results.hpp; docs/fsi.md "Failures"). Before 2 Dec a
// delta wing revolving at 45° with `shed` for 3 revolutions ended "ok" at a mean CL of 1.03
// (its last cycles −2.7, −3.3, −6.1, its first revolution 1.5) with no word of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "app/history_csv.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/run_results.hpp"

namespace {

using namespace flapsim;

app::RunResults shed_results(const char* leading_edge, double jump) {
  app::RunResults r;
  r.set("case", "delta");
  r.set("leading_edge", leading_edge);
  r.set("largest_CL_jump", jump);
  r.set("largest_CL_jump_step", 443L);
  return r;
}

TEST(SheetApartWarning, TheReportWarnsOfAShedSheetsJumpBeyondTheBound) {
  const std::string warned = app::run_report(shed_results("shed", 39.4));
  EXPECT_NE(
      warned.find("warning: with leading_edge = \"shed\" the lift coefficient changed by 39.4 from one step "
                  "to the next (into step 443"),
      std::string::npos)
      << warned;
  EXPECT_NE(warned.find("numerics.sheet_core_radius = 0.5"), std::string::npos) << warned;
  // The largest change of a sheet that stayed together (7.0, an AR-4 plate shedding at 20°),
  // and a jump of another model (a lattice without a sheet has none to come apart).
  EXPECT_EQ(app::run_report(shed_results("shed", 7.0)).find("came apart"), std::string::npos);
  EXPECT_EQ(app::run_report(shed_results("separated", 39.4)).find("came apart"), std::string::npos);
}

TEST(SheetApartWarning, TheJumpIsHistorysLargestChangeOfCLAfterTheStart) {
  // wings/flat_plate.toml revolving at 45°, 3 × 6 panels, 40 steps: the start's two steps
  // change CL by about 8 (the impulse); the largest change from step 3 on is the summary's.
  test::ScratchDir dir("sheet_apart_jump");
  std::ofstream(dir / "case.toml")
      << "name = \"revolve\"\nwing = \"" FLAPSIM_SOURCE_DIR
         "/wings/flat_plate.toml\"\n"
         "[kinematics]\nfrequency_hz = 2.0\nsweep = 0.0\nrotation = 45.0\n"
         "revolution = { rate_deg_per_s = -720.0 }\n[structure]\nkind = \"rigid\"\n"
         "[numerics]\nsteps_per_cycle = 40\ncycles = 1\nchordwise_panels = 3\nspanwise_panels = 6\n"
         "leading_edge = \"shed\"\n[output]\nvtk_every = 0\n";
  ASSERT_EQ(test::run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string(),
                              dir / "run.txt"),
            0);
  const test::HistoryCsv h = test::read_history_csv(dir / "out" / "history.csv");
  const auto cl = h.column("CL");
  ASSERT_EQ(cl.size(), 40u);
  double largest = 0.0, start = 0.0;
  long step = 0;
  for (std::size_t k = 1; k < cl.size(); ++k) {
    const double change = std::abs(cl[k] - cl[k - 1]);
    if (k == 1)
      start = change;
    else if (change > largest)
      largest = change, step = static_cast<long>(k) + 1;
  }
  const std::string summary = test::read_text(dir / "out" / "summary.json");
  EXPECT_NEAR(test::json_number(summary, "largest_CL_jump"), largest, 1e-12 * std::max(largest, 1.0));
  EXPECT_EQ(test::json_number(summary, "largest_CL_jump_step"), static_cast<double>(step));
  EXPECT_GT(start, largest);  // the start's impulse, left out
  EXPECT_LT(largest, app::kSheetApartClJump);
  EXPECT_EQ(test::read_text(dir / "run.txt").find("came apart"), std::string::npos);
}

}  // namespace
