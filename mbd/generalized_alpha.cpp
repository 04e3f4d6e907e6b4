#include "mbd/generalized_alpha.hpp"

#include "mbd/chain_dynamics.hpp"
#include "mbd/chain_kinematics.hpp"
#include "mbd/convergence_failure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace flapsim::mbd {

GeneralizedAlphaCoefficients GeneralizedAlphaCoefficients::from_rho_infinity(double rho) {
  if (!(rho >= 0.0 && rho <= 1.0))
    throw std::invalid_argument("generalized-alpha: rho_infinity must be in [0, 1], got " +
                                std::to_string(rho));
  GeneralizedAlphaCoefficients c;
  c.alpha_m = (2.0 * rho - 1.0) / (rho + 1.0);
  c.alpha_f = rho / (rho + 1.0);
  c.gamma = 0.5 + c.alpha_f - c.alpha_m;
  c.beta = 0.25 * (c.gamma + 0.5) * (c.gamma + 0.5);
  return c;
}

ChainState make_initial_state(const ChainModel& model, ChainData& data, const BaseMotion& base,
                              double t0, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                              const Loads& loads) {
  const int n = model.num_dofs();
  if (q0.size() != n || v0.size() != n)
    throw std::invalid_argument("initial state: Φ and Φ̇ must have " + std::to_string(n) +
                                " entries");
  ChainState s;
  s.time = t0;
  s.step = 0;
  s.q = q0;
  s.v = v0;
  s.qdd.resize(n);
  forward_dynamics(model, data, base(t0), q0, v0, loads, s.qdd);
  if (!s.qdd.allFinite()) throw ConvergenceFailure("initial accelerations are not finite", 0, t0);
  s.a = s.qdd;
  return s;
}

namespace {

std::string scientific(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", x);
  return buf;
}

// Everything one residual evaluation needs; references into the caller's objects.
struct StepProblem {
  const ChainModel& model;
  ChainData& data;
  const BasePose& pose;
  const ChainState& cur;
  const Loads& loads;
  GeneralizedAlphaCoefficients c;
  double h;
  double roundoff = 0.0;  // round-off floor of the last residual [N m]
  // The load damping acts in this solve: it is active and the solve is the whole step
  // (chain_data.hpp LoadDamping).
  bool damping = data.load_damping.active && cur.time == data.load_damping.step_start &&
                 std::abs(cur.time + h - data.load_damping.step_end) <= 1e-9 * std::max(h, 1e-300);

  // Φ, Φ̇, a at the end of the step for a trial Φ̈_{n+1} = x, into ws.q, ws.v, ws.a.
  void predict(const Eigen::VectorXd& x) {
    StepWorkspace& ws = data.step;
    ws.a = ((1.0 - c.alpha_f) * x + c.alpha_f * cur.qdd - c.alpha_m * cur.a) / (1.0 - c.alpha_m);
    ws.q = cur.q + h * cur.v + (h * h * (0.5 - c.beta)) * cur.a + (h * h * c.beta) * ws.a;
    ws.v = cur.v + (h * (1.0 - c.gamma)) * cur.a + (h * c.gamma) * ws.a;
  }

  // r = M x + H − Q at the predicted state; returns the force scale.
  double residual(const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    predict(x);
    StepWorkspace& ws = data.step;
    compute_all_terms(model, data, pose, ws.q, ws.v, loads);
    if (damping) {  // Q −= D (Φ̇ − Φ̇_ref) (chain_data.hpp LoadDamping)
      ws.scratch = ws.v - data.load_damping.reference;
      data.generalized_load.noalias() -= data.load_damping.matrix * ws.scratch;
    }
    ws.scratch.noalias() = data.mass_matrix * x;
    r = ws.scratch + data.inertial_bias + data.spring_force - data.generalized_load;
    // Force scale: the size of the terms that make up r, so that the tolerance is
    // relative; plus a round-off floor: |K| |Φ| (not |K| |Φ − Φ_rest|) bounds the round-off
    // of the spring term, which matters for tiny motions about a bent rest shape.
    const double terms = ws.scratch.lpNorm<Eigen::Infinity>() +
                         data.inertial_bias.lpNorm<Eigen::Infinity>() +
                         data.spring_force.lpNorm<Eigen::Infinity>() +
                         data.generalized_load.lpNorm<Eigen::Infinity>();
    ws.scratch = ws.q.cwiseAbs() + data.rest.cwiseAbs();
    ws.scratch2.noalias() = data.stiffness_abs * ws.scratch;
    roundoff = 1e3 * std::numeric_limits<double>::epsilon() * (terms + ws.scratch2.lpNorm<Eigen::Infinity>());
    return terms;
  }

