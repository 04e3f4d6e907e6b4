// The hawkmoth forewing reduced to bar chains, checked against its own FEM
// (issue 7: 10 bodies within 5 % in first bending / torsion frequency and static
// tip deflection / twist; 3 bodies beside the rotation-phase paper's Table 1).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "fem/wing_fem.hpp"
#include "reduction/beam_properties.hpp"
#include "reduction/chain_lumping.hpp"
#include "reduction/reduction_report.hpp"
#include "wings/loader/wing_file.hpp"

namespace flapsim::reduction {
namespace {

class HawkmothReduction : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    wing_ = std::make_unique<wings::Wing>(
        wings::load_wing_file(std::string(FLAPSIM_SOURCE_DIR) + "/wings/hawkmoth.toml"));
    fem_ = std::make_unique<fem::WingFem>(fem::build_wing_fem(*wing_));
    modes_ = std::make_unique<fem::WingModes>(fem::wing_modes(*fem_, 12));
    analysis_ = std::make_unique<ClampedWingAnalysis>(fem_->model.mesh, fem_->system, fem_->root_clamp);
  }
  static void TearDownTestSuite() {
    analysis_.reset();
    modes_.reset();
    fem_.reset();
    wing_.reset();
  }
  static ChainFemComparison compare(int nb) {
    const LumpedChain lc = lump_into_chain(*analysis_, nb);
    return compare_chain_with_fem(*analysis_, lc, modes_->modes, modes_->kinds);
  }
  static void print(const ChainFemComparison& c) {
    std::printf(
        "N_b=%2d  bending %.2f/%.2f Hz (%+.2f %%, MAC %.3f)  torsion %.2f/%.2f Hz (%+.2f %%, MAC %.3f)  "
        "tip w %+.2f %%  tip theta %+.2f %%  tip twist %+.2f %%\n",
        c.num_bodies, c.chain_hz.empty() ? 0.0 : c.bending.chain_hz, c.bending.fem_hz,
        100 * c.bending.relative_error, c.bending.mac, c.torsion.chain_hz, c.torsion.fem_hz,
        100 * c.torsion.relative_error, c.torsion.mac, 100 * c.tip_deflection.relative_error,
        100 * c.tip_bending_rotation.relative_error, 100 * c.tip_twist.relative_error);
  }
  static inline std::unique_ptr<wings::Wing> wing_;
  static inline std::unique_ptr<fem::WingFem> fem_;
  static inline std::unique_ptr<fem::WingModes> modes_;
  static inline std::unique_ptr<ClampedWingAnalysis> analysis_;
};

// Issue 7's acceptance test and issue 17's: the 10-body chain with the joint stiffness by
// reciprocity (docs/reduction.md, "Joint stiffness by reciprocity") against the
// root-clamped FEM of the calibrated wings/hawkmoth.toml. Measured: first bending −0.24 %
// (MAC 1.000), first torsion +0.61 % (MAC 0.994), tip deflection +0.04 %, tip twist −3.0 %.
// (The first reciprocity chain, with a body's bending rotation fitted in its mid-span band
// instead of the chord slope between its joints, gave −3.1 % / −9.3 %: the twist rate
// aliased into the fitted slope and the chain's torsion mode carried 31 % more kinetic
// energy than the FEM's.)
TEST_F(HawkmothReduction, TenBodiesMatchTheFem) {
  const ChainFemComparison c = compare(10);
  print(c);
  ASSERT_TRUE(c.bending.found);
  ASSERT_TRUE(c.torsion.found);
  // Issue 17: first bending and first torsion within 3 % of the FEM.
  EXPECT_NEAR(c.bending.relative_error, 0.0, 0.03);
  EXPECT_NEAR(c.torsion.relative_error, 0.0, 0.03);
  // Issue 7 acceptance: statics within 5 %.
  EXPECT_NEAR(c.tip_deflection.relative_error, 0.0, 0.05);
  EXPECT_NEAR(c.tip_twist.relative_error, 0.0, 0.05);
  // The bending rotation conjugate to a moment spread over the tip body (issue 34 item 10;
  // docs/reduction.md, "A tip moment on a film tip"), positive on both sides by construction
  // and within the same 5 % on a beam-like wing (measured +1.58 %: FEM 2.318e-3 rad, chain
  // 2.355e-3 rad under 1e-6 N m; before, read at the measuring body, +0.09 %).
  EXPECT_GT(c.tip_bending_rotation.fem, 0.0);
  EXPECT_NEAR(c.tip_bending_rotation.relative_error, 0.0, 0.05);
  // The chain's bodies carry the FEM mass (strip sums, docs/reduction.md).
  EXPECT_NEAR(c.chain_mass, c.fem_mass, 1e-12 * c.fem_mass);
}

