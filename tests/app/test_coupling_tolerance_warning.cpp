// A coupling tolerance below what the wake's single-precision sums let the sub-iterations
// reach is warned about by check and run (pipeline/app/coupling_tolerance_warning.hpp,
// docs/uvlm.md "Precision of the wake's sums"): with numerics.coupling_tolerance = 1e-10 the
// MAV film wing's run stopped at step 2, its change between 6e-10 and 2e-9 rad for 50
// sub-iterations, and ran with wake_precision = "double".
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"

namespace {

const std::string kToleranceSource = FLAPSIM_SOURCE_DIR;

// `flapsim check` of cases/hover_flexible.toml (the shipped chain) with the given numerics
// lines added; returns its stderr (the exit status is asserted 0).
std::string check_with(const flapsim::test::ScratchDir& dir, const std::string& name, const std::string& numerics) {
  std::string text = flapsim::test::read_text(kToleranceSource + "/cases/hover_flexible.toml");
  const std::string wing = "\"../wings/hawkmoth.toml\"";
  text.replace(text.find(wing), wing.size(), "\"" + kToleranceSource + "/wings/hawkmoth.toml\"");
  const std::string old_tolerance = "coupling_tolerance = 1e-6\n";
  text.replace(text.find(old_tolerance), old_tolerance.size(), numerics);
  const auto file = dir / (name + ".toml");
  std::ofstream(file) << text;
  const flapsim::test::FlapsimOutcome out = flapsim::test::run_flapsim_capturing_stderr(
      dir.path(), "check " + file.string() + " --chain " + kToleranceSource + "/cases/chains/hawkmoth_10_bodies.toml");
  EXPECT_EQ(out.status, 0) << out.err;
  return out.err;
}

const std::string kToleranceWarning = "numerics.coupling_tolerance = 1e-10 rad lies below the 1e-08 rad";

}  // namespace

TEST(CouplingToleranceWarning, AToleranceBelowTheSinglePrecisionFloorIsWarned) {
  flapsim::test::ScratchDir dir("coupling_tolerance_warning");
  EXPECT_NE(check_with(dir, "tight", "coupling_tolerance = 1e-10\n").find(kToleranceWarning), std::string::npos);
  // Double-precision sums, or the default tolerance: no warning.
  EXPECT_EQ(check_with(dir, "tight_double", "coupling_tolerance = 1e-10\nwake_precision = \"double\"\n")
                .find("numerics.coupling_tolerance"),
            std::string::npos);
  EXPECT_EQ(check_with(dir, "default", "coupling_tolerance = 1e-6\n").find("numerics.coupling_tolerance"),
            std::string::npos);
}