  // ∂Φ̇_{n+1}/∂Φ̈_{n+1} (predict) [s].
  double velocity_factor() const { return h * c.gamma * (1.0 - c.alpha_f) / (1.0 - c.alpha_m); }

  // The kept Jacobian corrected for a change of the load damping since it was made:
  // ∂r/∂Φ̈ gains (D_now − D_then) ∂Φ̇/∂Φ̈.
  void update_load_damping() {
    StepWorkspace& ws = data.step;
    const LoadDamping& d = data.load_damping;
    if (!damping && ws.jacobian_damping.isZero(0.0)) return;
    if (damping && ws.jacobian_damping == d.matrix) return;
    if (damping) {
      ws.jacobian += velocity_factor() * (d.matrix - ws.jacobian_damping);
      ws.jacobian_damping = d.matrix;
    } else {
      ws.jacobian -= velocity_factor() * ws.jacobian_damping;
      ws.jacobian_damping.setZero();
    }
    ws.lu.compute(ws.jacobian);
  }

  // Finite-difference Jacobian at x (r = residual at x), factorised.
  void rebuild_jacobian(Eigen::VectorXd& x, const Eigen::VectorXd& r) {
    StepWorkspace& ws = data.step;
    const double delta = 1e-7 * std::max(x.lpNorm<Eigen::Infinity>(), 1.0);
    for (int j = 0; j < x.size(); ++j) {
      const double keep = x(j);
      x(j) = keep + delta;
      residual(x, ws.r_new);
      ws.jacobian.col(j) = (ws.r_new - r) / delta;
      x(j) = keep;
    }
    residual(x, ws.r_new);  // leave data at x again
    if (damping)
      ws.jacobian_damping = data.load_damping.matrix;
    else
      ws.jacobian_damping.setZero();
    ws.lu.compute(ws.jacobian);
    ws.jacobian_valid = true;
    ws.jacobian_dt = h;
    ++ws.last_refreshes;
    ++ws.total_refreshes;
  }
};

// The coefficients that make the scheme backward Euler when the start's a and Φ̈ are zero:
// Φ_{n+1} = Φ_n + h Φ̇_{n+1}, Φ̇_{n+1} = Φ̇_n + h Φ̈_{n+1}, a_{n+1} = Φ̈_{n+1}.
constexpr GeneralizedAlphaCoefficients kBackwardEuler{0.0, 0.0, 1.0, 1.0};

// One step of size dt from `current`, solved whole: generalized-α, or with `restart` one
// backward-Euler step from `current`'s Φ and Φ̇ alone (its a and Φ̈ not used, Newton started
// from Φ̈ = 0), which leaves a_{n+1} = Φ̈_{n+1}: the scheme started again from there.
void solve_step(const ChainModel& model, ChainData& data, const BaseMotion& base,
                const GeneralizedAlphaSettings& settings, const ChainState& given, double dt,
                const Loads& loads, ChainState& next, bool restart = false) {
  ChainState restarted;
  if (restart) {
    restarted = given;
    restarted.a.setZero();
    restarted.qdd.setZero();
  }
  const ChainState& current = restart ? restarted : given;
  const double t1 = current.time + dt;
  const BasePose pose = base(t1);
  StepProblem p{
      model,
      data,
      pose,
      current,
      loads,
      restart ? kBackwardEuler : GeneralizedAlphaCoefficients::from_rho_infinity(settings.rho_infinity),
      dt};
  StepWorkspace& ws = data.step;
  ws.last_iterations = 0;
  ws.last_refreshes = 0;

  ws.x = current.qdd;  // initial guess: the last acceleration
  double scale = p.residual(ws.x, ws.r);
  double rnorm = ws.r.lpNorm<Eigen::Infinity>();
  if (!std::isfinite(rnorm))
    throw ConvergenceFailure("residual is not finite at the first iterate", current.step, t1);
  // The Jacobian's h-dependent part changes with dt and with the scheme's coefficients:
  // rebuild when the step size changed or the kept one belongs to the other scheme.
  if (restart || ws.jacobian_restart) ws.jacobian_valid = false;
  ws.jacobian_restart = restart;
  if (!ws.jacobian_valid || std::abs(ws.jacobian_dt - dt) > 1e-12 * dt)
    p.rebuild_jacobian(ws.x, ws.r);
  else
    p.update_load_damping();

  bool converged = rnorm <= settings.tolerance * scale + p.roundoff;
  while (!converged) {
    if (ws.last_iterations >= settings.max_iterations)
      throw ConvergenceFailure("quasi-Newton solve did not converge in " +
                                   std::to_string(settings.max_iterations) +
                                   " iterations (residual " + scientific(rnorm) +
                                   " N m, force scale " + scientific(scale) + " N m)",
                               current.step, t1);
    ++ws.last_iterations;
    ws.dx = ws.lu.solve(ws.r);
    ws.dx = -ws.dx;
    ws.x += ws.dx;
    scale = p.residual(ws.x, ws.r_new);
    const double new_norm = ws.r_new.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(new_norm) || !ws.x.allFinite())
      throw ConvergenceFailure("state became NaN/Inf in the quasi-Newton solve", current.step, t1);
    converged = new_norm <= settings.tolerance * scale + p.roundoff;
    if (converged) {
      ws.r = ws.r_new;
      rnorm = new_norm;
      break;
    }
    if (new_norm > 0.5 * rnorm && ws.last_refreshes < settings.max_jacobian_refreshes) {
      // Broyden stalls: start again from a fresh finite-difference Jacobian here.
      ws.r = ws.r_new;
      p.rebuild_jacobian(ws.x, ws.r);
    } else {
      // Good Broyden update: J += (Δr − J Δx) Δxᵀ / (Δxᵀ Δx).
      ws.dr = ws.r_new - ws.r;
      ws.jdx.noalias() = ws.jacobian * ws.dx;
      const double dxx = ws.dx.squaredNorm();
      if (dxx > 0.0) {
        ws.jacobian.noalias() += ((ws.dr - ws.jdx) / dxx) * ws.dx.transpose();
        ws.lu.compute(ws.jacobian);
      }
      ws.r = ws.r_new;
    }
    rnorm = new_norm;
  }
  // data and the workspace hold the last residual evaluation = the converged iterate.
  update_accelerations(model, data, ws.x);
  next.time = t1;
  next.step = current.step + 1;
  next.q = ws.q;
  next.v = ws.v;
  next.a = ws.a;
  next.qdd = ws.x;
}

