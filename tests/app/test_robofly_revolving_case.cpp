// cases/robofly_revolving.toml, the Robofly wing revolving at 1 rev/s with leading_edge =
// "shed" as a user runs it: the numerics of the lattice-level validation
// (uvlm.RevolvingWingShed.*; docs/uvlm.md, "Against the fit, 10°–60°"), its last cycle the
// mean over 90°–180° of revolution. At 50° and 60° within issue 30's bounds of
// [Dickinson et al. 1999]'s fit (CL 10 %, CD 15 %); at 10°–40° not (docs/uvlm.md).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "shipped_case_text.hpp"
#include "sweep_test_helpers.hpp"

namespace {

// Dickinson et al. 1999's fit to the Robofly wing's translational coefficients, α in degrees.
double fit_lift(double alpha) {
  return 0.225 + 1.58 * std::sin((2.13 * alpha - 7.20) * std::numbers::pi / 180.0);
}
double fit_drag(double alpha) {
  return 1.92 - 1.55 * std::cos((2.04 * alpha - 9.82) * std::numbers::pi / 180.0);
}

TEST(RoboflyRevolvingCase, TheShippedCaseAt50And60DegreesIsWithinTheFitsBoundsAndItsForceNormalToTheWing) {
  // Measured 2 Dec: 50°: CL 1.648 (−7.6 %), CD 1.812 (−8.5 %); 60°: CL 1.531 (−3.4 %), CD
  // 2.445 (−2.8 %) (1 Dec, the reference speed 719/720 of Ω r2 R: 1.652, 1.817, 1.535, 2.452;
  // the force 47.7° and 57.9° from the vertical).
  // The lattice-level run of the same conditions (unmerged sheet): 1.649, 1.809.
  flapsim::test::ScratchDir dir("robofly_revolving_case");
  std::string toml = flapsim::test::shipped_case_text("robofly_revolving");
  const std::string every = "vtk_every = 4";
  ASSERT_NE(toml.find(every), std::string::npos);
  toml.replace(toml.find(every), every.size(), "vtk_every = 0");
  std::ofstream(dir / "case.toml") << toml;
  const auto outcome = flapsim::test::run_flapsim_capturing_stderr(
      dir.path(), "sweep " + (dir / "case.toml").string() + " --vary kinematics.rotation=50,60 -q -o " +
                      (dir / "sweep").string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  // Half a revolution in 2 cycles never comes round to its wake: no warning of round-off.
  EXPECT_EQ(outcome.err.find("round-off"), std::string::npos) << outcome.err;
  const auto table = flapsim::test::read_sweep_table((dir / "sweep" / "sweep.csv").string());
  ASSERT_EQ(table.rows.size(), 2u);
  for (const auto& row : table.rows) {
    ASSERT_EQ(row.at("status"), "ok");
    const double alpha = std::stod(row.at("kinematics.rotation"));
    const double cl = std::stod(row.at("mean_CL")), cd = std::stod(row.at("mean_CD"));
    EXPECT_NEAR(cl / fit_lift(alpha), 1.0, 0.10) << alpha;
    EXPECT_NEAR(cd / fit_drag(alpha), 1.0, 0.15) << alpha;
    // A revolving wing's force is normal to it ([Usherwood & Ellington 2002]): within 3°.
    EXPECT_NEAR(std::atan2(cd, cl) * 180.0 / std::numbers::pi, alpha, 3.0) << alpha;
  }
}

TEST(RoboflyRevolvingCase, LaminarSkinFrictionBringsTheDragAt40To60DegreesWithinTheFitsBound) {
  // numerics.skin_friction = "laminar" (uvlm/skin_friction.hpp: Blasius, 1.328/√Re_c a side,
  // with the case's ν, set for the experiment's Re = 136 before the option existed; nothing
  // calibrated). Measured 1 Dec against the inviscid lattice's (docs/uvlm.md, "Skin
  // friction"; 2 Dec): CD at 10°–60° 0.280, 0.492, 0.788, 1.292, 1.871, 2.483 (−29, −17, −17,
  // −10, −5, −1 % of the fit; inviscid −88 … −3 %), CL 0.491 … 1.465 (−20, −16, −21, −16, −12,
  // −8 %; inviscid −13 … −3 %): the drag within 15 % at 40°–60° and the lift farther off.
  flapsim::test::ScratchDir dir("robofly_revolving_friction");
  std::string toml = flapsim::test::shipped_case_text("robofly_revolving");
  const std::string every = "vtk_every = 4", shed = "\nleading_edge = \"shed\"";
  ASSERT_NE(toml.find(every), std::string::npos);
  toml.replace(toml.find(every), every.size(), "vtk_every = 0");
  ASSERT_NE(toml.find(shed), std::string::npos);
  toml.replace(toml.find(shed), shed.size(), std::string(shed) + "\nskin_friction = \"laminar\"");
  std::ofstream(dir / "case.toml") << toml;
  const auto outcome = flapsim::test::run_flapsim_capturing_stderr(
      dir.path(), "sweep " + (dir / "case.toml").string() + " --vary kinematics.rotation=10,40,50,60 -q -o " +
                      (dir / "sweep").string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const auto table = flapsim::test::read_sweep_table((dir / "sweep" / "sweep.csv").string());
  ASSERT_EQ(table.rows.size(), 4u);
  for (const auto& row : table.rows) {
    ASSERT_EQ(row.at("status"), "ok");
    const double alpha = std::stod(row.at("kinematics.rotation"));
    const double cd = std::stod(row.at("mean_CD"));
    if (alpha >= 40.0)
      EXPECT_NEAR(cd / fit_drag(alpha), 1.0, 0.15) << alpha;  // issue 30's bound on CD
    else  // 10°: the friction is most of the drag; measured 0.281 (inviscid 0.046)
      EXPECT_NEAR(cd, 0.281, 0.01);
  }
}

}  // namespace
