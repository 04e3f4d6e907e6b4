// Leading-edge vortex lift by the suction analogy on a flat AR 1 delta wing (docs/validation.md
// U20): the separated leading-edge model against Polhamus' formula with the constants of
// the same lattice.
#include "planform_wings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace flapsim::uvlm;
using flapsim::uvlm::testing::PlanformWing;
using flapsim::uvlm::testing::steady_loads;
using flapsim::uvlm::testing::uniform_stations;

TEST(VortexLift, DeltaWingFollowsThePolhamusAnalogyOfItsOwnLattice) {
  // AR 1 delta (span 1, root chord 2, leading edges swept 76°), 8 × 24 panels, span
  // stations ending where the chord is 2 % of the root chord. [Polhamus 1966]:
  //   CL = Kp sin α cos² α + Kv sin² α cos α,
  // Kp the potential normal-force slope, Kv the suction (per sin² α) of the same lattice
  // at α = 1° with the attached leading edge. The separated model is the same suction
  // turned normal, so it must follow the formula; what differs is the lattice's own
  // nonlinearity (its wake leaves along the free stream, not in the wing plane, so the
  // normal force grows a little faster than sin α cos α: Kp(α)/Kp(1°) = 1.04 at 20°).
  // Bound: 3 % at 5°–20° (issue 12); at 25° the difference is +3.7 % (printed).
  const double deg = M_PI / 180.0, b = 1.0, root = 2.0;
  PlanformWing w;
  w.chordwise = 8;
  w.stations = uniform_stations(-0.49 * b, 0.49 * b, 24);
  w.chord = [=](double y) { return root * (1.0 - 2.0 * std::abs(y) / b); };
  w.leading_edge = [=](double y) { return -root * 2.0 * std::abs(y) / b; };
  const double a0 = 1.0 * deg;
  const auto potential = steady_loads(w, a0, LeadingEdge::Attached);
  const double kp = potential.normal / (std::sin(a0) * std::cos(a0));
  const double kv = potential.suction / (std::sin(a0) * std::sin(a0));
  std::printf("[ value ] AR 1 delta lattice: Kp %.4f /rad, Kv %.4f\n", kp, kv);
  for (double alpha_deg : {5.0, 10.0, 15.0, 20.0, 25.0}) {
    const double a = alpha_deg * deg;
    const auto r = steady_loads(w, a, LeadingEdge::Separated);
    const double polhamus = kp * std::sin(a) * std::cos(a) * std::cos(a) + kv * std::sin(a) * std::sin(a) * std::cos(a);
    const double attached = steady_loads(w, a, LeadingEdge::Attached).cl_bernoulli;
    std::printf("[ value ] %4.0f deg: CL separated %.4f (KJ %.4f), Polhamus %.4f (%+.2f %%), attached %.4f\n",
                alpha_deg, r.cl_bernoulli, r.cl_kutta_joukowski, polhamus, 100 * (r.cl_bernoulli / polhamus - 1),
                attached);
    if (alpha_deg <= 20.0) EXPECT_NEAR(r.cl_bernoulli / polhamus, 1.0, 0.03) << alpha_deg << " deg";
    EXPECT_NEAR(r.cl_bernoulli / r.cl_kutta_joukowski, 1.0, 0.01) << alpha_deg << " deg";
    EXPECT_GT(r.cl_bernoulli, attached * 1.1) << "no vortex lift at " << alpha_deg << " deg";
  }
}
