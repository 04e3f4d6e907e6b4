// Steady loads of the vortex lattice on panels of any shape: lattice invariance, the two
// load routes against each other, and the near-field induced drag (leading-edge suction)
// against the Trefftz plane (docs/validation.md U14–U16).
#include "planform_wings.hpp"

#include <Eigen/QR>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace flapsim::uvlm;
using flapsim::uvlm::testing::PlanformWing;
using flapsim::uvlm::testing::steady_loads;
using flapsim::uvlm::testing::uniform_stations;

namespace {

constexpr double kDeg = M_PI / 180.0;

PlanformWing rectangle(double aspect_ratio, int nc, int ns) {
  PlanformWing w;
  w.chordwise = nc;
  w.stations = uniform_stations(-0.5 * aspect_ratio, 0.5 * aspect_ratio, ns);
  w.leading_edge = [](double) { return 0.0; };
  w.chord = [](double) { return 1.0; };
  return w;
}

}  // namespace

TEST(AeroLoads, LiftDoesNotDependOnTheShearOfThePanels) {
  // The same AR 8 rectangle at 5°, meshed with orthogonal panels and with its interior
  // chordwise grid lines tilted by 30° (parallelogram panels with 60° corners; the root and
  // tip strips become trapezoids): the lift is a property of the wing, not of the mesh.
  // Bound: 0.5 % (issue 12). The edge-tangent pressure formula (V·τc ∂Γ/∂c + V·τs ∂Γ/∂s,
  // Katz & Plotkin §13.8) loses cos² 30° of the sheared panels' lift.
  const PlanformWing a = rectangle(8.0, 8, 16);
  PlanformWing b = a;
  b.shear = [](int j) { return j == 0 || j == 16 ? 0.0 : std::tan(30 * kDeg); };
  const auto ra = steady_loads(a, 5 * kDeg, LeadingEdge::Attached);
  const auto rb = steady_loads(b, 5 * kDeg, LeadingEdge::Attached);
  std::printf("[ value ] orthogonal CL %.5f (KJ %.5f), sheared 30 deg CL %.5f (KJ %.5f): %+.3f %%\n",
              ra.cl_bernoulli, ra.cl_kutta_joukowski, rb.cl_bernoulli, rb.cl_kutta_joukowski,
              100 * (rb.cl_bernoulli / ra.cl_bernoulli - 1));
  EXPECT_NEAR(rb.cl_bernoulli / ra.cl_bernoulli, 1.0, 0.005);
  EXPECT_NEAR(rb.cl_kutta_joukowski / ra.cl_kutta_joukowski, 1.0, 0.005);
  EXPECT_NEAR(rb.cl_bernoulli / rb.cl_kutta_joukowski, 1.0, 0.005);
}

TEST(AeroLoads, SweptWingBernoulliAgreesWithKuttaJoukowski) {
  // 45°-swept untapered wing of AR 5 (both halves, streamwise chord 1), α = 4°: the panels
  // are sheared by 45°. The two load routes of the same lattice agree within 1 % (issue 12).
  PlanformWing w;
  w.chordwise = 8;
  w.stations = uniform_stations(-2.5, 2.5, 40);
  w.leading_edge = [](double y) { return -std::abs(y); };
  w.chord = [](double) { return 1.0; };
  const auto r = steady_loads(w, 4 * kDeg, LeadingEdge::Attached);
  std::printf("[ value ] 45 deg swept AR 5, 4 deg: CL Bernoulli %.5f, KJ %.5f (%+.3f %%), Trefftz %.5f\n",
              r.cl_bernoulli, r.cl_kutta_joukowski, 100 * (r.cl_bernoulli / r.cl_kutta_joukowski - 1),
              r.cl_trefftz);
  EXPECT_NEAR(r.cl_bernoulli / r.cl_kutta_joukowski, 1.0, 0.01);
}

