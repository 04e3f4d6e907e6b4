// The chain's axis of a strongly swept wing. The default ("fitted") axis is a line through
// the pivot and the elastic axes of sections cut along y (docs/reduction.md, "Choice of
// ψ"); on a wing swept by 37° those sections twist as they bend and their elastic axes
// scatter far outside the wing. Before the fix the fitted line came out at ψ = −78°: the
// chain's bodies lay beside the planform, its first bending mode was 27 % off the FEM's
// (MAC 0.33) and `flapsim reduce` exited 0 without a word. Now a fitted axis that leaves
// the planform is replaced by the flexural axis (from the stations' compliance), and the
// report says so. Reference: the FEM of the same wing (its first modes), the reduction's
// own criterion (the chain reproduces the FEM's first bending and torsion).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fem/wing_fem.hpp"
#include "reduction/beam_properties.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/reduction_report.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::reduction {
namespace {

constexpr double kMm = 1e-3;

// A PET plate 40 mm long, chord 10 mm, swept back by atan(30/40) = 36.9° along a tapered
// solid leading-edge rod (the wing of the finding, a coarse mesh to keep the test short).
wings::Wing swept_wing(double sweep_dx_mm) {
  wings::Wing w;
  w.name = "swept";
  const Eigen::Vector2d le0(2.0 * kMm, 0.0), le1((2.0 - sweep_dx_mm) * kMm, 40.0 * kMm);
  w.outline = {le0, le1, {(-8.0 - sweep_dx_mm) * kMm, 40.0 * kMm}, {-8.0 * kMm, 0.0}};
  w.span = 40.0 * kMm;
  w.clamp_y = 0.5 * kMm;
  wings::Material pet;
  pet.youngs_modulus = 4.0e9;
  pet.poisson_ratio = 0.38;
  pet.density = 1390.0;
  w.membrane.thickness = 0.1 * kMm;
  w.membrane.material = pet;
  w.mesh.element_size = 2.5 * kMm;
  w.mesh.vein_element_size = 2.5 * kMm;
  wings::Section root, tip;
  root.outer_diameter = 0.6 * kMm;
  root.wall = 0.3 * kMm;
  tip.outer_diameter = 0.3 * kMm;
  tip.wall = 0.15 * kMm;
  w.veins.push_back({"leading edge", {le0, le1}, root, tip, pet, 0, ""});
  return w;
}

TEST(SweptWingAxis, AFittedAxisOutsideThePlanformIsReplacedByTheMidChordLine) {
  const wings::Wing w = swept_wing(30.0);
  const fem::WingFem fem = fem::build_wing_fem(w);
  const ClampedWingAnalysis analysis(fem.model.mesh, fem.system, fem.root_clamp);
  EXPECT_TRUE(analysis.fitted_axis_rejected());
  // The axis now runs through the wing over the whole flexible span.
  EXPECT_GE(analysis.axis_inside_fraction(), ClampedWingAnalysis::kFittedAxisMinInside);
  const BeamProperties beam = extract_beam_properties(analysis, 20);
  EXPECT_TRUE(beam.fitted_axis_rejected);
  // Chain against the FEM (6 bodies): the first bending and torsion modes within 5 %
  // (before: bending −27 %, MAC 0.33).
  const LumpedChain lc = lump_into_chain(analysis, 6);
  const fem::WingModes modes = fem::wing_modes(fem, 6);
  const ChainFemComparison cmp = compare_chain_with_fem(analysis, lc, modes.modes, modes.kinds);
  ASSERT_TRUE(cmp.bending.found);
  ASSERT_TRUE(cmp.torsion.found);
  EXPECT_LT(std::abs(cmp.bending.relative_error), 0.05);
  EXPECT_GT(cmp.bending.mac, 0.9);
  EXPECT_LT(std::abs(cmp.torsion.relative_error), 0.05);
  // Static tip responses (before: +97 %, +273 %, +433 %).
  EXPECT_LT(std::abs(cmp.tip_deflection.relative_error), 0.05);
  EXPECT_LT(std::abs(cmp.tip_bending_rotation.relative_error), 0.05);
  EXPECT_LT(std::abs(cmp.tip_twist.relative_error), 0.05);
  std::printf("swept wing: psi %.4f rad (fitted %.4f rejected); bending %+.2f %%, torsion %+.2f %%, static %+.1f/%+.1f/%+.1f %%\n",
              analysis.axis().psi, analysis.fitted_psi_rejected(), 100 * cmp.bending.relative_error,
              100 * cmp.torsion.relative_error, 100 * cmp.tip_deflection.relative_error,
              100 * cmp.tip_bending_rotation.relative_error, 100 * cmp.tip_twist.relative_error);
}

TEST(SweptWingAxis, AStraightWingKeepsItsFittedAxis) {
  const wings::Wing w = swept_wing(0.0);
  const fem::WingFem fem = fem::build_wing_fem(w);
  const ClampedWingAnalysis analysis(fem.model.mesh, fem.system, fem.root_clamp);
  EXPECT_FALSE(analysis.fitted_axis_rejected());
  EXPECT_DOUBLE_EQ(analysis.axis_inside_fraction(), 1.0);
}

}  // namespace
}  // namespace flapsim::reduction