// Why the chain's frequencies follow the FEM's (docs/reduction.md, "Why chord slopes, not
// fitted slopes"): an FEM mode x projected on the chain through the stations, q = T Aᵀ x,
// has the FEM's strain energy (qᵀ K q = xᵀ K_FEM x: K is exact at the stations) and its
// kinetic energy (qᵀ M_c q = xᵀ M_FEM x: the chain's joints follow the FEM's deflection).
// Rayleigh's quotient then puts the chain's frequency next to the FEM's. Measured at 10
// bodies: strain 1.000 / 1.000, kinetic 1.005 / 0.987 (bending / torsion); with slopes
// fitted in the mid-span bands the torsion mode's kinetic energy was 1.31.
TEST_F(HawkmothReduction, FemModesProjectedOnTheChainKeepTheirStrainAndKineticEnergy) {
  const LumpedChain lc = lump_into_chain(*analysis_, 10);
  const ChainFemComparison c = compare_chain_with_fem(*analysis_, lc, modes_->modes, modes_->kinds);
  const LinearChain lin(lc.chain);
  for (const ModeMatch* m : {&c.bending, &c.torsion}) {
    ASSERT_TRUE(m->found);
    const Eigen::VectorXd x = modes_->modes.shapes.col(m->fem_mode);
    const Eigen::VectorXd q = lc.joint_stiffness.joint_angles(lc.stations.station_motion(x));
    const double strain = q.dot(lin.stiffness() * q) / x.dot(fem_->system.stiffness * x);
    const double kinetic = q.dot(lin.mass_matrix() * q) / x.dot(fem_->system.mass * x);
    std::printf("FEM mode %d projected on the chain: strain energy ratio %.4f, kinetic energy ratio %.4f\n",
                m->fem_mode + 1, strain, kinetic);
    EXPECT_NEAR(strain, 1.0, 0.02);
    EXPECT_NEAR(kinetic, 1.0, 0.03);
  }
}

TEST_F(HawkmothReduction, ErrorsAtFourEightTenSixteenBodies) {
  double bending[3] = {}, torsion[3] = {};  // relative errors at 4, 8, 16 bodies
  int slot = 0;
  for (int nb : {4, 8, 10, 16}) {
    const ChainFemComparison c = compare(nb);
    print(c);
    ASSERT_TRUE(c.bending.found && c.torsion.found) << nb;
    // Strip sums: the bodies hold the FEM mass to round-off (docs/reduction.md).
    EXPECT_NEAR(c.chain_mass, c.fem_mass, 1e-12 * c.fem_mass) << nb;
    // The first bending and torsion shapes correlate (MAC > 0.9, the usual threshold
    // for the same mode, Allemang 2003).
    EXPECT_GT(c.bending.mac, 0.9) << nb;
    EXPECT_GT(c.torsion.mac, 0.9) << nb;
    if (nb != 10) {
      bending[slot] = c.bending.relative_error;
      torsion[slot] = c.torsion.relative_error;
      ++slot;
    }
  }
  // The chain converges as N_b doubles: the change 8 -> 16 is smaller than half the change
  // 4 -> 8 (Hencky lumping error of second order in the body length; measured bending
  // −1.67 / −0.38 / −0.09 %, torsion +2.16 / +0.83 / +0.58 % at 4 / 8 / 16 bodies).
  EXPECT_LT(std::abs(bending[2] - bending[1]), 0.5 * std::abs(bending[1] - bending[0]));
  EXPECT_LT(std::abs(torsion[2] - torsion[1]), 0.5 * std::abs(torsion[1] - torsion[0]));
}

