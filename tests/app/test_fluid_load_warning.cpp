// The fluid's loads in the chain's pre-run estimate (pipeline/app/quasi_steady_fluid_loads.hpp,
// fluid_load_deflection_warning). Before: a flexible wing in water (a dynamically scaled
// model) was warned of nothing before its run, as the only estimate was the flapping's
// inertia: the calibrated hawkmoth hover (cases/hover_flexible.toml) with density 1000 at
// 3 Hz bent its chain's tip 67.8° in the run (warned only after it), and at 26.1 Hz stopped at
// step 4 of 200 ("quasi-Newton solve did not converge ... residual 5.8e+84").
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "mbd/chain_data.hpp"
#include "mbd/chain_kinematics.hpp"
#include "mbd/chain_loads.hpp"
#include "pipeline/app/flexibility_warnings.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/app/quasi_steady_fluid_loads.hpp"
#include "pipeline/fsi/wing_attachment.hpp"
#include "pipeline/io/case_file.hpp"

using namespace flapsim;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// [Dickinson et al. 1999]'s fit by hand: at 90° CL = 0.225 + 1.58 sin(184.5°) = 0.1010,
// CD = 1.92 − 1.55 cos(173.78°) = 3.4609, C_N = CD = 3.4609; at 45° CL = 0.225 + 1.58
// sin(88.65°) = 1.8046, CD = 1.92 − 1.55 cos(81.98°) = 1.7037, C_N = (CL + CD)/√2 = 2.4807;
// at 0° C_N = CL = 0.225 + 1.58 sin(−7.2°) = 0.0270.
TEST(FluidLoadEstimate, TheNormalCoefficientIsDickinsonEtAlsFit) {
  EXPECT_NEAR(app::revolving_wing_normal_coefficient(90.0 * kDeg), 3.4609, 1e-3);
  EXPECT_NEAR(app::revolving_wing_normal_coefficient(45.0 * kDeg), 2.4807, 1e-3);
  EXPECT_NEAR(app::revolving_wing_normal_coefficient(0.0), 0.0270, 1e-3);
  EXPECT_EQ(app::revolving_wing_normal_coefficient(2.0),
            app::revolving_wing_normal_coefficient(0.5 * std::numbers::pi));
}

// wings/flat_plate.toml (x from −7.5 to 2.5 mm, y from 0 to 40 mm) as one lattice panel,
// revolving at Ω = 2π rad/s about the pivot with its plane vertical (rotation 90°): the panel
// moves normal to itself at Ω r, so the force is ½ ρ Ω² C_N(90°) ∫ r² dA — on one panel the
// estimate takes its centroid's speed, ½ ρ (Ω r_c)² C_N A with r_c = 20 mm, A = 400 mm²:
// ½ · 1000 · 4π² · 3.4609 · 4e-4 · (0.02)² = 0.010932 N, normal to the plate, against its motion.
TEST(FluidLoadEstimate, ARevolvingPlatesPanelCarriesHalfRhoVSquaredCnA) {
  const test::ScratchDir dir("fluid_load_plate");
  std::ofstream(dir / "case.toml")
      << "wing = \"" << FLAPSIM_SOURCE_DIR
      << "/wings/flat_plate.toml\"\n[kinematics]\nfrequency_hz = 1.0\nsweep = 0.0\n"
         "rotation = 90.0\nrevolution = { rate_deg_per_s = 360.0 }\n[air]\ndensity = "
         "1000.0\n[structure]\nkind = \"rigid\"\n[numerics]\nsteps_per_cycle = 8\n"
         "cycles = 1\nchordwise_panels = 1\nspanwise_panels = 1\n[output]\nvtk_every = 0\n";
  const io::Case c = io::load_case_file((dir / "case.toml").string());
  const app::FsiSetup setup = app::build_fsi_setup(c, {});
  const mbd::ChainModel& chain = setup.chain();
  mbd::ChainData data(chain);
  const double t = 0.3;  // any instant of the steady revolution
  mbd::forward_kinematics(chain, data, setup.model.base()(t), chain.rest_angles(),
                          Eigen::VectorXd::Zero(chain.num_dofs()));
  mbd::Loads loads(chain.num_bodies());
  app::add_quasi_steady_fluid_loads(setup.chain_structure->attachment, 1, 1, data, 1000.0,
                                    Eigen::Vector3d::Zero(), loads);
  Eigen::Vector3d force, moment;
  loads.resultant(0, data.bodies[0].rotation, force, moment);
  const double expected =
      0.5 * 1000.0 * 4.0 * std::numbers::pi * std::numbers::pi * 3.4609 * 4e-4 * 0.02 * 0.02;
  EXPECT_NEAR(force.norm(), expected, 1e-3 * expected);
  // Against the motion of the panel's centroid (the mean of its corners' velocities).
  Eigen::Matrix3Xd corners, velocities;
  fsi::deformed_nodes(setup.chain_structure->attachment, data, corners, velocities);
  const Eigen::Vector3d velocity = velocities.rowwise().mean();
  EXPECT_NEAR(force.normalized().dot(velocity.normalized()), -1.0, 1e-9);
}

std::string water_hover(const test::ScratchDir& dir, double frequency_hz, double density = 1000.0) {
  std::string text = test::read_text(std::string(FLAPSIM_SOURCE_DIR) + "/cases/hover_flexible.toml");
  auto replace = [&](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  replace("../wings/hawkmoth.toml", std::string(FLAPSIM_SOURCE_DIR) + "/wings/hawkmoth.toml");
  replace("frequency_hz = 26.1", "frequency_hz = " + std::to_string(frequency_hz));
  replace("density = 1.225", "density = " + std::to_string(density));
  replace("cycles = 3", "cycles = 2");
  replace("vtk_every = 2", "vtk_every = 0");
  const std::string path = (dir / ("water_" + std::to_string(frequency_hz) + ".toml")).string();
  std::ofstream(path) << text;
  return path;
}

// The calibrated hawkmoth wing (first bending 91 Hz) in water: at 3 Hz the estimate is beyond
// 30° (the run bends the tip 67.8°, measured 1 Dec), at 0.5 Hz it is not (loads ∝ f²: a 36th),
// nor in air at the hover's 26.1 Hz (the shipped case).
TEST(FluidLoadEstimate, AFlexibleWingInWaterIsWarnedBeforeItsRunWhereItBendsBeyondThirtyDegrees) {
  const test::ScratchDir dir("fluid_load_warning");
  const std::string warned = water_hover(dir, 3.0);
  const test::FlapsimOutcome check = test::run_flapsim_capturing_stderr(dir.path(), "check " + warned);
  ASSERT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.err.find(
                "warning: the fluid's loads with the flapping's inertia would bend the wing's tip by up to"),
            std::string::npos)
      << check.err;
  EXPECT_NE(check.err.find("density 1000 kg/m^3"), std::string::npos) << check.err;
  // The run bears it out: the tip bends beyond 30°.
  const test::FlapsimOutcome run =
      test::run_flapsim_capturing_stderr(dir.path(), "run " + warned + " -q -o " + (dir / "out").string());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_GT(test::json_number(test::read_text(dir / "out" / "summary.json"), "peak_tip_bend_deg"), 30.0);
  for (const std::string& quiet : {water_hover(dir, 0.5), water_hover(dir, 26.1, 1.225)}) {
    const test::FlapsimOutcome none = test::run_flapsim_capturing_stderr(dir.path(), "check " + quiet);
    ASSERT_EQ(none.status, 0) << none.err;
    EXPECT_EQ(none.err.find("the fluid's loads"), std::string::npos) << quiet << "\n" << none.err;
  }
}

}  // namespace
