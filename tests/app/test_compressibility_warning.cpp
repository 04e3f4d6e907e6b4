// A wing tip faster than Mach 0.3 is warned about (often a frequency in the wrong unit).
// Before: the hawkmoth hover at frequency_hz = 2610 instead of 26.1 ran silently, 72.7 N of
// lift from a 34 mg wing.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "pipeline/app/compressibility_warning.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_file.hpp"
#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

std::string warning_at(const ScratchDir& dir, double frequency_hz) {
  std::ofstream(dir / "case.toml") << "wing = \"" << kSourceDir << "/wings/flat_plate.toml\"\n[kinematics]\nfrequency_hz = "
                                   << frequency_hz
                                   << "\nsweep = { cos_deg = [50.0] }\nrotation = 90.0\n[structure]\nkind = \"rigid\"\n";
  const flapsim::io::Case c = flapsim::io::load_case_file((dir / "case.toml").string());
  return flapsim::app::compressibility_warning(c, flapsim::app::build_fsi_setup(c, {}));
}

TEST(CompressibilityWarning, ATipBeyondMachZeroPointThreeIsWarnedWithItsSpeed) {
  ScratchDir dir("compressibility");
  // φ = 50° cos 2πft about the vertical, the 40 mm plate's span axis horizontal: the tip's
  // peak speed is R Φ 2πf = 0.04 m × 0.8727 × 2π × 1000 Hz = 219.3 m/s, Mach 0.64 at 343 m/s.
  const double peak = 0.04 * (50.0 * std::numbers::pi / 180.0) * 2.0 * std::numbers::pi * 1000.0;
  ASSERT_NEAR(peak, 219.3, 0.1);
  const std::string w = warning_at(dir, 1000.0);
  EXPECT_NE(w.find("the wing tip meets the air at up to 219.3 m/s, Mach 0.64"), std::string::npos) << w;
  // At 300 Hz: 65.8 m/s, Mach 0.19: no warning.
  EXPECT_EQ(warning_at(dir, 300.0), "");
}

}  // namespace
