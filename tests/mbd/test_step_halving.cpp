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

}  // namespace
}  // namespace flapsim::mbd::test
