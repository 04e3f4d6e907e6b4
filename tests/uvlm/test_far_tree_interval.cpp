// The far wake's tree is rebuilt every k steps, k = max(k0, √(2κN / ((2 ns + 1) T))) for its N
// segments seen by T points a step (uvlm::far_tree_rebuild_interval): the build's cost, κ N
// direct pairs (SegmentTree::kBuildPairsPerSegment, measured), spread over k steps, against
// the rows joined since, summed directly. Before 4 Dec every 10 steps: a 300-cycle hover
// (cases/lua_rigid.toml with `separated`, one thread) ran 756 s, 183 s now, its settled mean
// CL the same to 2e-6 (docs/performance.md, "The far wake's tree, rebuilt as it grows").
#include <gtest/gtest.h>

#include <cmath>

#include "uvlm/vortex_lattice.hpp"

using namespace flapsim::uvlm;

TEST(FarTreeInterval, BalancesTheBuildAgainstTheRowsSummedDirectly) {
  VortexLatticeModel m;
  m.spanwise = 10;  // 21 segments a row
  // The 20-cycle far wake of cases/hover_periodic.toml (40 771 segments) seen by the young
  // wake's 51 x 11 nodes and 60 panels: √(2 · 188 · 40771 / (21 · 621)) = 34.3.
  EXPECT_EQ(far_tree_rebuild_interval(m, 40771, 621.0), 34);
  // At the optimum the two costs a step are equal: κN/k = T s k/2 (to the rounding of k).
  const double k = std::sqrt(2.0 * SegmentTree::kBuildPairsPerSegment * 40771.0 / (21.0 * 621.0));
  EXPECT_NEAR(SegmentTree::kBuildPairsPerSegment * 40771.0 / k, 621.0 * 21.0 * k / 2.0, 1e-6);
  // 300 cycles (629 000 segments): 135 steps; the interval grows as √N.
  EXPECT_EQ(far_tree_rebuild_interval(m, 629000, 621.0), 135);
  // A small far wake: the least interval, model.far_tree_rebuild_steps (10).
  EXPECT_EQ(far_tree_rebuild_interval(m, 1000, 621.0), 10);
  m.far_tree_rebuild_steps = 25;
  EXPECT_EQ(far_tree_rebuild_interval(m, 1000, 621.0), 25);
  EXPECT_EQ(far_tree_rebuild_interval(m, 629000, 621.0), 135);
  // With core growth the tree's cores are as old as the tree: the least interval always.
  m.core_growth.enabled = true;
  EXPECT_EQ(far_tree_rebuild_interval(m, 629000, 621.0), 25);
}
