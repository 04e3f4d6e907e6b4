// The first bending and torsion rows of the chain-vs-FEM comparison pair the FEM's first
// mode of each kind with the chain mode of the same shape (largest MAC), not with the
// chain's first mode of that kind (issue 34, item 9; docs/reduction.md, "Checking the
// chain against the FEM"). Before, each side was named by its own 0.5 energy cut, so a
// strongly coupled mode could be "torsion" in the FEM and "bending" in the chain: a
// bumblebee-size wing was reported -37 % / +150 % while its own correlation table paired
// FEM 92.8 <-> chain 93.3 Hz (MAC 0.99) and 148.3 <-> 150.4 Hz (MAC 0.81).
//
// Here the same frequencies on hand-made shapes (two sample points per body, two bodies),
// the MAC values written out from MAC = (a^T b)^2 / (a^T a b^T b).

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <vector>

#include "reduction/reduction_report.hpp"

namespace flapsim::reduction {
namespace {

Eigen::VectorXd v4(double a, double b, double c, double d) {
  Eigen::VectorXd v(4);
  v << a, b, c, d;
  return v;
}

struct CoupledModes {
  // FEM: mode 0 coupled, named torsion by the stations; mode 1 film (skipped); mode 2 bending.
  std::vector<Eigen::VectorXd> fem = {v4(1, -1, 2, -1), v4(1, -1, 2, -2), v4(1, 1, 2, 2)};
  std::vector<double> fem_hz = {92.8, 120.0, 148.3};
  std::vector<StationModeKind> kinds = {StationModeKind::torsion, StationModeKind::film, StationModeKind::bending};
  // Chain: mode 0 the FEM's coupled mode (opposite sign, twice the size; the chain's own
  // energy split calls it bending), mode 1 the FEM's bending mode with some twist at the
  // tip, mode 2 a pure twist (the chain's first "torsion").
  std::vector<Eigen::VectorXd> chain = {v4(-2, 2, -4, 2), v4(1, 1, 2.5, 1.5), v4(1, -1, 2, -2)};
  std::vector<double> chain_hz = {93.3, 150.4, 232.0};
};

TEST(ModePairing, FirstBendingAndTorsionPairByShapeNotByTheChainsKind) {
  const CoupledModes m;
  const std::vector<ModeMatch> pairs = pair_modes_by_mac(m.fem, m.fem_hz, m.kinds, m.chain, m.chain_hz);
  // The film mode is not a beam mode: two pairs, in the FEM's order.
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].fem_mode, 0);
  EXPECT_EQ(pairs[1].fem_mode, 2);

  const ModeMatch torsion = first_pair_of_kind(pairs, m.kinds, StationModeKind::torsion);
  ASSERT_TRUE(torsion.found);
  EXPECT_EQ(torsion.fem_mode, 0);
  EXPECT_EQ(torsion.chain_mode, 0);  // the chain's kind-based pairing took mode 2 (232 Hz, +150 %)
  EXPECT_NEAR(torsion.mac, 1.0, 1e-14);  // the same shape, scaled by -2
  EXPECT_NEAR(torsion.relative_error, 93.3 / 92.8 - 1.0, 1e-14);

  const ModeMatch bending = first_pair_of_kind(pairs, m.kinds, StationModeKind::bending);
  ASSERT_TRUE(bending.found);
  EXPECT_EQ(bending.fem_mode, 2);
  EXPECT_EQ(bending.chain_mode, 1);  // not chain mode 0 (93.3 Hz, -37 %)
  // a^T b = 1 + 1 + 5 + 3 = 10, a^T a = 10, b^T b = 1 + 1 + 6.25 + 2.25 = 10.5.
  EXPECT_NEAR(bending.mac, 100.0 / 105.0, 1e-14);
  EXPECT_NEAR(bending.chain_hz, 150.4, 0.0);
  EXPECT_NEAR(bending.relative_error, 150.4 / 148.3 - 1.0, 1e-14);
  // Both within the 10 % the warning uses (app::kChainFemMismatch).
  EXPECT_LT(std::abs(bending.relative_error), 0.10);
  EXPECT_LT(std::abs(torsion.relative_error), 0.10);
}

TEST(ModePairing, AKindTheFemDoesNotShowIsNotFound) {
  CoupledModes m;
  m.kinds = {StationModeKind::bending, StationModeKind::film, StationModeKind::bending};
  const std::vector<ModeMatch> pairs = pair_modes_by_mac(m.fem, m.fem_hz, m.kinds, m.chain, m.chain_hz);
  EXPECT_FALSE(first_pair_of_kind(pairs, m.kinds, StationModeKind::torsion).found);
  const ModeMatch bending = first_pair_of_kind(pairs, m.kinds, StationModeKind::bending);
  ASSERT_TRUE(bending.found);
  EXPECT_EQ(bending.fem_mode, 0);  // the first FEM mode of the kind, in frequency order
  EXPECT_EQ(bending.chain_mode, 0);
}

TEST(ModePairing, NoChainModesNoPairs) {
  const CoupledModes m;
  EXPECT_TRUE(pair_modes_by_mac(m.fem, m.fem_hz, m.kinds, {}, {}).empty());
}

}  // namespace
}  // namespace flapsim::reduction
