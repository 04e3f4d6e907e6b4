// A flexible chain driven above its first natural frequency is warned about before the run.
// Before: a 30 x 10 mm, 50 µm PET film wing without veins (first bending 15.7 Hz, FEM and
// 6-body chain alike) flapped at 20 Hz ran into "quasi-Newton solve did not converge ...
// residual 8e+49 N m" at step 52, in air and in vacuum (at 40, 100 and 400 steps per cycle;
// at 1600 its joints bent up to 94°): nothing said that the wing was too soft for the
// wingbeat. Now `run` and `check` warn when the linearised chain's first frequency lies
// below the wingbeat frequency (pipeline/app/fsi_setup.hpp, soft_chain_warning).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_file.hpp"
#include "one_joint_chain.hpp"
#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

std::string warning_at(const ScratchDir& dir, double frequency_hz) {
  const flapsim::io::Case c = load_one_joint_case(dir, frequency_hz, "rotation = { mean_deg = 90.0, sin_deg = [-45.0] }",
                                                  "[numerics]\nsteps_per_cycle = 40\n");
  return flapsim::app::soft_chain_warning(c, flapsim::app::build_fsi_setup(c, {}));
}

TEST(SoftChainWarning, AChainDrivenAboveItsFirstFrequencyIsWarned) {
  const double f1 = std::sqrt(1e-3 / (1e-9 + 1e-4 * 0.01 * 0.01)) / (2 * std::numbers::pi);
  ASSERT_NEAR(f1, 47.99, 0.01);
  ScratchDir dir("soft_chain");
  const std::string w = warning_at(dir, 60.0);
  EXPECT_NE(w.find("first natural frequency, 48 Hz (bending), is below the wingbeat frequency 60 Hz"),
            std::string::npos) << w;
  EXPECT_EQ(warning_at(dir, 40.0), "");  // below resonance: no warning
}

TEST(SoftChainWarning, TheShippedFlexibleCasesWithAChainFileAreNotWarned) {
  for (const char* name : {"three_body.toml", "vacuum_flapping.toml"}) {
    const flapsim::io::Case c = flapsim::io::load_case_file(kSourceDir + "/cases/" + name);
    EXPECT_EQ(flapsim::app::soft_chain_warning(c, flapsim::app::build_fsi_setup(c, {})), "") << name;
  }
}

}  // namespace
