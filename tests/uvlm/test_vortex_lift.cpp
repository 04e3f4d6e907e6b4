// Leading-edge vortex lift by the suction analogy on a flat AR 1 delta wing (docs/validation.md
// U20, U22): the separated leading-edge model against Polhamus' formula with the constants of
// the same lattice, and against the measured lift Polhamus compared his formula with.
#include "planform_wings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

using namespace flapsim::uvlm;
using flapsim::uvlm::testing::PlanformWing;
using flapsim::uvlm::testing::steady_loads;
using flapsim::uvlm::testing::uniform_stations;

namespace {

constexpr double kDeg = M_PI / 180.0;

/// AR 1 delta (span 1, root chord 2, leading edges swept 76°), 8 × 24 panels, span
/// stations ending where the chord is 2 % of the root chord.
PlanformWing delta_wing() {
  const double b = 1.0, root = 2.0;
  PlanformWing w;
  w.chordwise = 8;
  w.stations = uniform_stations(-0.49 * b, 0.49 * b, 24);
  w.chord = [=](double y) { return root * (1.0 - 2.0 * std::abs(y) / b); };
  w.leading_edge = [=](double y) { return -root * 2.0 * std::abs(y) / b; };
  return w;
}

}  // namespace

TEST(VortexLift, DeltaWingFollowsThePolhamusAnalogyOfItsOwnLattice) {
  // [Polhamus 1966] (NASA TN D-3767): CL = Kp sin α cos² α + Kv sin² α cos α, with Kp the
  // potential normal-force slope and Kv the leading-edge suction constant of LINEAR
  // lifting-surface theory (the wake in the wing's plane); the nonlinearity of the formula
  // is only the exact boundary condition (sin α) and the turning of the suction normal to
  // the wing. What is compared (issue 12: "within 3 % of the suction analogy evaluated
  // from the same lattice's potential and suction constants"):
  //  - the analogy: Kp, Kv of this lattice (attached leading edge, α = 1°, wake planar);
  //  - the lattice: CL of the separated model under the analogy's own assumption, the
  //    steady wake in the wing's plane, at 5°–25°. Bound 0.1 % (the 3 %, tightened
  //    to what linear theory makes exact; measured below 0.001 %): it fails
  //    if the separated model turned the suction wrongly or mis-sized it, or if the
  //    lattice's normal force or suction were not the linear-theory ones.
  //  - printed, and bound at 3 % at 5°–20° only: the same with the default steady wake
  //    along V∞, which is not the analogy's flow — the trailing vortices leave the wing's
  //    plane at α and induce less downwash, so the normal force grows faster than
  //    sin α cos α: +0.2, +0.7, +1.5, +2.5, +3.6 % at 5…25°. That wake ignores the
  //    downwash acting on the wake itself; the relaxed free wake (impulsive start, 8 steps
  //    per root chord, 6 root chords) is inclined 7° to the wing's plane on the centre line
  //    half a root chord behind the edge at α = 25° (15° at three root chords, 17° at five,
  //    the tip vortices 20–22°), and its CL
  //    lies between: +0.5, +1.3, +1.9, +2.8 % at 5, 15, 20, 25° (docs/uvlm.md).
  const PlanformWing w = delta_wing();
  const double a0 = 1.0 * kDeg;
  const auto potential = steady_loads(w, a0, LeadingEdge::Attached, true);
  const double kp = potential.normal / (std::sin(a0) * std::cos(a0));
  const double kv = potential.suction / (std::sin(a0) * std::sin(a0));
  std::printf("[ value ] AR 1 delta lattice: Kp %.4f /rad, Kv %.4f\n", kp, kv);
  for (double alpha_deg : {5.0, 10.0, 15.0, 20.0, 25.0}) {
    const double a = alpha_deg * kDeg;
    const auto r = steady_loads(w, a, LeadingEdge::Separated);
    const auto planar = steady_loads(w, a, LeadingEdge::Separated, true);
    const double polhamus = kp * std::sin(a) * std::cos(a) * std::cos(a) + kv * std::sin(a) * std::sin(a) * std::cos(a);
    const double attached = steady_loads(w, a, LeadingEdge::Attached).cl_bernoulli;
    std::printf("[ value ] %4.0f deg: CL separated %.4f (KJ %.4f), Polhamus %.4f (%+.2f %%), planar wake %.4f "
                "(%+.3f %%), attached %.4f\n",
                alpha_deg, r.cl_bernoulli, r.cl_kutta_joukowski, polhamus, 100 * (r.cl_bernoulli / polhamus - 1),
                planar.cl_bernoulli, 100 * (planar.cl_bernoulli / polhamus - 1), attached);
    EXPECT_NEAR(planar.cl_bernoulli / polhamus, 1.0, 0.001) << alpha_deg << " deg, planar wake";
    if (alpha_deg <= 20.0) {
      EXPECT_NEAR(r.cl_bernoulli / polhamus, 1.0, 0.03) << alpha_deg << " deg";
    }
    EXPECT_NEAR(r.cl_bernoulli / r.cl_kutta_joukowski, 1.0, 0.01) << alpha_deg << " deg";
    EXPECT_GT(r.cl_bernoulli, attached * 1.1) << "no vortex lift at " << alpha_deg << " deg";
  }
}

TEST(VortexLift, DeltaWingLiftAgreesWithMeasurements) {
  // The measured lift of a flat sharp-edged AR 1 delta wing, the experimental points of
  // [Polhamus 1966] Fig. 12 (tests/data/delta_wing_ar1_polhamus1966_fig12.csv), 4°–25°:
  // the separated model (default steady wake along V∞) within 10 % of each point (issue 12).
  std::ifstream in(std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/delta_wing_ar1_polhamus1966_fig12.csv");
  ASSERT_TRUE(in.good());
  const PlanformWing w = delta_wing();
  int points = 0;
  double alpha_deg = 0.0, measured = 0.0;
  int set = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || std::sscanf(line.c_str(), "%lf,%lf,%d", &alpha_deg, &measured, &set) != 3)
      continue;
    const double cl = steady_loads(w, alpha_deg * kDeg, LeadingEdge::Separated).cl_bernoulli;
    std::printf("[ value ] %5.2f deg (set %d): CL %.4f, measured %.3f (%+.1f %%)\n", alpha_deg, set, cl, measured,
                100 * (cl / measured - 1));
    EXPECT_NEAR(cl / measured, 1.0, 0.10) << alpha_deg << " deg";
    ++points;
  }
  EXPECT_EQ(points, 16);
}
