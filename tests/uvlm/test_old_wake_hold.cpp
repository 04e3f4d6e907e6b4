// Holding the wing's sums over the older wake within a step (uvlm/old_wake_hold.hpp), and
// the factorisation of the current matrix for the added mass's right-hand sides
// (factorise_current_matrix). References: the same lattice summed anew at every solve (the
// older rows apart or not), and a first-order Taylor argument for the held sums' error (it
// must halve with the wing's move).
#include "hover_wake.hpp"

#include "uvlm/added_mass.hpp"
#include "uvlm/old_wake_hold.hpp"
#include "uvlm/planform_grid.hpp"
#include "uvlm/vortex_lattice.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace flapsim::uvlm;

namespace {

const flapsim::uvlm::testing::HoverWing kHover;

/// The hover wing with a quarter cycle (12 steps) of young wake rows (and `edge` its
/// leading edge's model).
VortexLatticeModel hold_model(LeadingEdge edge = VortexLatticeModel{}.leading_edge) {
  VortexLatticeModel m = kHover.model(2);
  m.young_wake_rows = 12;
  m.leading_edge = edge;
  return m;
}

/// The hover run for `steps` steps with the older wake kept apart (or not).
void run_steps(const VortexLatticeModel& m, VortexLatticeData& d, int steps) {
  const PlanformGrid g = kHover.grid();
  Eigen::Matrix3Xd x(3, m.nodes()), v(3, m.nodes());
  for (int k = 0; k < steps; ++k) {
    kHover.pose(g, k * kHover.dt(), x, v);
    solve(m, d, x, v, Eigen::Vector3d::Zero(), kHover.dt(), 1.225);
    advance(m, d);
  }
}

/// The nodes of step `step` turned about the sweep axis (z) by `angle` [rad]: a coupling
/// sub-iteration's change of the wing's place (the tip moves by 0.073 m × angle).
Eigen::Matrix3Xd moved_pose(int step, double angle, Eigen::Matrix3Xd& v) {
  const PlanformGrid g = kHover.grid();
  Eigen::Matrix3Xd x(3, g.nodes.cols());
  v.resize(3, g.nodes.cols());
  kHover.pose(g, step * kHover.dt(), x, v);
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix() * x;
}

/// Lift [N] of a solve at `step`'s pose turned by `angle` after solves at the pose turned
/// by each of `recorded` (which record the older wake's sums), held or not.
double lift_after_moves(int step, const std::vector<double>& recorded, double angle, bool hold,
                        LeadingEdge edge = VortexLatticeModel{}.leading_edge) {
  const VortexLatticeModel m = hold_model(edge);
  VortexLatticeData d(m);
  d.old_wake_apart = true;
  run_steps(m, d, step);
  Eigen::Matrix3Xd v;
  for (double a : recorded) {
    const Eigen::Matrix3Xd x = moved_pose(step, a, v);
    solve(m, d, x, v, Eigen::Vector3d::Zero(), kHover.dt(), 1.225);
  }
  if (hold) hold_old_wake_sums(m, d);
  EXPECT_EQ(d.old_wake_held, hold);
  const Eigen::Matrix3Xd x = moved_pose(step, angle, v);
  solve(m, d, x, v, Eigen::Vector3d::Zero(), kHover.dt(), 1.225);
  return d.loads.total_force.z();
}

/// The held lift's error relative to the lift summed anew.
double held_error(int step, const std::vector<double>& recorded, double angle,
                  LeadingEdge edge = VortexLatticeModel{}.leading_edge) {
  const double exact = lift_after_moves(step, recorded, angle, false, edge);
  return (lift_after_moves(step, recorded, angle, true, edge) - exact) / exact;
}

/// After a solve at pose x (velocities v): held, a solve there gives the same
/// circulations and loads, bit for bit.
void expect_the_held_solve_gives_the_same_bits(const VortexLatticeModel& m, VortexLatticeData& d,
                                               const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& v) {
  const Eigen::VectorXd gamma = d.gamma;
  const Eigen::Matrix3Xd force = d.loads.force;
  hold_old_wake_sums(m, d);
  ASSERT_TRUE(d.old_wake_held);
  solve(m, d, x, v, Eigen::Vector3d::Zero(), kHover.dt(), 1.225);
  EXPECT_EQ((d.gamma - gamma).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((d.loads.force - force).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace

// The record is the bits of the sum: a solve at the recorded points gives the same
// circulations and loads held or not.
TEST(OldWakeHold, ASolveAtTheRecordedPointsGivesTheSameBits) {
  const VortexLatticeModel m = hold_model();
  VortexLatticeData d(m);
  d.old_wake_apart = true;
  const int step = 40;  // 28 rows older than the young ones
  run_steps(m, d, step);
  Eigen::Matrix3Xd v;
  const Eigen::Matrix3Xd x = moved_pose(step, 0.0, v);
  solve(m, d, x, v, Eigen::Vector3d::Zero(), kHover.dt(), 1.225);
  ASSERT_GT(d.wake_segments.size(), 0u);
  ASSERT_GT(d.young_wake_segments.size(), 0u);
  EXPECT_EQ(d.old_wake[0].size, static_cast<std::size_t>(m.panels()));
  EXPECT_EQ(d.old_wake[1].size, static_cast<std::size_t>(m.panels()));  // the separated edge's midpoints
  expect_the_held_solve_gives_the_same_bits(m, d, x, v);
  advance(m, d);  // the wake moved: the hold and the record are gone
  EXPECT_FALSE(d.old_wake_held);
  EXPECT_EQ(d.old_wake[0].size, 0u);
}

// Keeping the older rows apart changes only the order of the single-precision sum: the
// lift of every step of a wingbeat within 1e-5 of its peak of the run summed as one set
// (measured 1.0e-6: the rounding of the sums, 1e-7 relative, grown by the rolling-up wake).
TEST(OldWakeHold, KeepingTheOlderWakeApartChangesOnlyTheRounding) {
  const VortexLatticeModel m = hold_model();
  VortexLatticeData one(m), apart(m);
  apart.old_wake_apart = true;
  const std::vector<double> a = kHover.run(m, one, 1), b = kHover.run(m, apart, 1);
  double peak = 0.0, diff = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    peak = std::max(peak, std::abs(a[k]));
    diff = std::max(diff, std::abs(a[k] - b[k]));
  }
  std::printf("[ value ] lift, older wake apart against one set: %.3g of the peak\n", diff / peak);
  EXPECT_GT(apart.young_wake_segments.capacity(), 0u);
  EXPECT_LT(diff, 1e-5 * peak);
}

// The held sums' error is the older wake's velocity change over the wing's move. With one
// record, the last one as it is: of first order in the move (half the move, half the
// error: ratio 0.5 within 5 %; a sweep of 1e-5 rad, a tip move of 7e-7 m, about what a
// coupling change of 1e-5 rad makes: measured 1.45e-6 of the lift). With two records, moved
// along their secant: below a tenth of that for the same move (measured 2e-9), and of
// second order for a move that goes on along it (half the moves, a quarter of the error:
// ratio 0.25 ± 0.06, measured 0.286 at 1e-3 rad).
TEST(OldWakeHold, TheHeldSumsErrIsOfFirstOrderInTheMoveAndOfSecondAlongTheSecant) {
  const int step = 40;
  const double a = 1e-5;  // [rad]
  const double one = held_error(step, {0.0}, a), one_half = held_error(step, {0.0}, a / 2);
  const double two = held_error(step, {0.0, a / 2}, a);
  // Large moves for the order along the secant (a sweep of 1e-3 rad moves the tip 73 µm): at
  // the small ones the single-precision sums' rounding, 1e-7 of the velocity, is the error.
  const double big = 1e-3, secant = held_error(step, {0.0, big / 2}, big),
               secant_half = held_error(step, {0.0, big / 4}, big / 2);
  std::printf("[ value ] held lift's error, one record: %.3g (half the move %.3g, ratio %.3f); along the secant: "
              "%.3g; at 1e-3 rad %.3g (half the moves %.3g, ratio %.3f)\n",
              one, one_half, one_half / one, two, secant, secant_half, secant_half / secant);
  EXPECT_NE(one, 0.0);  // the hold took the record
  EXPECT_LT(std::abs(one), 3e-6);
  EXPECT_NEAR(one_half / one, 0.5, 0.025);
  EXPECT_LT(std::abs(two), 0.1 * std::abs(one));
  EXPECT_NEAR(secant_half / secant, 0.25, 0.06);  // first order would give 0.5
}

// Nothing is held where the wake is not kept apart: not asked for, a wake in double
// precision.
TEST(OldWakeHold, NothingIsHeldUnlessTheOlderWakeIsApart) {
  for (int c = 0; c < 2; ++c) {
    VortexLatticeModel m = hold_model();
    if (c == 1) m.single_precision_wake = false;
    VortexLatticeData d(m);
    d.old_wake_apart = c > 0;
    run_steps(m, d, 20);
    Eigen::Matrix3Xd v;
    solve(m, d, moved_pose(20, 0.0, v), v, Eigen::Vector3d::Zero(), kHover.dt(), 1.225);
    hold_old_wake_sums(m, d);
    EXPECT_FALSE(d.old_wake_held) << "case " << c;
    EXPECT_EQ(d.young_wake_segments.size(), 0u) << "case " << c;
  }
}

// With a shed leading edge the sheet's rows are kept apart by age as the wake's: those older
// than the young rows join the held sums, the younger ones are summed anew with the young
// wake, the newest (which move with every solve) in double precision. A solve at the
// recorded points gives the same bits held or not, and a move's error with one record is
// of the order of the wake's alone (the test above: 1.45e-6 of the lift for 1e-5 rad;
// measured 2.8e-6 here, where holding the sheet's young rows too gave 1.1e-5: below 5e-6),
// below a tenth of that along the secant (measured 2.7e-8).
TEST(OldWakeHold, AShedSheetIsHeldByAgeAsTheWake) {
  const VortexLatticeModel m = hold_model(LeadingEdge::Shed);
  VortexLatticeData d(m);
  d.old_wake_apart = true;
  const int step = 40;
  run_steps(m, d, step);
  Eigen::Matrix3Xd v;
  const Eigen::Matrix3Xd x = moved_pose(step, 0.0, v);
  solve(m, d, x, v, Eigen::Vector3d::Zero(), kHover.dt(), 1.225);
  ASSERT_GT(d.le_sheet.rows, m.young_wake_rows + 2);  // the sheet has rows older than the young ones
  EXPECT_GT(d.wake_segments.size(), d.trailing_wake_segments);              // its older rows: held
  EXPECT_GT(d.young_wake_segments.size(), d.trailing_young_wake_segments);  // its younger rows: anew
  EXPECT_GT(d.wake_edge_segments.size(), d.trailing_wake_edge_segments);    // its newest: in double
  expect_the_held_solve_gives_the_same_bits(m, d, x, v);
  const double a = 1e-5;  // [rad]
  const double one = held_error(step, {0.0}, a, LeadingEdge::Shed);
  const double two = held_error(step, {0.0, a / 2}, a, LeadingEdge::Shed);
  std::printf("[ value ] shed sheet: held lift's error, one record: %.3g; along the secant: %.3g\n", one,
              two);
  EXPECT_NE(one, 0.0);
  EXPECT_LT(std::abs(one), 5e-6);
  EXPECT_LT(std::abs(two), 0.1 * std::abs(one));
}

// factorise_current_matrix: after a GMRES solve (the iterative path keeps an earlier
// matrix's factors) it factorises the current matrix, leaves the solve's results alone, and
// the added mass's circulation changes are then the direct solve's (Eigen's LU of the
// same matrix, to 1e-12 of their size).
TEST(FactoriseCurrentMatrix, MakesTheAddedMassRightHandSidesDirectSolves) {
  VortexLatticeModel m;
  m.chordwise = 10;
  m.spanwise = 16;  // 160 panels: the iterative path
  m.wake_capacity = 10;
  m.core = {CoreModel::LambOseen, 0.004};
  ASSERT_TRUE(m.iterative(m.panels()));
  PlanformGridOptions o;
  o.chordwise = m.chordwise;
  o.spanwise = m.spanwise;
  const Eigen::Matrix3Xd x0 = make_rectangular_grid(0.02, 0.05, o).nodes;
  VortexLatticeData d(m);
  const double dt = 4e-4, w = 2 * M_PI * 25.0;
  Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, m.nodes());
  for (int k = 0; k < 6; ++k) {
    Eigen::Matrix3Xd x = x0;
    for (Eigen::Index n = 0; n < x.cols(); ++n) x(2, n) += 0.004 * std::sin(w * k * dt) * std::pow(x(1, n) / 0.05, 2);
    v.row(2) = Eigen::RowVectorXd::Constant(m.nodes(), 0.3);
    solve(m, d, x, v, Eigen::Vector3d(5, 0, 0), dt, 1.225);
    if (k < 5) advance(m, d);
  }
  ASSERT_FALSE(d.factorisation_current);  // the last solve was GMRES's
  const long factorisations = d.solver_counts.factorisations;
  const Eigen::VectorXd gamma = d.gamma;
  factorise_current_matrix(d);
  EXPECT_TRUE(d.factorisation_current);
  EXPECT_EQ(d.solver_counts.factorisations, factorisations + 1);
  EXPECT_EQ((d.gamma - gamma).cwiseAbs().maxCoeff(), 0.0);
  factorise_current_matrix(d);  // current already: nothing
  EXPECT_EQ(d.solver_counts.factorisations, factorisations + 1);
  AddedMassScratch s(m);
  Eigen::Matrix3Xd dv = Eigen::Matrix3Xd::Zero(3, m.nodes()), df;
  dv.row(2).setOnes();
  added_mass_force_change(m, d, dv, s, df);
  const Eigen::VectorXd reference = d.influence.partialPivLu().solve(s.rhs);
  EXPECT_LT((s.dgamma - reference).norm(), 1e-12 * reference.norm());
}
