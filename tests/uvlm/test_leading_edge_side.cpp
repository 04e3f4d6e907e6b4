// The side of the separated leading-edge force (uvlm/leading_edge_side.hpp): it follows
// the sign of each strip's leading-edge circulation unless held, a hold lasts until the
// next accepted step (advance), and the force's size does not depend on the side.
#include <gtest/gtest.h>

#include "tilted_plate.hpp"
#include "uvlm/leading_edge_side.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace {

using namespace flapsim;

// Σ_j n_k · F_le,k over the leading-edge row [N].
double normal_edge_force(const uvlm::VortexLatticeModel& m, const uvlm::VortexLatticeData& d) {
  double sum = 0.0;
  for (int j = 0; j < m.spanwise; ++j) {
    const int k = m.panel(0, j);
    sum += d.loads.leading_edge_force.col(k).dot(d.normal.col(k));
  }
  return sum;
}

}  // namespace

TEST(LeadingEdgeSide, AHeldSideKeepsTheSeparatedForceOnItUntilTheNextStep) {
  // A plate in a 5 m/s stream at +0.2 rad (Γ > 0, the force along +n), held; solved again
  // at −0.2 rad (Γ < 0) within the same step the force stays on +n
  // with the size the free side gives on −n; after advance it follows the circulation.
  uvlm::VortexLatticeModel m;
  m.chordwise = 4;
  m.spanwise = 8;
  m.wake_capacity = 5;
  m.leading_edge = uvlm::LeadingEdge::Separated;
  const Eigen::Matrix3Xd rest = Eigen::Matrix3Xd::Zero(3, m.nodes());
  const Eigen::Vector3d stream(5.0, 0.0, 0.0);
  const double dt = 1e-3, rho = 1.225;
  uvlm::VortexLatticeData d(m), free(m);
  const Eigen::Matrix3Xd up = test::tilted_plate(m, 0.2), down = test::tilted_plate(m, -0.2);
  uvlm::solve(m, d, up, rest, stream, dt, rho);
  ASSERT_GT(d.gamma(m.panel(0, 0)), 0.0);
  EXPECT_GT(normal_edge_force(m, d), 0.0);
  for (int j = 0; j < m.spanwise; ++j) EXPECT_EQ(uvlm::leading_edge_side(m, d, j), 1.0);
  uvlm::hold_leading_edge_sides(m, d);

  uvlm::solve(m, d, down, rest, stream, dt, rho);
  uvlm::solve(m, free, down, rest, stream, dt, rho);
  ASSERT_LT(free.gamma(m.panel(0, 0)), 0.0);
  EXPECT_LT(normal_edge_force(m, free), 0.0);
  // Held: the same magnitude on the other side (the circulations are the held lattice's:
  // the side changes the loads only).
  EXPECT_NEAR(normal_edge_force(m, d), -normal_edge_force(m, free), 1e-12 * std::abs(normal_edge_force(m, free)));
  EXPECT_EQ((d.gamma - free.gamma).norm(), 0.0);

  uvlm::advance(m, d);
  uvlm::advance(m, free);
  uvlm::solve(m, d, down, rest, stream, dt, rho);
  uvlm::solve(m, free, down, rest, stream, dt, rho);
  EXPECT_EQ(normal_edge_force(m, d), normal_edge_force(m, free));  // freed by advance
}
