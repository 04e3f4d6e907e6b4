// The run's Reynolds number and the warning below Re = 32 (pipeline/app/low_reynolds_warning.hpp;
// docs/uvlm.md, "Reynolds number"): there a wing's leading- and trailing-edge vortices stay
// attached and its lift falls (Miller & Peskin 2004), which the inviscid lattice, shedding at
// its trailing edge, does not follow.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/low_reynolds_warning.hpp"
#include "pipeline/io/case_file.hpp"

namespace {

using namespace flapsim::test;

const std::string kReSource = FLAPSIM_SOURCE_DIR;

/// A rigid hover of wings/flat_plate.toml (R = 40 mm, chord 10 mm, y from 0 to R): sweep
/// ±50° at `frequency` [Hz], with `numerics` added to its [numerics] table.
flapsim::io::Case plate_case(const ScratchDir& dir, const std::string& frequency, const std::string& numerics,
                             const std::string& air = "") {
  const auto file = dir / "plate.toml";
  std::ofstream(file) << "name = \"plate\"\nwing = \"" + kReSource +
                             "/wings/flat_plate.toml\"\n[kinematics]\nfrequency_hz = " + frequency +
                             "\nsweep = { mean_deg = 10.0, cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, "
                             "sin_deg = [-45.0] }\n[structure]\nkind = \"rigid\"\n" +
                             air + "[numerics]\ncycles = 1\n" + numerics;
  return flapsim::io::load_case_file(file.string());
}

}  // namespace

TEST(LowReynoldsWarning, TheReynoldsNumberIsTheReferenceSpeedTimesTheMeanChordOverNu) {
  // By hand: φ = Φ cos(2π f t) sweeps the span axis at a cycle-mean speed 4 Φ f r2 R; the
  // rectangle from the pivot has r2 = 1/√3 (∫y² dy / R³ = 1/3), c̄ = S/R = 10 mm. At 26.1 Hz,
  // Φ = 50°: U = 4 · 0.87266 · 26.1 · 0.57735 · 0.04 = 2.1038 m/s, Re = U c̄ / 1.5e-5 = 1402.5.
  ScratchDir dir("low_reynolds_number");
  const flapsim::io::Case c = plate_case(dir, "26.1", "");
  const flapsim::app::FsiSetup setup = flapsim::app::build_fsi_setup(c, {});
  const double phi = 50.0 * std::numbers::pi / 180.0;
  const double expected = 4.0 * phi * 26.1 / std::sqrt(3.0) * 0.04 * 0.01 / 1.5e-5;
  EXPECT_NEAR(flapsim::app::reynolds_number(c, setup), expected, 1e-3 * expected);
  EXPECT_NEAR(expected, 1402.5, 0.5);
  EXPECT_EQ(flapsim::app::low_reynolds_warning(c, setup), "");
}

// In a free stream the wing meets the air at the faster of the stream and its flapping: the
// plate flapped at 2.10 m/s (above) in a 0.02 m/s stream has Re 1402.5, not the stream's 13.3
// (warned as a fairyfly's until 3 Dec); in a 10 m/s stream Re = 10 · 0.01 / 1.5e-5 = 6667.
TEST(LowReynoldsWarning, AWingFlappedInASlowStreamHasItsFlappingReynoldsNumber) {
  ScratchDir dir("low_reynolds_stream");
  const flapsim::io::Case slow = plate_case(dir, "26.1", "", "[air]\nfreestream = [-0.02, 0.0, 0.0]\n");
  const flapsim::app::FsiSetup slow_setup = flapsim::app::build_fsi_setup(slow, {});
  EXPECT_NEAR(flapsim::app::reynolds_number(slow, slow_setup), 1402.5, 0.5);
  EXPECT_EQ(flapsim::app::low_reynolds_warning(slow, slow_setup), "");
  EXPECT_NE(flapsim::app::describe_reynolds(slow, slow_setup)
                .find("2.1 m/s at r2 of the span, faster than the "
                      "free stream"),
            std::string::npos)
      << flapsim::app::describe_reynolds(slow, slow_setup);
  const flapsim::io::Case fast = plate_case(dir, "26.1", "", "[air]\nfreestream = [-10.0, 0.0, 0.0]\n");
  const flapsim::app::FsiSetup fast_setup = flapsim::app::build_fsi_setup(fast, {});
  EXPECT_NEAR(flapsim::app::reynolds_number(fast, fast_setup), 10.0 * 0.01 / 1.5e-5, 1e-6);
  EXPECT_NE(flapsim::app::describe_reynolds(fast, fast_setup).find("10 m/s at the free stream"),
            std::string::npos)
      << flapsim::app::describe_reynolds(fast, fast_setup);
}

TEST(LowReynoldsWarning, BelowThirtyTwoTheRunIsWarnedAndAboveNot) {
  ScratchDir dir("low_reynolds_warning");
  // ν 50 times air's: Re = 1402.5 / 50 = 28.05, below 32; 40 times: 35.1, above.
  const flapsim::io::Case thick = plate_case(dir, "26.1", "kinematic_viscosity = 7.5e-4\n");
  const std::string w = flapsim::app::low_reynolds_warning(thick, flapsim::app::build_fsi_setup(thick, {}));
  EXPECT_NE(w.find("the Reynolds number is 28"), std::string::npos) << w;
  EXPECT_NE(w.find("Miller & Peskin 2004"), std::string::npos) << w;
  EXPECT_NE(w.find("numerics.kinematic_viscosity"), std::string::npos) << w;
  const flapsim::io::Case thinner = plate_case(dir, "26.1", "kinematic_viscosity = 6e-4\n");
  EXPECT_EQ(flapsim::app::low_reynolds_warning(thinner, flapsim::app::build_fsi_setup(thinner, {})), "");
  EXPECT_EQ(flapsim::app::kLowestLatticeReynolds, 32.0);
}

TEST(LowReynoldsWarning, CheckPrintsTheShippedHoversReynoldsNumber) {
  // cases/hover.toml: the hawkmoth at 2500 (docs/uvlm.md, "Reynolds number").
  ScratchDir dir("low_reynolds_check");
  ASSERT_EQ(run_flapsim("check " + kReSource + "/cases/hover.toml", dir / "out.txt"), 0);
  std::ifstream in(dir / "out.txt");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("Reynolds number        2500 (U c/nu: 2.22 m/s at r2 of the span, mean chord 16.9 mm"),
            std::string::npos)
      << text;
}