TEST(AeroLoads, NearFieldInducedDragMatchesTheTrefftzPlane) {
  // Near-field induced drag (pressure plus leading-edge suction, attached) against the
  // Trefftz-plane drag of the same circulations (Katz & Plotkin §8.3): within 2 % (issue 12).
  // Elliptic wing: span efficiency within 2 % of 1 (Prandtl's lifting line: the elliptic
  // loading has e = 1; Katz & Plotkin §8.1).
  const double alpha = 5 * kDeg;
  {
    const auto r = steady_loads(rectangle(4.0, 8, 32), alpha, LeadingEdge::Attached);
    std::printf("[ value ] AR 4 rectangle: CD near field %.6f, KJ %.6f, Trefftz %.6f (%+.2f %%); CL %.5f\n",
                r.cd_bernoulli, r.cd_kutta_joukowski, r.cd_trefftz,
                100 * (r.cd_bernoulli / r.cd_trefftz - 1), r.cl_bernoulli);
    EXPECT_NEAR(r.cd_bernoulli / r.cd_trefftz, 1.0, 0.02);
    EXPECT_NEAR(r.cd_kutta_joukowski / r.cd_trefftz, 1.0, 0.02);
  }
  {
    // Elliptic planform, span 4, root chord 4b/(π AR) for AR 4, straight quarter-chord line,
    // 8 × 48 panels, uniform span stations ending where the chord is 2 % of the root chord.
    // The near-field drag of a curved leading edge depends on the lattice more than the
    // Trefftz drag does (docs/uvlm.md, "Induced drag": −12 … +12 % over 4–8 × 24–96 panels,
    // within 2 % from 48 spanwise panels at 8 chordwise); this is one such lattice.
    const double b = 4.0, c0 = 4.0 * b / (M_PI * 4.0), y_end = 0.5 * b * std::sqrt(1.0 - 0.02 * 0.02);
    PlanformWing w;
    w.chordwise = 8;
    w.stations = uniform_stations(-y_end, y_end, 48);
    w.chord = [=](double y) { return c0 * std::sqrt(std::max(0.0, 1.0 - 4.0 * y * y / (b * b))); };
    w.leading_edge = [=](double y) { return 0.25 * w.chord(y); };
    const auto r = steady_loads(w, alpha, LeadingEdge::Attached);
    // Span efficiency of the lattice's loading (Katz & Plotkin §8.1, lifting line):
    // Γ(θ) = Σ A_n sin nθ, y = −(b/2) cos θ, e = 1 / (1 + Σ_(n≥2) n A_n² / A_1²), fitted by
    // least squares to the strip circulations at the strip midpoints (odd n ≤ 9: symmetric).
    const int ns = static_cast<int>(r.strip_gamma.size()), modes = 5;
    Eigen::MatrixXd basis(ns, modes);
    Eigen::VectorXd gamma(ns);
    for (int j = 0; j < ns; ++j) {
      const double theta = std::acos(std::clamp(-2.0 * r.strip_mid[j] / b, -1.0, 1.0));
      for (int m = 0; m < modes; ++m) basis(j, m) = std::sin((2 * m + 1) * theta);
      gamma(j) = r.strip_gamma[j];
    }
    const Eigen::VectorXd A = basis.colPivHouseholderQr().solve(gamma);
    double delta = 0.0;
    for (int m = 1; m < modes; ++m) delta += (2 * m + 1) * A(m) * A(m) / (A(0) * A(0));
    const double e = 1.0 / (1.0 + delta);
    std::printf("[ value ] elliptic AR 4: CD near field %.6f, KJ %.6f, Trefftz %.6f (%+.2f %%); e %.5f\n",
                r.cd_bernoulli, r.cd_kutta_joukowski, r.cd_trefftz,
                100 * (r.cd_bernoulli / r.cd_trefftz - 1), e);
    EXPECT_NEAR(r.cd_bernoulli / r.cd_trefftz, 1.0, 0.02);
    EXPECT_NEAR(e, 1.0, 0.02);
    // The same with a case's wake core, 0.2 mean chords (c̄ = 1 here): the same loads. Until
    // 3 Dec that core smoothed the steady wake's legs beside the last panels, and a case's
    // elliptic wing (A = 5.09, 8 × 32 … 16 × 128) gave a near-field CD 5–7 % under the
    // Trefftz drag (e = 1.069 … 1.050 from CL²/(π A CD)); now e = 1.021 … 0.998.
    const auto cased = steady_loads(w, alpha, LeadingEdge::Attached, false, 0.2);
    std::printf("[ value ] elliptic AR 4, wake core 0.2 c: CD near field %.6f, Trefftz %.6f (%+.2f %%)\n",
                cased.cd_bernoulli, cased.cd_trefftz, 100 * (cased.cd_bernoulli / cased.cd_trefftz - 1));
    EXPECT_NEAR(cased.cd_bernoulli / r.cd_bernoulli, 1.0, 1e-9);
    EXPECT_NEAR(cased.cd_kutta_joukowski / r.cd_kutta_joukowski, 1.0, 1e-9);
    EXPECT_NEAR(cased.cd_bernoulli / cased.cd_trefftz, 1.0, 0.02);
  }
}
