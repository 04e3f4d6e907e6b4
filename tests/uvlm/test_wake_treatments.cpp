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
    for (int q = 0; q <= W; ++q)
      for (int j = 0; j < ns; ++j) {
        const std::size_t k = static_cast<std::size_t>(q) * ns + j;  // spanwise segments first
        const double age = d.wake_row_age[q];
        double rc2 = grown_core_radius2(m.core_growth, rc0, age, d.wake_segments.gamma()[k]);
        if (view == detail::WakeView::Wing && age > m.near_wing_min_age)
          rc2 = std::max(rc2, m.near_wing_core * m.near_wing_core);
        EXPECT_NEAR(d.wake_segments.core_ratio2()[k], rc0 * rc0 / rc2, 1e-12) << "row " << q;
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
      if (age[q] > m.frozen_wake_age)
        EXPECT_EQ(moved, 0.0) << "row " << q << " age " << age[q];
      else if (q + 1 < static_cast<int>(age.size()))
        EXPECT_GT(moved, 0.0) << "row " << q << " age " << age[q];
    }
  }
}
