// The power the base supplies to a rigid wing includes the air's loads (docs/fsi.md:
// drive_power_W = ω·M + v·F at the pivot, "inertial plus aerodynamic"). Before: the rigid
// wing's step solved the lattice but never passed its loads to the chain, so the drive
// moment and power were the wing's inertia alone: a swept 32 mm wing, 12 cycles at 20 Hz,
// mean drive power 7.9e-17 W against an aerodynamic power of 2.94e-3 W (a flexible wing's
// two agreed: 0.03313 vs 0.03317 W).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

// Work–energy over one period: the prescribed motion is periodic, so the wing's kinetic
// energy returns to its value and the cycle-mean drive power equals the cycle-mean power
// the wing gives the air. The means are over the last cycle's 24 samples (rectangle rule
// of a smooth periodic function: the inertial part averages out to round-off level).
TEST(RigidDrivePower, TheCycleMeanDrivePowerIsTheAerodynamicPower) {
  ScratchDir dir("rigid_drive_power");
  std::ofstream(dir / "case.toml") << small_plate_case("rigid", 2, 0);
  ASSERT_EQ(run_flapsim("run " + (dir / "case.toml").string() + " -o " + (dir / "out").string()), 0);
  const std::string summary = read_text(dir / "out" / "summary.json");
  const double aero = json_number(summary, "mean_power_W");
  const double drive = json_number(summary, "mean_drive_power_W");
  ASSERT_GT(aero, 0.0) << summary;
  EXPECT_NEAR(drive, aero, 1e-3 * aero) << summary;
  // The peak moment includes the air's: at least the mean aerodynamic moment about the pivot.
  EXPECT_GE(json_number(summary, "peak_drive_moment_Nm"), std::abs(json_number(summary, "mean_Mx_base_Nm")));
}

}  // namespace
