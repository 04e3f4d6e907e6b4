// The wake treatments of docs/uvlm.md ("Model"): core growth with age (Lamb–Oseen with
// Squire's eddy viscosity), the near-wing core and the frozen far wake.
#include "uvlm/core_growth.hpp"
#include "uvlm/lattice_internal.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hover_wake.hpp"

using namespace flapsim::uvlm;

TEST(WakeTreatments, CoreGrowthFollowsLambOseenWithSquiresFactor) {
  // r_c² = r_c0² + 4 α_L δ ν t, δ = 1 + a1 Γ/ν [Squire 1965; Bhagwat & Leishman 2002]:
  // r_c0 = 1 mm, Γ = 0.03 m²/s, ν = 1.5e-5 m²/s, a1 = 2e-4 → δ = 1.4; t = 0.1 s →
  // r_c² = 1e-6 + 4 · 1.25643 · 1.4 · 1.5e-5 · 0.1 = 1.1554012e-5 m².
  CoreGrowth g;
  g.enabled = true;
  EXPECT_NEAR(eddy_viscosity_factor(g, 0.03), 1.4, 1e-12);
  EXPECT_NEAR(eddy_viscosity_factor(g, -0.03), 1.4, 1e-12);  // |Γ|
  EXPECT_NEAR(grown_core_radius2(g, 1e-3, 0.1, 0.03), 1.1554012e-5, 1e-12);
  g.enabled = false;
  EXPECT_EQ(grown_core_radius2(g, 1e-3, 0.1, 0.03), 1e-6);
}

TEST(WakeTreatments, WakeSegmentsCarryTheirAgeAndTheWingSeesTheNearWingCore) {
  flapsim::uvlm::testing::HoverWing wing;
  VortexLatticeModel m = wing.model(1);
  m.core_growth.enabled = true;
  m.near_wing_core = 3 * m.core.radius;
  m.near_wing_min_age = 0.5 * wing.dt() * wing.steps_per_cycle;  // half a cycle
  VortexLatticeData d(m);
  wing.run(m, d, 1);
  const int ns = m.spanwise, W = d.wake_rows;
  ASSERT_EQ(W, wing.steps_per_cycle);
  // Node row q has been convected W − q times: age (W − q) dt.
  for (int q = 0; q <= W; ++q) EXPECT_NEAR(d.wake_row_age[q], (W - q) * wing.dt(), 1e-12);
  const double rc0 = m.core.radius;
  for (auto view : {detail::WakeView::Wake, detail::WakeView::Wing}) {
    detail::build_wake_segments(m, d, view);
    // Seen from the wing (single-precision sums), the newest node row's segments are kept
    // apart, spanwise first (docs/uvlm.md, "Precision of the wake's sums").
    const bool edge_apart = view == detail::WakeView::Wing && m.single_precision_wake;
    ASSERT_EQ(d.wake_edge_segments.size(), edge_apart ? static_cast<std::size_t>(2 * ns + 1) : 0u);
    for (int q = 0; q <= W; ++q)
      for (int j = 0; j < ns; ++j) {
        const bool edge = edge_apart && q == W;
        const SegmentSet& set = edge ? d.wake_edge_segments : d.wake_segments;
        const std::size_t k = edge ? static_cast<std::size_t>(j) : static_cast<std::size_t>(q) * ns + j;  // spanwise first
        const double age = d.wake_row_age[q];
        double rc2 = grown_core_radius2(m.core_growth, rc0, age, set.gamma()[k]);
        if (view == detail::WakeView::Wing && age > m.near_wing_min_age)
          rc2 = std::max(rc2, m.near_wing_core * m.near_wing_core);
        EXPECT_NEAR(set.core_ratio2()[k], rc0 * rc0 / rc2, 1e-12) << "row " << q;
      }
  }
}

TEST(WakeTreatments, FrozenWakeStaysWhereItIs) {
  // Rows older than frozen_wake_age do not move; the younger ones do.
  flapsim::uvlm::testing::HoverWing wing;
  VortexLatticeModel m = wing.model(2);
  m.frozen_wake_age = 1.0 / wing.frequency;  // one cycle
  VortexLatticeData d(m);
  wing.run(m, d, 1);
  // One more cycle, one step at a time: a row is frozen from the step its age exceeds a cycle.
  const flapsim::uvlm::PlanformGrid g = wing.grid();
  Eigen::Matrix3Xd x(3, m.nodes()), v(3, m.nodes());
  const int n1 = m.spanwise + 1;
  for (int k = 0; k < 10; ++k) {
    wing.pose(g, (wing.steps_per_cycle + k) * wing.dt(), x, v);
    solve(m, d, x, v, Eigen::Vector3d::Zero(), wing.dt(), 1.225);
    const std::vector<double> before(d.wake_nodes.z.begin(), d.wake_nodes.z.begin() + d.wake_nodes.size);
    const std::vector<double> age(d.wake_row_age.begin(), d.wake_row_age.begin() + d.wake_rows + 1);
    advance(m, d);
    for (int q = 0; q < static_cast<int>(age.size()); ++q) {
      const double moved = std::abs(d.wake_nodes.z[q * n1 + n1 / 2] - before[q * n1 + n1 / 2]);
      if (age[q] > m.frozen_wake_age) {
        EXPECT_EQ(moved, 0.0) << "row " << q << " age " << age[q];
      } else if (q + 1 < static_cast<int>(age.size())) {
        EXPECT_GT(moved, 0.0) << "row " << q << " age " << age[q];
      }
    }
  }
}

