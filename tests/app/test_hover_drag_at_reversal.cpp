// The hover's drag at a stroke reversal (pipeline/app/run_history.cpp, docs/fsi.md
// "Directions"). Drag in hover is against the wing's horizontal motion at r2·R, which stops
// at a reversal. With sweep = A cos 2πft and 40 steps a cycle, steps 20, 40, 60, 80 fall on
// reversals, where that speed was 1e-16 m/s of a sign set by round-off: the step's drag was
// ±|F_horizontal| (for the flat plate below, −1.44, +1.33, +1.17, −1.22 mN), and the same
// run at three times the frequency, which must give the same coefficients (an inviscid
// lattice without a viscous scale: forces ∝ f², to 3e-14 with the wake summed in double),
// had CD 40 % off at two of them and a mean drag 8e-4 N off.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "app/history_csv.hpp"
#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

using namespace flapsim;

std::string reversal_plate_case(double frequency_hz) {
  return "name = \"plate\"\nwing = \"" + std::string(FLAPSIM_SOURCE_DIR) +
         "/wings/flat_plate.toml\"\n[kinematics]\nfrequency_hz = " + std::to_string(frequency_hz) +
         "\nsweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
         "[structure]\nkind = \"rigid\"\n[numerics]\nsteps_per_cycle = 40\ncycles = 2\nchordwise_panels = 6\n"
         "spanwise_panels = 10\ncore_radius = 0.2\nfar_wake_cycles = 0.5\nwake_precision = \"double\"\n"
         "[output]\nvtk_every = 0\n";
}

TEST(HoverDragAtReversal, AStepOnAReversalHasNoDragAndTheCoefficientsDoNotMoveWithTheFrequency) {
  test::ScratchDir dir("hover_drag_at_reversal");
  test::HistoryCsv runs[2];
  double mean_cd[2] = {0.0, 0.0};
  const double frequencies[2] = {26.1, 3.0 * 26.1};
  for (int k = 0; k < 2; ++k) {
    const std::string name = "f" + std::to_string(k);
    std::ofstream(dir / (name + ".toml")) << reversal_plate_case(frequencies[k]);
    ASSERT_EQ(test::run_flapsim("run " + (dir / (name + ".toml")).string() + " -o " + (dir / name).string() +
                                " -q"),
              0);
    runs[k] = test::read_history_csv(dir / name / "history.csv");
    mean_cd[k] = test::json_number(test::read_text(dir / name / "summary.json"), "mean_CD");
  }
  ASSERT_EQ(runs[0].rows.size(), 80u);
  ASSERT_EQ(runs[1].rows.size(), 80u);
  for (long step : {20L, 40L, 60L, 80L}) {
    EXPECT_EQ(runs[0].at(step, "drag_N"), 0.0) << "step " << step;
    EXPECT_EQ(runs[1].at(step, "side_N"), 0.0) << "step " << step;
    EXPECT_GT(std::abs(runs[0].at(step, "lift_N")), 0.0) << "step " << step;  // the wing is loaded there
  }
  // Every step's CD alike at both frequencies (a step beside a reversal keeps its drag).
  for (long step = 1; step <= 80; ++step)
    EXPECT_NEAR(runs[1].at(step, "CD"), runs[0].at(step, "CD"),
                1e-9 * (1.0 + std::abs(runs[0].at(step, "CD"))))
        << "step " << step;
  EXPECT_NE(runs[0].at(19, "drag_N"), 0.0);
  EXPECT_NEAR(mean_cd[1], mean_cd[0], 1e-9 * std::abs(mean_cd[0]));
}

}  // namespace