// The step from `current` over dt in 2^level pieces or more: solved whole if it converges,
// else as two halves, each split again if it fails, down to level max_step_halvings.
// With `restart` each piece is a backward-Euler step (solve_step). Returns the number of
// pieces used.
int solve_in_pieces(const ChainModel& model, ChainData& data, const BaseMotion& base,
                    const GeneralizedAlphaSettings& settings, const ChainState& current, double dt,
                    const Loads& loads, ChainState& next, int level, bool restart = false) {
  try {
    solve_step(model, data, base, settings, current, dt, loads, next, restart);
    return 1;
  } catch (const ConvergenceFailure&) {
    if (level >= settings.max_step_halvings) throw;
  }
  ChainState middle;
  int pieces =
      solve_in_pieces(model, data, base, settings, current, 0.5 * dt, loads, middle, level + 1, restart);
  middle.step = current.step;  // the pieces belong to the step being solved
  pieces += solve_in_pieces(model, data, base, settings, middle, 0.5 * dt, loads, next, level + 1, restart);
  return pieces;
}

// One step of dt from `current`: solved whole, else in halves (solve_in_pieces); returns the
// number of pieces. A failure names current.step and the step's end time.
int solve_with_halving(const ChainModel& model, ChainData& data, const BaseMotion& base,
                       const GeneralizedAlphaSettings& settings, const ChainState& current, double dt,
                       const Loads& loads, ChainState& next) {
  const double t1 = current.time + dt;
  try {
    solve_step(model, data, base, settings, current, dt, loads, next);
    return 1;
  } catch (const ConvergenceFailure& whole) {
    if (settings.max_step_halvings <= 0) throw;
    int pieces = 0;
    try {
      pieces = solve_in_pieces(model, data, base, settings, current, 0.5 * dt, loads, next, 1);
      ChainState first_half = next;
      first_half.step = current.step;
      pieces += solve_in_pieces(model, data, base, settings, first_half, 0.5 * dt, loads, next, 1);
    } catch (const ConvergenceFailure& split) {
      // The scheme's history can be what fails: its algorithmic acceleration carries a
      // start's (or a jump's) acceleration into every piece, e.g. a light chain under a load
      // applied at once, Φ̈₀ = 3.5e8 rad/s², whose first step of 0.25 s got Φ̇₁ = 2.2e7 rad/s
      // from a₀ alone. Last: the step restarted without it, as backward Euler (first order,
      // damps every mode the step does not resolve), in halves if need be.
      try {
        pieces = solve_in_pieces(model, data, base, settings, current, dt, loads, next, 0, true);
        ++data.step.restarted_steps;
      } catch (const ConvergenceFailure& restarted) {
        throw ConvergenceFailure(whole.reason() + "; split into pieces down to 1/" +
                                     std::to_string(1 << settings.max_step_halvings) +
                                     " of the step, still: " + split.reason() +
                                     "; restarted as backward Euler, still: " + restarted.reason(),
                                 current.step, t1);
      }
    }
    next.time = t1;
    next.step = current.step + 1;
    return pieces;
  }
}

}  // namespace

