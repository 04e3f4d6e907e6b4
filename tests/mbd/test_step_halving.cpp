// Step halving (mbd/generalized_alpha.hpp): a step whose quasi-Newton solve does not
// converge whole is solved in halves.
// Before: the rotation-phase paper's 3-body chain (chain_test_models.hpp), base held still,
// released from Φ = 0.5 rad on every joint with the joints' rates ±50 rad/s, stopped at its
// first step of h = 3 ms with "quasi-Newton solve did not converge in 50 iterations"
// (residual 4.5e-2 against a force scale 0.11 N m); two steps of 1.5 ms converge.
#include <gtest/gtest.h>

#include "chain_test_models.hpp"
#include "mbd/chain_data.hpp"
#include "mbd/convergence_failure.hpp"
#include "mbd/generalized_alpha.hpp"

#include <cmath>
#include <vector>

namespace flapsim::mbd::test {
namespace {

struct Outcome {
  Eigen::VectorXd q, v;
  int last_substeps = 0;
  long split_steps = 0;
};

// `steps` steps of h from the released state; halving down to h / 2^halvings.
Outcome release(double h, int steps, int halvings) {
  const ChainModel model = three_body_chain();
  const BaseMotion base = fixed_base();
  const Loads loads(model.num_bodies());
  ChainData data(model);
  GeneralizedAlphaSettings settings;
  settings.max_step_halvings = halvings;
  const Eigen::VectorXd q0 = Eigen::VectorXd::Constant(4, 0.5);
  const Eigen::VectorXd v0 = (Eigen::VectorXd(4) << -50.0, 50.0, -50.0, 50.0).finished();
  ChainState state = make_initial_state(model, data, base, 0.0, q0, v0, loads), next;
  for (int k = 0; k < steps; ++k) {
    advance(model, data, base, settings, state, h, loads, next);
    state = next;
  }
  return {state.q, state.v, data.step.last_substeps, data.step.split_steps};
}

TEST(StepHalving, AStepThatDoesNotConvergeWholeIsSolvedInHalves) {
  // Without halving: today's failure.
  EXPECT_THROW(release(3e-3, 1, 0), ConvergenceFailure);
  // With it: two pieces, exactly two generalized-α steps of h/2 (the variable-step form).
  const Outcome halved = release(3e-3, 1, 6);
  EXPECT_EQ(halved.last_substeps, 2);
  EXPECT_EQ(halved.split_steps, 1);
  const Outcome two_steps = release(1.5e-3, 2, 0);
  EXPECT_LT((halved.q - two_steps.q).lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_LT((halved.v - two_steps.v).lpNorm<Eigen::Infinity>(), 1e-9);
  // Against a step-converged reference (3000 steps of 1 µs; 1500 steps of 2 µs agree with it
  // within 3.1e-7 rad) the halved step is as accurate as its pieces: 0.063 rad off after the
  // joints moved by up to 0.89 rad, within a tenth of the motion (the error of two steps of
  // 1.5 ms). It keeps the run going; accuracy needs a smaller step.
  const Outcome reference = release(1e-6, 3000, 0);
  EXPECT_LT((reference.q - release(2e-6, 1500, 0).q).lpNorm<Eigen::Infinity>(), 1e-6);
  const double motion = (reference.q - Eigen::VectorXd::Constant(4, 0.5)).lpNorm<Eigen::Infinity>();
  EXPECT_LT((halved.q - reference.q).lpNorm<Eigen::Infinity>(), 0.1 * motion);
}

TEST(StepHalving, AStepThatConvergesWholeIsNotTouched) {
  // 1.5 ms steps converge whole: the same to the bit with and without halving.
  const Outcome with = release(1.5e-3, 4, 6), without = release(1.5e-3, 4, 0);
  EXPECT_EQ(with.split_steps, 0);
  EXPECT_EQ(with.q, without.q);
  EXPECT_EQ(with.v, without.v);
}

// A light uniform chain (a film's: 1e-6 kg/m, EI = 1e-4 N m², GJ = 5e-5 N m², 40 mm in
// `n` bodies, rigid root) under a tip force applied at once, in steps of h = 0.25 s, ρ∞ = 0:
// Φ̈₀ ≈ 1e8 rad/s², modes near 3.5 kHz and up (ω h > 5000).
struct SuddenLoadOutcome {
  std::vector<Eigen::VectorXd> q;  // after each step
  long restarted_steps = 0;
  Eigen::VectorXd static_bend;  // small-rotation statics: θ_k = P (n − k) a / k_θ
};

SuddenLoadOutcome light_chain_under_a_sudden_load(int n, double force, int steps) {
  const double a = 0.04 / n, mass = 1e-6 * a, ei = 1e-4, gj = 5e-5;
  ChainModel model;
  model.root = RootAttachment::rigid;
  for (int i = 0; i < n; ++i) {
    ChainBody b;
    b.length = a;
    b.mass = mass;
    b.center_of_mass = Eigen::Vector3d(0.0, 0.5 * a, 0.0);
    const double ix = mass * a * a / 12.0, iy = 1e-3 * ix;
    b.inertia = Eigen::Vector3d(ix, iy, ix + iy).asDiagonal();
    b.outboard_joint = Eigen::Vector3d(0.0, a, 0.0);
    model.bodies.push_back(b);
    ChainJoint j;
    j.bend_stiffness = ei / a;
    j.twist_stiffness = gj / a;
    model.joints.push_back(j);
  }
  Loads loads(n);
  loads.add_force(n - 1, Eigen::Vector3d(0.0, a, 0.0), Eigen::Vector3d(0.0, 0.0, force), LoadFrame::ground);
  const BaseMotion base = fixed_base();
  ChainData data(model);
  GeneralizedAlphaSettings settings;
  settings.rho_infinity = 0.0;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.num_dofs());
  ChainState state = make_initial_state(model, data, base, 0.0, zero, zero, loads), next;
  SuddenLoadOutcome out;
  for (int k = 0; k < steps; ++k) {
    advance(model, data, base, settings, state, 0.25, loads, next);
    state = next;
    out.q.push_back(state.q);
  }
  out.restarted_steps = data.step.restarted_steps;
  out.static_bend.resize(n - 1);
  for (int k = 1; k < n; ++k) out.static_bend(k - 1) = force * (n - k) * a / (ei / a);
  return out;
}

TEST(StepHalving, ALoadAppliedAtOnceOnALightChainRestartsTheScheme) {
  // Before: "quasi-Newton solve did not converge … split into pieces down to 1/64 of the step,
  // still: …" at step 1 (generalized-α carries a₀ = Φ̈₀ into every piece: Φ̇₁ ≈ 2e7 rad/s).
  // Now the first step is restarted as backward Euler and lands on the static answer, which
  // the generalized-α steps after it keep (ρ∞ = 0 annihilates what the step does not resolve).
  for (const int n : {10, 20}) {
    const SuddenLoadOutcome out = light_chain_under_a_sudden_load(n, 1e-3, 4);
    EXPECT_EQ(out.restarted_steps, 1) << n << " bodies";
    for (std::size_t step = 0; step < out.q.size(); ++step) {
      for (int k = 0; k + 1 < n; ++k) {
        // Bend: the linear statics to 1e-4 (the largest bend is 1.5e-3 rad: the nonlinear
        // correction is of order 1e-6; the unresolved modes' residue (ω h)⁻² ≈ 4e-8).
        EXPECT_NEAR(std::abs(out.q[step](2 * k)), out.static_bend(k), 1e-4 * out.static_bend(k))
            << n << " bodies, step " << step + 1 << ", joint " << k + 2;
        EXPECT_NEAR(out.q[step](2 * k + 1), 0.0, 1e-12) << "twist, joint " << k + 2;  // load on the axis
      }
    }
  }
}

}  // namespace
}  // namespace flapsim::mbd::test
