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
#include <vector>

#include "common/run_flapsim.hpp"
#include "common/scratch_dir.hpp"
#include "shipped_case_text.hpp"
#include "sweep_test_helpers.hpp"

namespace robofly_revolving_case_test {

// Dickinson et al. 1999's fit to the Robofly wing's translational coefficients, α in degrees.
double fit_lift(double alpha) {
  return 0.225 + 1.58 * std::sin((2.13 * alpha - 7.20) * std::numbers::pi / 180.0);
}
double fit_drag(double alpha) {
  return 1.92 - 1.55 * std::cos((2.04 * alpha - 9.82) * std::numbers::pi / 180.0);
}

// The shipped case without its ParaView frames (vtk_every = 0).
std::string shipped_case_without_frames() {
  std::string toml = flapsim::test::shipped_case_text("robofly_revolving");
  const std::string every = "vtk_every = 4";
  EXPECT_NE(toml.find(every), std::string::npos);
  if (const auto at = toml.find(every); at != std::string::npos)
    toml.replace(at, every.size(), "vtk_every = 0");
  return toml;
}

// `flapsim sweep` of the case text \p toml over \p vary (--vary arguments) into DIR/sweep:
// its exit status, stderr and sweep.csv.
struct SweepOutcome {
  flapsim::test::FlapsimOutcome run;
  flapsim::test::SweepTable table;
};
SweepOutcome sweep_robofly(const flapsim::test::ScratchDir& dir, const std::string& toml,
                           const std::string& vary) {
  std::ofstream(dir / "case.toml") << toml;
  SweepOutcome out;
  out.run = flapsim::test::run_flapsim_capturing_stderr(
      dir.path(),
      "sweep " + (dir / "case.toml").string() + " " + vary + " -q -o " + (dir / "sweep").string());
  out.table = flapsim::test::read_sweep_table((dir / "sweep" / "sweep.csv").string());
  return out;
}

TEST(RoboflyRevolvingCase, TheShippedCaseAt50And60DegreesIsWithinTheFitsBoundsAndItsForceNormalToTheWing) {
  // Measured 2 Dec: 50°: CL 1.648 (−7.6 %), CD 1.812 (−8.5 %); 60°: CL 1.531 (−3.4 %), CD
  // 2.445 (−2.8 %) (1 Dec, the reference speed 719/720 of Ω r2 R: 1.652, 1.817, 1.535, 2.452;
  // the force 47.7° and 57.9° from the vertical).
  // The lattice-level run of the same conditions (unmerged sheet): 1.649, 1.809.
  flapsim::test::ScratchDir dir("robofly_revolving_case");
  const auto [outcome, table] =
      sweep_robofly(dir, shipped_case_without_frames(), "--vary kinematics.rotation=50,60");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  // Half a revolution in 2 cycles never comes round to its wake: no warning of round-off.
  EXPECT_EQ(outcome.err.find("round-off"), std::string::npos) << outcome.err;
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
  std::string toml = shipped_case_without_frames();
  const std::string shed = "\nleading_edge = \"shed\"";
  ASSERT_NE(toml.find(shed), std::string::npos);
  toml.replace(toml.find(shed), shed.size(), std::string(shed) + "\nskin_friction = \"laminar\"");
  const auto [outcome, table] = sweep_robofly(dir, toml, "--vary kinematics.rotation=10,40,50,60");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
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

// The lift each spanwise strip carries (span_loads.csv), 50°, with `none` and `shed`:
// docs/uvlm.md, "Where shed's lift lies along the span". The shed total within the fit's
// 10 % (the test above) is carried by the end strips; a revolving wing's load grows along
// the span as `none`'s does. Measured 4 Dec (span_loads.csv's shares, root to tip): `none`
// 0.030, 0.042, 0.062, 0.081, 0.099, 0.117, 0.133, 0.145, 0.151, 0.140; `shed` 0.095, 0.064,
// 0.083, 0.061, 0.024, 0.007, 0.027, 0.082, 0.146, 0.410. This pins what the documents
// say of `shed`: a model that gave the wing's load its shape would fail here, and the
// documents and the shed warning would then be rewritten with it.
TEST(RoboflyRevolvingCase, At50DegreesTheShedLiftLiesOnTheEndStripsWhereNonesGrowsAlongTheSpan) {
  flapsim::test::ScratchDir dir("robofly_revolving_span");
  const auto [outcome, table] =
      sweep_robofly(dir, shipped_case_without_frames(), "--vary numerics.leading_edge=none,shed");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  ASSERT_EQ(table.rows.size(), 2u);
  for (const auto& row : table.rows) {
    ASSERT_EQ(row.at("status"), "ok");
    const std::string model = row.at("numerics.leading_edge");
    const auto strips =
        flapsim::test::read_sweep_table((dir / "sweep" / row.at("folder") / "span_loads.csv").string());
    ASSERT_EQ(strips.rows.size(), 10u) << model;
    std::vector<double> share;
    for (const auto& strip : strips.rows) share.push_back(std::stod(strip.at("lift_share")));
    if (model == "none") {
      for (int j = 1; j <= 8; ++j) EXPECT_GT(share[j], share[j - 1]) << "strip " << j;  // grows to 80 % span
      EXPECT_NEAR(share[9], 0.140, 0.01);
      EXPECT_NEAR(share[5], 0.117, 0.01);
    } else {
      EXPECT_NEAR(share[9], 0.410, 0.02);  // the tip strip: 41 % (none 14 %)
      for (int j = 4; j <= 6; ++j) EXPECT_LT(share[j], 0.03) << "strip " << j;  // none: 0.10-0.13
    }
  }
}

TEST(RoboflyRevolvingCase, ShedLiftFallsToNonesOnFinerStripsWhereNonesHolds) {
  // docs/uvlm.md, "The two load routes part on the shed sheet" (5 Dec): the shipped case at
  // 50 deg on 10 and 40 spanwise panels gives "none" CL 1.388 and 1.402 (+1.0 %), "shed"
  // 1.648 and 1.404 (-14.8 %): on 40 strips "shed" adds no vortex lift. What goes is the end
  // strips' share (they do not shed, Polhamus' suction there; a tenth of the span each on 10
  // strips, the tip strip 35-41 % of the lift): on 80 strips "shed" settles within 8 % of
  // "none" (docs/uvlm.md, "Converged along the span, and the wing's view split from the
  // sheet's own"; the vortical impulse falls alike, so the flow does, not only the loads).
  // The "shed" warning (pipeline/io/case_file.cpp, warn_experimental_shedding) says so.
  // Asserted: "none" within 3 % between the lattices; "shed" on 40 strips 8-25 % below its
  // 10-strip lift and within 5 % of "none" on 40. It fails if "shed" came to converge along
  // the span (then update the warning and docs/uvlm.md) or "none" stopped converging. 5 s.
  flapsim::test::ScratchDir dir("robofly_revolving_strips");
  const auto [outcome, table] =
      sweep_robofly(dir, shipped_case_without_frames(),
                    "--vary numerics.spanwise_panels=10,40 --vary numerics.leading_edge=none,shed");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  ASSERT_EQ(table.rows.size(), 4u);
  auto lift = [&](const std::string& strips, const std::string& model) {
    for (const auto& row : table.rows)
      if (row.at("numerics.spanwise_panels") == strips && row.at("numerics.leading_edge") == model) {
        EXPECT_EQ(row.at("status"), "ok") << strips << " " << model;
        return std::stod(row.at("mean_CL"));
      }
    ADD_FAILURE() << "no row " << strips << " " << model;
    return std::nan("");
  };
  const double none10 = lift("10", "none"), none40 = lift("40", "none");
  const double shed10 = lift("10", "shed"), shed40 = lift("40", "shed");
  EXPECT_NEAR(none40 / none10, 1.0, 0.03);  // measured +1.0 %
  EXPECT_GT(shed40 / shed10 - 1.0, -0.25);  // measured -14.8 %
  EXPECT_LT(shed40 / shed10 - 1.0, -0.08);
  EXPECT_NEAR(shed40 / none40, 1.0, 0.05);  // measured +0.15 %
}

}  // namespace robofly_revolving_case_test