void advance(const ChainModel& model, ChainData& data, const BaseMotion& base,
             const GeneralizedAlphaSettings& settings, const ChainState& current, double dt,
             const Loads& loads, ChainState& next) {
  const double t1 = current.time + dt;
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw ConvergenceFailure("time step must be positive and finite", current.step, t1);
  if (settings.substeps < 1)
    throw std::invalid_argument("generalized-alpha: substeps must be at least 1, got " +
                                std::to_string(settings.substeps));
  StepWorkspace& ws = data.step;
  data.load_damping.step_start = current.time;
  data.load_damping.step_end = t1;
  int pieces = 0;
  if (settings.substeps == 1) {
    pieces = solve_with_halving(model, data, base, settings, current, dt, loads, next);
  } else {
    // Sub-steps: equal steps of dt / substeps with the same loads, the base at their own times.
    const double h = dt / settings.substeps;
    ChainState start = current;
    for (int i = 0; i < settings.substeps; ++i) {
      pieces += solve_with_halving(model, data, base, settings, start, h, loads, next);
      start = next;
      start.step = current.step;  // the sub-steps belong to the step being solved
    }
    next.time = t1;
    next.step = current.step + 1;
  }
  ws.last_substeps = pieces;
  if (pieces > settings.substeps) {
    ++ws.split_steps;
    ws.max_substeps = std::max(ws.max_substeps, pieces);
  }
}

}  // namespace flapsim::mbd
