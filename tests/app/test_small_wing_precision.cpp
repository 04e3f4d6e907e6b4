// A wing of some micrometres: the lattice knows no absolute length (the flat plate drawn in
// mm and in um, flapped at 26.1 Hz and 26.1 kHz, is the same flow), but the wake's
// single-precision sums do: their kernel's denominator, the sixth power of the distances,
// meets the float range's floor below some micrometres. Measured (1 Dec 2026; rigid, 40 steps
// a cycle): the 10 um-chord plate's CL differs from the 10 mm one's by 4e-4 at the second
// step in single precision, 1e-14 in double. check and run warn below a 0.1 mm mean chord
// (pipeline/app/small_wing_precision_warning.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "history_csv.hpp"

namespace {

using namespace flapsim::test;

/// wings/flat_plate.toml (R = 40, chord 10 in its unit) with length_unit `unit`.
std::string plate_in(const std::string& unit) {
  std::ifstream in(std::string(FLAPSIM_SOURCE_DIR) + "/wings/flat_plate.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::string mm = "length_unit = \"mm\"";
  s.replace(s.find(mm), mm.size(), "length_unit = \"" + unit + "\"");
  return s;
}

/// A rigid hover of the plate: eq. 8 at `frequency` [Hz], 40 steps a cycle, 2 cycles.
std::string plate_hover(const std::string& wing, const std::string& frequency, const std::string& precision) {
  return "name = \"plate\"\nwing = \"" + wing + "\"\n[kinematics]\nfrequency_hz = " + frequency +
         "\nsweep = { mean_deg = 10.0, cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] "
         "}\n"
         "[structure]\nkind = \"rigid\"\n[numerics]\nsteps_per_cycle = 40\ncycles = 2\nfar_wake_cycles = "
         "0.5\n"
         "wake_precision = \"" +
         precision + "\"\n[output]\nvtk_every = 0\n";
}

struct PlateRun {
  FlapsimOutcome outcome;
  std::vector<double> cl;
};

PlateRun run_plate(const ScratchDir& dir, const std::string& unit, const std::string& frequency,
                   const std::string& precision) {
  const std::string name = unit + "_" + precision;
  std::ofstream(dir / ("plate_" + unit + ".toml")) << plate_in(unit);
  std::ofstream(dir / (name + ".toml")) << plate_hover("plate_" + unit + ".toml", frequency, precision);
  PlateRun r;
  r.outcome = run_flapsim_capturing_stderr(
      dir.path(), "run " + (dir / (name + ".toml")).string() + " -o " + (dir / name).string());
  EXPECT_EQ(r.outcome.status, 0) << r.outcome.err;
  r.cl = read_history_csv(dir / name / "history.csv").column("CL");
  return r;
}

TEST(SmallWingPrecision, AMicrometrePlateInDoublePrecisionIsTheMillimetrePlatesFlow) {
  ScratchDir dir("small_wing_precision");
  const PlateRun mm = run_plate(dir, "mm", "26.1", "double"), um = run_plate(dir, "um", "26100.0", "double");
  ASSERT_EQ(mm.cl.size(), 80u);
  ASSERT_EQ(um.cl.size(), 80u);
  // Every step's CL the same flow's: measured 1e-14 apart (the rescaling's rounding).
  for (std::size_t k = 0; k < mm.cl.size(); ++k) EXPECT_NEAR(um.cl[k], mm.cl[k], 1e-9) << "step " << k + 1;
  // Neither warned about precision: double sums.
  EXPECT_EQ(um.outcome.err.find("single-precision"), std::string::npos) << um.outcome.err;
}

TEST(SmallWingPrecision, SinglePrecisionSumsOnAMicrometreWingAreWarned) {
  ScratchDir dir("small_wing_precision_single");
  const PlateRun mm = run_plate(dir, "mm", "26.1", "single"), um = run_plate(dir, "um", "26100.0", "single");
  ASSERT_EQ(mm.cl.size(), 80u);
  ASSERT_EQ(um.cl.size(), 80u);
  // The warning names the mean chord (S/R = 10 um) and the remedy; the mm plate's run has none.
  EXPECT_NE(um.outcome.err.find("the wing's mean chord, 10 um, lies below the 100 um"), std::string::npos)
      << um.outcome.err;
  EXPECT_NE(um.outcome.err.find("wake_precision = \"double\""), std::string::npos) << um.outcome.err;
  EXPECT_EQ(mm.outcome.err.find("mean chord"), std::string::npos) << mm.outcome.err;
  // What it warns of: the second step's CL, 4e-4 off the mm plate's (measured 4.3e-4; at a
  // 10 mm chord the rounding of any rescaling moves it by 1e-8).
  EXPECT_GT(std::abs(um.cl[1] - mm.cl[1]), 1e-5);
}

}  // namespace
