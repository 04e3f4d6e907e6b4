#pragma once
/// \file generalized_alpha.hpp
/// \brief Implicit time integration of the chain: generalized-α (Chung & Hulbert
/// 1993, in the form of Arnold & Brüls 2007 for M(Φ)Φ̈ + H = Q) with a quasi-Newton
/// (Broyden) solve per step, as the papers solve their equations.
///
/// Per step h, with the algorithmic acceleration a:
///   M(Φ_{n+1}) Φ̈_{n+1} + H(Φ_{n+1}, Φ̇_{n+1}, t_{n+1}) = Q_{n+1}
///   (1 − α_m) a_{n+1} + α_m a_n = (1 − α_f) Φ̈_{n+1} + α_f Φ̈_n
///   Φ_{n+1} = Φ_n + h Φ̇_n + h² (½ − β) a_n + h² β a_{n+1}
///   Φ̇_{n+1} = Φ̇_n + h (1 − γ) a_n + h γ a_{n+1}
/// α_m = (2ρ∞ − 1)/(ρ∞ + 1), α_f = ρ∞/(ρ∞ + 1), γ = ½ + α_f − α_m, β = ¼(γ + ½)²:
/// second order, unconditionally stable for linear problems, high-frequency spectral
/// radius ρ∞. ρ∞ = 1: no numerical dissipation (with a₀ = Φ̈₀ it is the trapezoidal
/// rule, which conserves the energy of a linear undamped system exactly); ρ∞ < 1 damps
/// the modes the step cannot resolve (ρ∞ = 0.9 loses about 1 % of their amplitude per
/// step once ωh ≫ 1) and leaves the resolved ones almost untouched.
///
/// The unknown Φ̈_{n+1} is found by Broyden's method ("good" update of the Jacobian)
/// starting from a finite-difference Jacobian kept from step to step; when an iteration
/// fails to halve the residual the Jacobian is rebuilt by finite differences.
///
/// Step halving: a step whose solve does not converge (or turns NaN/Inf) is solved again
/// as two steps of h/2 from the same state with the same loads, each of them halved again
/// if it fails, down to h / 2^max_step_halvings; only then ConvergenceFailure is thrown.
/// A step that converges whole is solved exactly as without halving (the pieces are a
/// retry, never a first try), so runs that never fail are unchanged to the bit. The pieces
/// are generalized-α steps of their own size (the scheme's variable-step form: the
/// algorithmic acceleration carries over), with the base motion at their own times.
/// ChainData::step.last_substeps says how many pieces the last step took.
///
/// Re-entrant: advance() reads `current` and writes `next` (they may be the same object);
/// it never changes `current`, so a coupling can redo a step with updated loads. The
/// quasi-Newton Jacobian in ChainData is only a starting guess and does not change the
/// converged answer beyond the tolerance.

#include "mbd/base_motion.hpp"
#include "mbd/chain_data.hpp"
#include "mbd/chain_loads.hpp"
#include "mbd/chain_model.hpp"

#include <Eigen/Core>

namespace flapsim::mbd {

struct GeneralizedAlphaSettings {
  double rho_infinity = 0.9;  ///< spectral radius at ωh → ∞, in [0, 1]
  /// Converged when ‖residual‖∞ ≤ tolerance · (‖MΦ̈‖∞ + ‖H‖∞ + ‖Q‖∞) + a round-off floor
  /// (relative force balance).
  double tolerance = 1e-10;
  int max_iterations = 50;          ///< quasi-Newton iterations per step
  int max_jacobian_refreshes = 4;   ///< finite-difference rebuilds per step
  /// A failing step is retried in halves down to h / 2^max_step_halvings (0: no retry).
  int max_step_halvings = 6;
};

/// The four coefficients of the scheme for a given ρ∞.
struct GeneralizedAlphaCoefficients {
  double alpha_m, alpha_f, beta, gamma;
  /// \throws std::invalid_argument if ρ∞ is outside [0, 1]
  static GeneralizedAlphaCoefficients from_rho_infinity(double rho_infinity);
};

/// State of the chain at a time step.
struct ChainState {
  double time = 0.0;     ///< [s]
  long step = 0;         ///< steps taken since the initial state
  Eigen::VectorXd q;     ///< Φ [rad]
  Eigen::VectorXd v;     ///< Φ̇ [rad/s]
  Eigen::VectorXd qdd;   ///< Φ̈ [rad/s²] (satisfies the equations of motion)
  Eigen::VectorXd a;     ///< algorithmic acceleration of generalized-α [rad/s²]
};

/// Initial state: Φ̈₀ from the equations of motion, a₀ = Φ̈₀.
/// \param t0     initial time [s]
/// \param q0     Φ(t0) [rad]
/// \param v0     Φ̇(t0) [rad/s]
/// \param loads  loads at t0
ChainState make_initial_state(const ChainModel& model, ChainData& data, const BaseMotion& base,
                              double t0, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                              const Loads& loads);

/// One implicit step from `current` to `next` (time current.time + dt).
/// \param loads  the external loads at the end of the step (fixed during the solve;
///               their moment arms follow the end-of-step pose)
/// On return data holds the kinematics of `next` (poses, velocities, full accelerations),
/// so points fixed in bodies can be read with point_position / point_velocity.
/// \throws ConvergenceFailure naming step index (current.step) and time (current.time + dt),
///         when the step does not converge even in 2^max_step_halvings pieces
void advance(const ChainModel& model, ChainData& data, const BaseMotion& base,
             const GeneralizedAlphaSettings& settings, const ChainState& current, double dt,
             const Loads& loads, ChainState& next);

}  // namespace flapsim::mbd
