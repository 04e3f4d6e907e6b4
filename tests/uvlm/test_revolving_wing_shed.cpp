// The shed leading-edge vortex on the revolving Robofly wing (LeadingEdge::Shed; docs/uvlm.md,
// "Leading-edge vortex shedding: measurements"): with laminar viscous cores the sheet stays
// steady in the wing's frame, the force stays normal to the wing, and the mean lift and drag
// at 50° meet Dickinson et al. 1999's fit; the end strips of the outline do not shed and keep
// the suction analogy; a shedding strip's suction is the LDVM's π ρ U² c A0².
#include "robofly_revolving.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace robofly_revolving;

namespace {

/// ν of the Robofly experiment: Re = U c̄ / ν ≈ 136 [Dickinson, Lehmann & Sane 1999], taken on
/// the tip speed ω R = 2π · 0.25 m/s and the mean chord c̄ = S/R = 0.06329 m of this outline
/// (chosen from the experiment before any run, not adjusted): 7.31e-4 m²/s.
constexpr double kRoboflyViscosity = 2.0 * M_PI * 0.25 * 0.06329 / 136.0;

}  // namespace

TEST(RevolvingWingShed, ViscousCoresKeepTheLiftSteadyAndNormalToTheWingAt50Degrees) {
  // A wing revolving at constant speed settles to a steady flow in its own frame with a
  // stable leading-edge vortex ([Dickinson et al. 1999]; [Usherwood & Ellington 2002]: the
  // force is then normal to the wing). With fixed cores the shed sheet broke down from ~60°
  // of revolution (per-step CL −1.6 … +7.9 over 90°–180° at 120 steps; docs/uvlm.md); with
  // laminar Lamb–Oseen cores (ν of the experiment) and the rules of leading_edge_loads.cpp
  // and kResolvedStripChordRatio, 120 steps per half revolution, over 90°–180°:
  //  - the per-step CL stays within 20 % of its mean (measured 1.563 … 1.892, mean 1.649,
  //    standard deviation 2.7 %);
  //  - the force is normal to the wing within 3° (measured atan(CD/CL) = 47.6° at α = 50°);
  //  - mean CL within 10 % and CD within 15 % of the fit (issue 30's bounds; measured
  //    1.649 against 1.784, −7.6 %, and 1.809 against 1.979, −8.6 %).
  const int steps = 120;
  const double alpha = 50.0;
  std::vector<double> lift;
  double cl = 0.0, cd = 0.0;
  revolve_each(
      alpha, LeadingEdge::Shed, steps,
      [&](int k, const VortexLatticeData&, double l, double dr) {
        if (k >= steps / 2) {
          lift.push_back(l);
          cl += l;
          cd += dr;
        }
        return true;
      },
      kRoboflyViscosity);
  cl /= static_cast<double>(lift.size());
  cd /= static_cast<double>(lift.size());
  double lo = lift.front(), hi = lift.front();
  for (double l : lift) lo = std::min(lo, l), hi = std::max(hi, l);
  std::printf("[ value ] alpha 50, 120 steps, viscous cores: CL %.4f (%.3f ... %.3f), CD %.4f; fit %.3f, %.3f\n", cl, lo,
              hi, cd, measured_lift(alpha), measured_drag(alpha));
  EXPECT_GT(lo, 0.8 * cl);
  EXPECT_LT(hi, 1.2 * cl);
  EXPECT_NEAR(std::atan2(cd, cl) * 180.0 / M_PI, alpha, 3.0);
  EXPECT_NEAR(cl / measured_lift(alpha), 1.0, 0.10);
  EXPECT_NEAR(cd / measured_drag(alpha), 1.0, 0.15);
}

