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
#include "robustness_helpers.hpp"

using namespace flapsim::test;

namespace {

// Body 2 on a rigid root body: mass m = 1e-4 kg at y = 10 mm from its joint, I_xx = 1e-9 kg m²,
// bend spring k = 1e-3 N m/rad. Bending about x at the joint: I = I_xx + m y² = 1.1e-8 kg m²,
// f = sqrt(k / I) / 2π = 47.99 Hz; twist: I_yy = 1e-10 kg m² with 1e-3 N m/rad, 503 Hz.
const char* const kOneJointChain =
    "root = \"rigid\"\n"
    "[[bodies]]\nlength = 0.02\nmass = 1e-5\ncenter_of_mass = [0, 0.01, 0]\n"
    "inertia = [[4e-10,0,0],[0,1e-11,0],[0,0,4e-10]]\n"
    "[[bodies]]\nlength = 0.02\nmass = 1e-4\ncenter_of_mass = [0, 0.01, 0]\n"
    "inertia = [[1e-9,0,0],[0,1e-10,0],[0,0,1e-9]]\n"
    "[bodies.joint]\nbend_stiffness = 1e-3\ntwist_stiffness = 1e-3\n";

std::string warning_at(const ScratchDir& dir, double frequency_hz) {
  std::ofstream(dir / "chain.toml") << kOneJointChain;
  std::ofstream(dir / "case.toml") << "air = \"none\"\nchain = \"chain.toml\"\n[kinematics]\nfrequency_hz = "
                                   << frequency_hz
                                   << "\nsweep = { cos_deg = [50.0] }\nrotation = { mean_deg = 90.0, sin_deg = [-45.0] }\n"
                                      "[structure]\nkind = \"flexible\"\nbodies = 2\n[numerics]\nsteps_per_cycle = 40\n";
  const flapsim::io::Case c = flapsim::io::load_case_file((dir / "case.toml").string());
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