// The literal 12 µm cuticle membrane (wings/hawkmoth_thin_membrane.toml): its sections
// camber between the veins. With the joint stiffness by reciprocity it reduces for 4 … 16
// bodies (K positive definite, test_joint_stiffness.cpp); chain vs FEM (issue 17). Measured
// at 4 / 8 / 10 / 16 bodies: bending −0.92 / −0.02 / −0.11 / +0.11 % (MAC 0.995–0.996),
// torsion +0.30 / +2.10 / +2.05 / +2.08 % (MAC 0.76–0.83: the FEM's torsion mode cambers
// the film, which rigid sections cannot). The tip-load section fits of issue 7 missed by
// +28 % / +46 %; the first reciprocity chain (mid-span fitted slopes) by −28 … −38 % in
// bending with no torsion match.
TEST(HawkmothThinMembrane, ChainAgainstFemForFourToSixteenBodies) {
  const wings::Wing wing =
      wings::load_wing_file(std::string(FLAPSIM_SOURCE_DIR) + "/wings/hawkmoth_thin_membrane.toml");
  const fem::WingFem fem = fem::build_wing_fem(wing);
  const fem::WingModes modes = fem::wing_modes(fem, 12);
  const ClampedWingAnalysis analysis(fem.model.mesh, fem.system, fem.root_clamp);
  for (int nb : {4, 8, 10, 16}) {
    const ChainFemComparison c =
        compare_chain_with_fem(analysis, lump_into_chain(analysis, nb), modes.modes, modes.kinds);
    std::printf("thin membrane N_b=%2d  bending %.2f/%.2f Hz (%+.2f %%, MAC %.3f)  torsion %.2f/%.2f Hz (%+.2f %%, MAC %.3f)\n",
                nb, c.bending.chain_hz, c.bending.fem_hz, 100 * c.bending.relative_error, c.bending.mac,
                c.torsion.chain_hz, c.torsion.fem_hz, 100 * c.torsion.relative_error, c.torsion.mac);
    for (const ModeMatch& p : c.beam_mode_pairs)
      std::printf("  FEM beam mode %2d (%s) %7.2f Hz ~ chain mode %2d %7.2f Hz (%+.1f %%, MAC %.3f)\n", p.fem_mode + 1,
                  c.fem_kinds[static_cast<std::size_t>(p.fem_mode)].c_str(), p.fem_hz, p.chain_mode + 1, p.chain_hz,
                  100 * p.relative_error, p.mac);
    ASSERT_TRUE(c.bending.found && c.torsion.found) << nb;
    // The first bending mode is a beam mode and the chain follows it (MAC > 0.9).
    EXPECT_GT(c.bending.mac, 0.9) << nb;
    // Issue 17's 3 % (set for the calibrated wing) holds here too for both frequencies.
    EXPECT_NEAR(c.bending.relative_error, 0.0, 0.03) << nb;
    EXPECT_NEAR(c.torsion.relative_error, 0.0, 0.03) << nb;
    // The first bending frequency lies below the 26.1 Hz wingbeat (both papers).
    EXPECT_LT(c.bending.fem_hz, 26.1);
  }
}

TEST_F(HawkmothReduction, ThreeEqualBodiesMassesBesideTable1) {
  const LumpedChain lc = lump_into_chain(*analysis_, 3);
  // Rotation-phase paper, Table 1: 13.27 / 13.01 / 7.48 mg; 0.47 / 3.84 / 1.26e-10 kg m².
  const double paper_mass_mg[3] = {13.27, 13.01, 7.48};
  const double paper_inertia[3] = {0.47e-10, 3.84e-10, 1.26e-10};
  std::printf("body  length_mm  mass_mg (Table 1)  Ixx  Iyy(span)  Izz about com [1e-10 kg m2] (Table 1)\n");
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const auto& b = lc.chain.bodies[static_cast<std::size_t>(k)];
    sum += b.mass;
    std::printf("%d  %.2f  %.2f (%.2f)  %.3f  %.3f  %.3f (%.2f)\n", k + 1, 1e3 * b.length, 1e6 * b.mass,
                paper_mass_mg[k], 1e10 * b.inertia(0, 0), 1e10 * b.inertia(1, 1), 1e10 * b.inertia(2, 2),
                1e10 * paper_inertia[k]);
  }
  // The three bodies hold the whole FEM mass to round-off.
  EXPECT_NEAR(sum, lc.fem_mass, 1e-12 * lc.fem_mass);
  // Table 1's masses, within the FEM's known difference (docs/reduction.md, "Three equal
  // bodies": +15.1 / −4.2 / −19.0 %; the span thirds of the FEM itself differ alike,
  // fem.HawkmothFem.MassOverSpanThirdsBesideTable1): 20 % per body. Table 1's inertia
  // moments are not compared: the paper does not state their axis, and their pattern
  // (small, large, middle) matches none of the chain's components (docs/reduction.md).
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(1e6 * lc.chain.bodies[static_cast<std::size_t>(k)].mass / paper_mass_mg[k], 1.0, 0.20) << k + 1;
}

}  // namespace
}  // namespace flapsim::reduction