TEST(WakeTreatments, FarWakeVelocityIsMomentumTheorysInducedVelocity) {
  // Hover: v_i = sqrt(T / (2 ρ A)) along −F̄/|F̄| [Leishman 2006, ch. 2]. T = 5 mN,
  // ρ = 1.225 kg/m³, A = 2e-3 m² → v_i = sqrt(0.005 / 0.0049) = 1.0101525 m/s.
  VortexLatticeModel m;
  m.wake_capacity = 1;
  m.far_wake_age = 0.01;
  m.far_wake_disk_area = 2e-3;
  VortexLatticeData d(m);
  EXPECT_EQ(far_wake_velocity(m, d), Eigen::Vector3d::Zero());  // no accepted step yet
  d.rho = 1.225;
  d.force_time = 0.5;
  d.force_impulse = Eigen::Vector3d(0.0, 0.0, 0.005 * 0.5);
  EXPECT_NEAR(far_wake_velocity(m, d).z(), -1.0101525, 1e-6);
  EXPECT_NEAR(far_wake_velocity(m, d).head<2>().norm(), 0.0, 1e-15);
  m.far_wake_speed_factor = 2.0;  // the fully developed jet, 2 v_i
  EXPECT_NEAR(far_wake_velocity(m, d).z(), -2.0203051, 1e-6);
  // Glauert with a free stream V∞ normal to the force: v_i sqrt(V∞² + v_i²) = T/(2ρA)
  // = 1.0204082 m²/s²; V∞ = 3 m/s → v_i⁴ + 9 v_i² − 1.0412328 = 0,
  // v_i² = (sqrt(81 + 4 · 1.0412328) − 9)/2 → v_i = 0.33800 m/s; the far wake moves with V∞ + v_i down.
  m.far_wake_speed_factor = 1.0;
  d.free_stream = Eigen::Vector3d(3.0, 0.0, 0.0);
  const double c = 0.005 / (2 * 1.225 * 2e-3), vi = std::sqrt((std::sqrt(81.0 + 4 * c * c) - 9.0) / 2);
  EXPECT_NEAR(vi, 0.33800, 5e-5);
  EXPECT_NEAR(far_wake_velocity(m, d).z(), -vi, 1e-9);
  EXPECT_NEAR(far_wake_velocity(m, d).x(), 3.0, 1e-12);
}

TEST(WakeTreatments, ConvectedFarWakeMovesAsAWholeAndStillInduces) {
  // Rows older than far_wake_age move by dt · far_wake_velocity, the younger ones freely.
  // The far wake summed by the tree code (rebuilt every 10 steps, moved with the far wake
  // in between) gives the run with every row summed directly, to the tree's tolerance:
  // compared after 45 steps (0.9 cycles; the far wake begins after 25), before this
  // wing's wake, chaotic where the wing meets it, amplifies the tree's 1e-5 (measured:
  // relative |Δγ| 3e-8 after 40 steps, 1e-4 after 90).
  flapsim::uvlm::testing::HoverWing wing;
  VortexLatticeModel m = wing.model(1);
  m.far_wake_age = 0.5 / wing.frequency;  // half a cycle
  m.far_wake_disk_area = 0.5 * (120.0 * M_PI / 180.0) * std::pow(wing.root + 4 * wing.chord, 2);
  m.single_precision_wake = false;
  VortexLatticeModel tree = m;
  tree.wake_sum = WakeSum::Tree;
  tree.tree_tolerance = 1e-5;
  VortexLatticeData d(m), t(tree);
  const flapsim::uvlm::PlanformGrid g = wing.grid();
  Eigen::Matrix3Xd x(3, m.nodes()), v(3, m.nodes());
  int k = 0;
  for (; k < 45; ++k) {
    wing.pose(g, k * wing.dt(), x, v);
    solve(m, d, x, v, Eigen::Vector3d::Zero(), wing.dt(), 1.225);
    solve(tree, t, x, v, Eigen::Vector3d::Zero(), wing.dt(), 1.225);
    advance(m, d);
    advance(tree, t);
  }
  EXPECT_GT(t.far_tree_rows, 10);                        // the tree holds the far wake
  EXPECT_GT(t.accepted_steps, t.far_tree_step);         // and has moved since its build
  EXPECT_GT(t.far_tree_shift.norm(), 0.0);
  EXPECT_LT((d.gamma - t.gamma).norm(), 1e-5 * d.gamma.norm());
  for (std::size_t i = 0; i < d.wake_nodes.size; ++i)
    ASSERT_NEAR(d.wake_nodes.z[i], t.wake_nodes.z[i], 1e-6) << "node " << i;
  // One more step, row by row.
  wing.pose(g, k * wing.dt(), x, v);
  solve(m, d, x, v, Eigen::Vector3d::Zero(), wing.dt(), 1.225);
  const std::vector<double> z0(d.wake_nodes.z.begin(), d.wake_nodes.z.begin() + d.wake_nodes.size);
  const std::vector<double> age(d.wake_row_age.begin(), d.wake_row_age.begin() + d.wake_rows + 1);
  advance(m, d);
  const double vz = far_wake_velocity(m, d).z();
  EXPECT_LT(vz, -0.1);  // downward, against the lift
  const int n1 = m.spanwise + 1;
  for (int q = 0; q + 1 < static_cast<int>(age.size()); ++q)
    for (int j = 0; j < n1; ++j) {
      const double moved = d.wake_nodes.z[q * n1 + j] - z0[q * n1 + j];
      if (age[q] > m.far_wake_age)
        EXPECT_NEAR(moved, wing.dt() * vz, 1e-15) << "row " << q;
      else
        EXPECT_NE(moved, wing.dt() * vz) << "row " << q;
    }
}
