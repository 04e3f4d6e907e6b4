// The implicit integrator: observed order of accuracy, re-entrancy (a step can be redone
// with other loads), and the failure it reports when a step cannot be solved.

#include "chain_test_models.hpp"

#include "mbd/chain_data.hpp"
#include "mbd/convergence_failure.hpp"
#include "mbd/generalized_alpha.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace flapsim::mbd {
namespace {

// Forced, damped, moving-base run of the general chain to t_end; Φ at the end.
Eigen::VectorXd run(double rho, int steps, double t_end) {
  const ChainModel model = test::general_chain();
  ChainData data(model);
  const BaseMotion base = make_base_motion(test::wobbling_kinematics(26.0));
  Loads loads(model.num_bodies());
  auto fill = [&](double t) {
    loads.clear();
    loads.add_force(3, Eigen::Vector3d(0.0, 0.01, 0.0),
                    Eigen::Vector3d(0.0, 0.0, 0.003 * std::sin(2 * test::kPi * 26.0 * t)), LoadFrame::ground);
  };
  fill(0.0);
  ChainState s = make_initial_state(model, data, base, 0.0, model.rest_angles(),
                                    Eigen::VectorXd::Zero(model.num_dofs()), loads);
  GeneralizedAlphaSettings settings;
  settings.rho_infinity = rho;
  settings.tolerance = 1e-13;
  const double dt = t_end / steps;
  for (int k = 0; k < steps; ++k) {
    fill(s.time + dt);
    advance(model, data, base, settings, s, dt, loads, s);
  }
  return s.q;
}

TEST(GeneralizedAlpha, ObservedOrderIsTwo) {
  // Chung & Hulbert (1993), Arnold & Brüls (2007): second order for every ρ∞ when
  // started with a₀ = Φ̈₀. Errors against a 16× finer run, steps resolving the chain's
  // highest mode (511 Hz: ω_max h ≤ 0.25); in the asymptotic range the ratio per halving
  // is 4·(1 + O(h)), so the observed order log2(ratio) is asserted within 2 ± 0.15.
  const double t_end = 1.0 / 26.0;  // one flapping cycle
  for (double rho : {0.8}) {
    const Eigen::VectorXd ref = run(rho, 500 * 16, t_end);
    const double e1 = (run(rho, 500, t_end) - ref).norm();
    const double e2 = (run(rho, 1000, t_end) - ref).norm();
    const double e3 = (run(rho, 2000, t_end) - ref).norm();
    std::printf("[order] rho_inf = %.1f: errors %.3e %.3e %.3e, ratios %.3f %.3f, orders %.3f %.3f\n",
                rho, e1, e2, e3, e1 / e2, e2 / e3, std::log2(e1 / e2), std::log2(e2 / e3));
    RecordProperty("order_ratio_rho_" + std::to_string(rho), std::to_string(e2 / e3));
    EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.15);
    EXPECT_NEAR(std::log2(e2 / e3), 2.0, 0.15);
  }
}

TEST(GeneralizedAlpha, StepCanBeRedoneWithOtherLoadsWithoutChangingTheStartState) {
  const ChainModel model = test::three_body_chain();
  ChainData data(model);
  const BaseMotion base = make_base_motion(test::three_body_kinematics());
  Loads loads(model.num_bodies());
  test::three_body_loads(0.0, loads);
  const int n = model.num_dofs();
  ChainState s0 = make_initial_state(model, data, base, 0.0, Eigen::VectorXd::Zero(n),
                                     Eigen::VectorXd::Zero(n), loads);
  for (int k = 0; k < 20; ++k) {
    test::three_body_loads(s0.time + 1e-5, loads);
    advance(model, data, base, GeneralizedAlphaSettings{}, s0, 1e-5, loads, s0);
  }
  const ChainState copy = s0;
  ChainState a, b, c;
  test::three_body_loads(s0.time + 1e-5, loads);
  advance(model, data, base, GeneralizedAlphaSettings{}, s0, 1e-5, loads, a);
  Loads other(model.num_bodies());
  other.add_force(2, Eigen::Vector3d(0, 0.0161, 0), Eigen::Vector3d(0, 0, 0.05), LoadFrame::ground);
  advance(model, data, base, GeneralizedAlphaSettings{}, s0, 1e-5, other, b);  // a sub-iteration
  advance(model, data, base, GeneralizedAlphaSettings{}, s0, 1e-5, loads, c);  // back to the first
  EXPECT_EQ((s0.q - copy.q).norm(), 0.0);  // the start state is untouched
  EXPECT_EQ((s0.v - copy.v).norm(), 0.0);
  EXPECT_EQ(s0.time, copy.time);
  EXPECT_GT((b.q - a.q).norm(), 1e-3 * a.q.norm());  // the other load matters
  // Same answer up to the solver tolerance (the Broyden matrix is only a starting guess).
  EXPECT_LT((c.q - a.q).norm(), 1e-9 * a.q.norm());
  EXPECT_LT((c.qdd - a.qdd).norm(), 1e-8 * a.qdd.norm());
  EXPECT_EQ(a.step, copy.step + 1);
  EXPECT_DOUBLE_EQ(a.time, copy.time + 1e-5);
}

TEST(GeneralizedAlpha, UnsolvableStepThrowsConvergenceFailureNamingStepAndTime) {
  const ChainModel model = test::three_body_chain();
  ChainData data(model);
  // A base whose motion turns NaN after t = 1.005 ms.
  const WingKinematics kin = test::three_body_kinematics();
  const BaseMotion base = [&](double t) {
    BasePose p = kin.pose(t);
    if (t > 1.005e-3) p.angular_acceleration.x() = std::numeric_limits<double>::quiet_NaN();
    return p;
  };
  Loads loads(model.num_bodies());
  const int n = model.num_dofs();
  ChainState s = make_initial_state(model, data, base, 0.0, Eigen::VectorXd::Zero(n),
                                    Eigen::VectorXd::Zero(n), loads);
  try {
    for (int k = 0; k < 200; ++k) advance(model, data, base, GeneralizedAlphaSettings{}, s, 1e-5, loads, s);
    FAIL() << "no ConvergenceFailure";
  } catch (const ConvergenceFailure& e) {
    EXPECT_EQ(e.step(), 100);  // t = 101e-5 s is the first end time past 1.005 ms
    EXPECT_NEAR(e.time(), 1.01e-3, 1e-12);
    EXPECT_NE(std::string(e.what()).find("step 100"), std::string::npos) << e.what();
  }
  // Too few iterations allowed: also a ConvergenceFailure, not a silent wrong answer.
  GeneralizedAlphaSettings strict;
  strict.max_iterations = 0;
  ChainData fresh(model);
  ChainState s2 = make_initial_state(model, fresh, make_base_motion(kin), 0.0, Eigen::VectorXd::Zero(n),
                                     Eigen::VectorXd::Zero(n), loads);
  EXPECT_THROW(advance(model, fresh, make_base_motion(kin), strict, s2, 1e-4, loads, s2), ConvergenceFailure);
}

}  // namespace
}  // namespace flapsim::mbd