TEST(RevolvingWingShed, EndStripsKeepTheSuctionAnalogyAndSheddingStripsTheLdvmSuction) {
  // Robofly wing at 50°, 30 steps to 60° of revolution, every step:
  //  - the root and tip strips (chords of their sides 0.016/0.082 m and 0.059/0.010 m:
  //    ratio < 0.5, kResolvedStripChordRatio) never shed, and their leading-edge force is
  //    normal to the wing with the magnitude of the lattice's suction (Polhamus 1966);
  //  - a strip that sheds has the suction of the leading-edge singularity with A0 = LESP,
  //    π ρ U² c A0² per unit span, in the wing's plane, forward (Ramesh et al. 2014, §2:
  //    C_S = 2π A0²);
  //    with |LESP| = 0.11 that is 2π · 0.11² = 0.076 of ½ ρ U² c.
  int shedding = 0;
  revolve_each(50.0, LeadingEdge::Shed, 30, [&](int k, const VortexLatticeData& d, double, double) {
    const LeadingEdgeSheet& s = d.le_sheet;
    const int ns = static_cast<int>(s.lesp.size()), nc = static_cast<int>(d.gamma.size()) / ns;
    for (int j = 0; j < ns; ++j) {
      const int p = j * nc;  // panel (0, j): strips are stored chordwise-first
      const Eigen::Vector3d f = d.loads.leading_edge_force.col(p), n = d.normal.col(p);
      if (j == 0 || j == ns - 1) {
        EXPECT_FALSE(s.resolved[j] || s.shedding[j]) << "step " << k << ", strip " << j;
        EXPECT_NEAR(std::abs(f.dot(n)), f.norm(), 1e-12 * (1.0 + f.norm())) << "step " << k << ", strip " << j;
        EXPECT_NEAR(f.norm(), d.loads.suction.col(j).norm(), 1e-12 * (1.0 + f.norm()));
      } else if (s.shedding[j]) {
        ++shedding;
        EXPECT_NEAR(f.dot(n), 0.0, 1e-12 * (1.0 + f.norm())) << "step " << k << ", strip " << j;
        // Per unit length along the first panel's spanwise direction (the direction the
        // LESP's U is taken normal to): the leading-edge segment's length along it.
        const Eigen::Vector3d edge = d.nodes.col((nc + 1) * (j + 1)) - d.nodes.col((nc + 1) * j);
        const double width = std::abs(edge.dot(d.span_tangent.col(p)));
        const double expected = M_PI * s.edge_speed(j) * s.edge_speed(j) * s.strip_chord(j) * s.lesp(j) * s.lesp(j) * width;
        EXPECT_NEAR(f.norm(), expected, 1e-12 * expected) << "step " << k << ", strip " << j;  // ρ = 1
        EXPECT_NEAR(s.lesp(j) * s.lesp(j), 0.11 * 0.11, 1e-12);
        EXPECT_GT(width, 0.0187 * 0.99) << "step " << k << ", strip " << j;  // at least the strips' 0.0187 m
        // pointing forward: toward the leading edge, away from the second node row
        const Eigen::Vector3d behind = d.nodes.col((nc + 1) * j + 1) - d.nodes.col((nc + 1) * j);
        EXPECT_LT(f.dot(behind), 0.0) << "step " << k << ", strip " << j;
      }
    }
    return k < 10;
  });
  EXPECT_GT(shedding, 8 * 11 / 2);
}

TEST(RevolvingWingShed, TheSheetsRowsOlderThanTheFrozenWakeAgeStayWhereTheyAre) {
  // VortexLatticeModel::frozen_wake_age acts on the sheet as on the wake (wake.cpp): its rows
  // older than the age neither move nor have their velocity summed; younger rows move.
  // (Before 29 Nov, evening, the sheet's rows went on moving with their own velocity.)
  // Robofly at 50°, 30 steps to 60° of revolution, frozen after 8 steps: the oldest sheet
  // row's nodes between the step they froze and the last.
  const int steps = 30, frozen_after = 8;
  std::vector<double> at_freeze, at_end, at_start, before_freeze;
  double frozen_age = 0.0;
  revolve_each(
      50.0, LeadingEdge::Shed, steps,
      [&](int k, const VortexLatticeData& d, double, double) {
        const LeadingEdgeSheet& s = d.le_sheet;
        if (s.rows < 1) return true;
        auto row0 = [&] { return std::vector<double>(s.nodes.x.begin(), s.nodes.x.begin() + (d.spanwise + 1)); };
        frozen_age = frozen_after * d.dt;
        if (at_start.empty()) at_start = row0();
        if (s.row_age[0] <= frozen_age) before_freeze = row0();
        if (at_freeze.empty() && s.row_age[0] > frozen_age) at_freeze = row0();
        if (k == steps) at_end = row0();
        return true;
      },
      0.0, [&](VortexLatticeModel& m) { m.frozen_wake_age = frozen_after * (M_PI / (2.0 * M_PI) / steps); });
  ASSERT_FALSE(at_freeze.empty());
  ASSERT_EQ(at_end.size(), at_freeze.size());
  for (std::size_t j = 0; j < at_end.size(); ++j) EXPECT_EQ(at_end[j], at_freeze[j]) << "node " << j;
  // It moved while younger (else the check above shows nothing).
  double moved = 0.0;
  for (std::size_t j = 0; j < at_start.size(); ++j) moved = std::max(moved, std::abs(before_freeze[j] - at_start[j]));
  EXPECT_GT(moved, 1e-4);
}
