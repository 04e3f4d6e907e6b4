// Leading-edge vortex lift by the suction analogy on a flat AR 1 delta wing (docs/validation.md
// U20, U22): the separated leading-edge model against Polhamus' formula with the constants of
// the same lattice, and against the measured lift Polhamus compared his formula with; the
// shed leading edge (LeadingEdge::Shed) on the same wing started impulsively (U22b).
#include "planform_wings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

/// The experimental points of [Polhamus 1966] Fig. 12 for AR 1
/// (tests/data/delta_wing_ar1_polhamus1966_fig12.csv): α [deg], CL, data set.
struct MeasuredLift {
  double alpha_deg = 0.0, cl = 0.0;
  int set = 0;
};
std::vector<MeasuredLift> polhamus_fig12() {
  std::ifstream in(std::string(FLAPSIM_SOURCE_DIR) + "/tests/data/delta_wing_ar1_polhamus1966_fig12.csv");
  std::vector<MeasuredLift> points;
  MeasuredLift p;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#' && std::sscanf(line.c_str(), "%lf,%lf,%d", &p.alpha_deg, &p.cl, &p.set) == 3)
      points.push_back(p);
  return points;
}

/// Per-step lift coefficient (Bernoulli route, on the lattice's area) of the delta wing
/// started impulsively at α in a stream of U = 1 (ρ = 1), free wake with a fixed Lamb–Oseen
/// core of `core` [m], steps_per_root_chord steps per root chord of travel, over `travel`
/// root chords: the mean, least and largest of the steps from `average_from` root chords on.
struct StartedLift {
  double mean = 0.0, least = 0.0, largest = 0.0;
};
StartedLift impulsively_started_delta_wing(double alpha, LeadingEdge leading_edge, int steps_per_root_chord,
                                           double travel, double average_from, double core) {
  const PlanformWing w = delta_wing();
  const double root = 2.0;
  const int steps = static_cast<int>(std::lround(travel * steps_per_root_chord));
  const int first = static_cast<int>(std::lround(average_from * steps_per_root_chord));
  VortexLatticeModel m;
  m.chordwise = w.chordwise;
  m.spanwise = w.spanwise();
  m.wake_capacity = steps + 1;
  m.core = {CoreModel::LambOseen, core};
  m.leading_edge = leading_edge;
  VortexLatticeData d(m);
  const Eigen::Vector3d v(-std::cos(alpha), 0.0, std::sin(alpha));
  const Eigen::Vector3d lift(std::sin(alpha), 0.0, std::cos(alpha));
  const Eigen::Matrix3Xd nodes = w.nodes();
  const Eigen::Matrix3Xd still = Eigen::Matrix3Xd::Zero(3, m.nodes());
  StartedLift r;
  int n = 0;
  for (int k = 0; k <= steps; ++k) {
    solve(m, d, nodes, still, v, root / steps_per_root_chord, 1.0);
    const double cl = d.loads.total_force.dot(lift) / (0.5 * d.area.sum());
    if (k >= first) {
      r.least = n == 0 ? cl : std::min(r.least, cl);
      r.largest = n == 0 ? cl : std::max(r.largest, cl);
      r.mean += cl;
      ++n;
    }
    if (k < steps) advance(m, d);
  }
  r.mean /= n;
  return r;
}

// Polhamus' constants of this lattice's delta wing [Polhamus 1966]: Kp, the potential
// normal-force slope [/rad], and Kv, the leading-edge suction constant, of the attached
// leading edge at α = 1° with the wake in the wing's plane (linear lifting-surface theory).
struct PolhamusConstants {
  double kp = 0.0, kv = 0.0;
};

PolhamusConstants polhamus_constants(const PlanformWing& w) {
  const double a0 = 1.0 * kDeg;
  const auto potential = steady_loads(w, a0, LeadingEdge::Attached, true);
  return {potential.normal / (std::sin(a0) * std::cos(a0)), potential.suction / (std::sin(a0) * std::sin(a0))};
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
  const auto [kp, kv] = polhamus_constants(w);
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
  const PlanformWing w = delta_wing();
  const std::vector<MeasuredLift> points = polhamus_fig12();
  for (const MeasuredLift& p : points) {
    const double cl = steady_loads(w, p.alpha_deg * kDeg, LeadingEdge::Separated).cl_bernoulli;
    std::printf("[ value ] %5.2f deg (set %d): CL %.4f, measured %.3f (%+.1f %%)\n", p.alpha_deg, p.set, cl, p.cl,
                100 * (cl / p.cl - 1));
    EXPECT_NEAR(cl / p.cl, 1.0, 0.10) << p.alpha_deg << " deg";
  }
  EXPECT_EQ(points.size(), 16u);
}

