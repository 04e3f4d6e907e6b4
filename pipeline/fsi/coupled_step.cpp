#include "pipeline/fsi/coupled_step.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "mbd/chain_kinematics.hpp"
#include "mbd/convergence_failure.hpp"
#include "pipeline/fsi/load_transfer.hpp"
#include "pipeline/fsi/numerical_failure.hpp"

namespace flapsim::fsi {

FsiData::FsiData(const FsiModel& model)
    : chain(model.chain),
      loads(model.chain.num_bodies()),
      aitken(model.coupling.first_relaxation),
      quasi_newton(model.chain.num_dofs()) {
  if (model.air) {
    lattice.emplace(model.lattice);
    nodes.setZero(3, model.lattice.nodes());
    node_velocities.setZero(3, model.lattice.nodes());
  }
  residual.setZero(model.chain.num_dofs());
}

namespace {

// A number of a message in 3 significant digits ("1e-06", "2.35e-07"): std::to_string's six
// decimals printed a change of 2e-7 rad and a tolerance of 1e-9 alike as 0.000000.
std::string significant(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g", v);
  return text;
}

void external_loads(const FsiModel& model, double t, mbd::Loads& loads) {
  loads.clear();
  if (model.external_loads) model.external_loads(t, loads);
}

// Relaxed state: s̃ += ω (ŝ − s̃) for Φ, Φ̇, Φ̈ and the algorithmic acceleration.
void relax(mbd::ChainState& relaxed, const mbd::ChainState& trial, double omega) {
  relaxed.q += omega * (trial.q - relaxed.q);
  relaxed.v += omega * (trial.v - relaxed.v);
  relaxed.qdd += omega * (trial.qdd - relaxed.qdd);
  relaxed.a += omega * (trial.a - relaxed.a);
  relaxed.time = trial.time;
  relaxed.step = trial.step;
}

// The lattice solved on the chain's current kinematics at time t (loads in data.lattice).
void solve_air(const FsiModel& model, FsiData& data, double dt, long step, double t) {
  deformed_nodes(model.attachment, data.chain, data.nodes, data.node_velocities);
  if (!data.nodes.allFinite() || !data.node_velocities.allFinite())
    throw NumericalFailure("deformed wing surface is not finite", step, t);
  uvlm::VortexLatticeData& lat = *data.lattice;
  uvlm::solve(model.lattice, lat, data.nodes, data.node_velocities, model.free_stream, dt,
              model.density);
  if (!lat.loads.force.allFinite() || !lat.gamma.allFinite())
    throw NumericalFailure("aerodynamic loads are not finite", step, t);
}

// data.loads = external loads at t + the lattice's panel loads (at the current pose).
void assemble_loads(const FsiModel& model, FsiData& data, double t) {
  external_loads(model, t, data.loads);
  if (model.air)
    add_panel_loads(model.attachment, data.chain, data.lattice->loads, data.loads);
}

void chain_step(const FsiModel& model, FsiData& data, double dt) {
  mbd::advance(model.chain, data.chain, model.base, model.integrator, data.state, dt, data.loads,
               data.trial);
}

// (Φ, Φ̇, Φ̈, a) as one vector, and back (time and step stay those of `to`).
void stack(const mbd::ChainState& s, Eigen::VectorXd& x) {
  const Eigen::Index n = s.q.size();
  x.resize(4 * n);
  x << s.q, s.v, s.qdd, s.a;
}
void unstack(const Eigen::VectorXd& x, mbd::ChainState& to) {
  const Eigen::Index n = to.q.size();
  to.q = x.segment(0, n);
  to.v = x.segment(n, n);
  to.qdd = x.segment(2 * n, n);
  to.a = x.segment(3 * n, n);
}

double change(const FsiModel& model, const mbd::ChainState& a, const mbd::ChainState& b) {
  const double rate_scale = 2.0 * std::numbers::pi * model.frequency;  // [rad/s] per flapping radian
  const double dq = (a.q - b.q).lpNorm<Eigen::Infinity>();
  const double dv = (a.v - b.v).lpNorm<Eigen::Infinity>() / rate_scale;
  return std::max(dq, dv);
}

// Sub-iterations from data.relaxed (steps 1–3 of the file comment) until the structure stops
// changing or k reaches k + limit; k counts the step's lattice solves, delta the last change.
bool sub_iterate(const FsiModel& model, FsiData& data, double dt, long step, double t1,
                 CouplingMethod method, int limit, int& k, double& delta) {
  const int last = k + limit;
  bool first = k == 0;
  while (k < last) {
    // 1. lattice on the relaxed iterate
    if (!first)
      mbd::forward_kinematics(model.chain, data.chain, model.base(t1), data.relaxed.q, data.relaxed.v);
    // (first of the step: data.chain already holds the kinematics of the predictor = relaxed)
    first = false;
    solve_air(model, data, dt, step, t1);
    ++k;
    // 2. chain step with these loads
    assemble_loads(model, data, t1);
    chain_step(model, data, dt);
    // 3. converged?
    delta = change(model, data.trial, data.relaxed);
    if (!std::isfinite(delta)) throw NumericalFailure("coupling produced a non-finite chain state", step, t1);
    if (delta <= model.coupling.tolerance) return true;
    data.residual = data.trial.qdd - data.relaxed.qdd;
    bool updated = false;
    if (method == CouplingMethod::InterfaceQuasiNewton) {
      stack(data.trial, data.stacked_trial);
      updated = data.quasi_newton.next(data.residual, data.stacked_trial, data.stacked_next);
      if (updated) {
        unstack(data.stacked_next, data.relaxed);
        data.relaxed.time = data.trial.time;
        data.relaxed.step = data.trial.step;
      }
    }
    if (!updated) relax(data.relaxed, data.trial, data.aitken.next(data.residual));
  }
  return false;
}

}  // namespace

void initialize(const FsiModel& model, FsiData& data, double t0) {
  const int n = model.chain.num_dofs();
  const Eigen::VectorXd q0 = model.initial_q.size() == n ? model.initial_q : model.chain.rest_angles();
  const Eigen::VectorXd v0 = model.initial_v.size() == n ? model.initial_v : Eigen::VectorXd::Zero(n);
  external_loads(model, t0, data.loads);
  try {
    data.state = mbd::make_initial_state(model.chain, data.chain, model.base, t0, q0, v0, data.loads);
  } catch (const mbd::ConvergenceFailure& e) {
    throw NumericalFailure("the initial state (t = " + std::to_string(t0) + " s): multibody: " + e.reason());
  }
  data.trial = data.state;
  data.relaxed = data.state;
  data.step = 0;
  data.last_iterations = 0;
  data.total_iterations = 0;
  data.last_change = 0.0;
}

void coupled_step(const FsiModel& model, FsiData& data, double dt) {
  const double t1 = data.state.time + dt;
  const long step = data.step;
  try {
    if (model.chain.num_dofs() == 0) {
      // Rigid wing: the pose is prescribed; one lattice solve, nothing to iterate.
      const Eigen::VectorXd none;
      mbd::forward_kinematics(model.chain, data.chain, model.base(t1), none, none);
      data.state.time = t1;
      data.state.step = step + 1;
      data.last_iterations = 0;
      if (model.air) {
        solve_air(model, data, dt, step, t1);
        data.last_iterations = 1;
      }
      // The loads on the wing at t1 (prescribed and aerodynamic): they move nothing, but the
      // drive moment and power the base supplies include them (ω·M + v·F at the pivot).
      assemble_loads(model, data, t1);
      data.last_change = 0.0;
    } else if (!model.air) {
      external_loads(model, t1, data.loads);
      chain_step(model, data, dt);
      data.state = data.trial;
      data.last_iterations = 0;
      data.last_change = 0.0;
    } else {
      // 0. predictor: the previous step's aerodynamic loads (their points ride on the bodies).
      external_loads(model, t1, data.loads);
      // The previous aerodynamic loads were attached at the previous pose; re-attach
      // them at the accepted pose of the last step (data.chain holds it).
      if (step > 0) add_panel_loads(model.attachment, data.chain, data.lattice->loads, data.loads);
      chain_step(model, data, dt);
      data.relaxed = data.trial;
      data.aitken.start_step();
      data.quasi_newton.start_step();
      int k = 0;
      double delta = 0.0;
      const bool converged = sub_iterate(model, data, dt, step, t1, model.coupling.method,
                                         model.coupling.max_iterations, k, delta);
      data.last_iterations = k;
      data.last_change = delta;
      if (!converged)
        throw NumericalFailure("strong coupling did not converge in " + std::to_string(k) +
                                   " sub-iterations (structure change " + significant(delta) +
                                   " rad, tolerance " + significant(model.coupling.tolerance) + ")" +
                                   (model.coupling.method == CouplingMethod::Aitken
                                        ? std::string("; a light wing may converge with numerics.coupling = "
                                                      "\"iqn_ils\" (docs/fsi.md, \"Coupling\")")
                                        : std::string()),
                               step, t1);
      // 4. accept the chain's answer; data.chain holds its kinematics (mbd::advance).
      data.state = data.trial;
    }
  } catch (const mbd::ConvergenceFailure& e) {
    throw NumericalFailure("multibody: " + e.reason(), step, t1);
  } catch (const std::length_error& e) {
    throw NumericalFailure(e.what(), step, t1);
  }
  data.step = step + 1;
  data.total_iterations += data.last_iterations;
}

void shed_wake(const FsiModel& model, FsiData& data) {
  if (!model.air) return;
  try {
    uvlm::advance(model.lattice, *data.lattice);
  } catch (const std::length_error& e) {
    throw NumericalFailure(e.what(), data.step - 1, data.state.time);
  }
}

}  // namespace flapsim::fsi