TEST(VortexLift, ShedLeadingEdgeGivesTheDeltaWingLessThanHalfItsVortexLift) {
  // U22 with LeadingEdge::Shed (issue 30: "Polhamus' delta wing (test U22) still within its
  // present bounds with shed (or the reason)"). The steady lattice sheds nothing, so the
  // wing is started impulsively and run until its lift settles. Chosen before any run of
  // `shed` on this wing and not changed after: U22's 8 × 24 lattice; the free wake with a
  // fixed Lamb–Oseen core of 0.02 root chords (the free-wake runs of U20, docs/uvlm.md; no
  // core growth: the experiment's Reynolds number is high); U Δt = c_root/16 (the release
  // row ½ U Δt = c_root/32 from the edge, a quarter of the root strip's first panel);
  // 6 root chords of travel, the lift averaged over the steps from 4 to 6 root chords;
  // LESP_crit 0.11 (the model's, not adjusted). Measured against the 16 points (docs/uvlm.md,
  // "Polhamus' delta wing with shed"): 13 of them 13–25 % low, 4.07° −4.2 %, 5.07° −9.1 %;
  // at 25.1° the lift does not settle (per-step CL 0.45 … 1.68 over the window), at
  // 12.4°–18.5° (set 1) it has excursions of +8 … +20 % above its mean in the window.
  // Run time: set 2's points below 25° only, 4.0°, 9.95°, 20.1° (15.0°, left out for time,
  // gives −19.6 % and the fraction 0.42), 16 s on 2 cores.
  // Asserted, for each:
  //  - the per-step CL over the window within 3 % of its mean (settled; measured at most
  //    1.0 %, at 20.1°);
  //  - the error against the measured point within −30 … −10 % (measured −13.2, −16.2,
  //    −25.0 %): NOT U22's 10 %. It fails if the model came within 10 % (then update this
  //    test and docs/validation.md U22b) or lost its vortex lift (the attached model in the
  //    same runs: −14.5, −25.5, −38.6 %);
  //  - the fraction of Polhamus' vortex lift it gives, (CL − Kp sin α cos² α) /
  //    (Kv sin² α cos α) with Kp, Kv of this lattice as in U20: measured 0.12, 0.39, 0.44
  //    (in the same runs the attached model 0.03, 0.07, 0.14 and the separated model 1.01,
  //    1.02, 1.05, −1.2, +2.0, +2.9 % of the measured points); bound 0–0.25 at 4° (no strip
  //    sheds there: the attached lift with the end strips' suction analogy), 0.25–0.60 at
  //    10° and 20°.
  //    It fails if the shed sheet added no vortex lift or all of Polhamus'.
  // Not converged in Δt (docs/uvlm.md): at 15.0° with 8, 16, 32, 64 steps per root chord
  // the fraction is 0.95, 0.42, 0.39, 0.32 (CL +1.2, −19.6, −20.7, −23.3 % of the measured
  // point); the 8-step agreement is the coarse step's.
  const auto [kp, kv] = polhamus_constants(delta_wing());
  int checked = 0;
  for (const MeasuredLift& p : polhamus_fig12()) {
    if (p.set != 2 || p.alpha_deg > 21.0 || std::abs(p.alpha_deg - 15.0) < 1.0) continue;
    const double a = p.alpha_deg * kDeg;
    const StartedLift r = impulsively_started_delta_wing(a, LeadingEdge::Shed, 16, 6.0, 4.0, 0.02 * 2.0);
    const double vortex = kv * std::sin(a) * std::sin(a) * std::cos(a);
    const double fraction = (r.mean - kp * std::sin(a) * std::cos(a) * std::cos(a)) / vortex;
    std::printf("[ value ] %5.2f deg: shed CL %.4f (steps %.4f ... %.4f), measured %.3f (%+.1f %%), "
                "fraction of the vortex lift %.2f\n",
                p.alpha_deg, r.mean, r.least, r.largest, p.cl, 100 * (r.mean / p.cl - 1), fraction);
    EXPECT_GT(r.least, 0.97 * r.mean) << p.alpha_deg << " deg";
    EXPECT_LT(r.largest, 1.03 * r.mean) << p.alpha_deg << " deg";
    EXPECT_GT(r.mean / p.cl - 1.0, -0.30) << p.alpha_deg << " deg";
    EXPECT_LT(r.mean / p.cl - 1.0, -0.10) << p.alpha_deg << " deg";
    EXPECT_GT(fraction, p.alpha_deg < 5.0 ? 0.0 : 0.25) << p.alpha_deg << " deg";
    EXPECT_LT(fraction, p.alpha_deg < 5.0 ? 0.25 : 0.60) << p.alpha_deg << " deg";
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}
