#pragma once
/// \file coupled_step.hpp
/// \brief One time step of the two-way coupled wing: bar chain (mbd) and vortex
/// lattice (uvlm), strongly coupled by sub-iterations with Aitken relaxation
/// (docs/fsi.md). A constant FsiModel and a mutable FsiData, as in mbd and uvlm.
///
/// Step t_n → t_{n+1} = t_n + dt:
///  0. predictor: the chain step with the previous step's aerodynamic loads → s̃⁰;
///  1. the lattice nodes ride on the bodies of s̃ᵏ (position and velocity), the lattice
///     is solved at t_{n+1} (wake unchanged), its panel forces go to the host bodies;
///  2. the chain step is redone from the same s_n with these loads → ŝᵏ⁺¹
///     (mbd::advance is re-entrant);
///  3. converged when the structure stops changing:
///        max(‖Φ̂ − Φ̃‖∞, ‖Φ̂̇ − Φ̃̇‖∞ / (2π f)) ≤ tolerance   [rad]
///     (angles in radians, rates in radians per flapping radian); else
///     s̃ᵏ⁺¹ = s̃ᵏ + ωₖ (ŝᵏ⁺¹ − s̃ᵏ) with Aitken's ωₖ on Φ̈ (Φ, Φ̇ and the algorithmic
///     acceleration are affine in Φ̈ within a step, so relaxing all of them with one ω
///     keeps the state a consistent generalized-α state) and back to 1; with
///     CouplingMethod::InterfaceQuasiNewton, from the second sub-iteration on, s̃ᵏ⁺¹ is
///     the IQN-ILS combination of the step's answers ŝ (interface_quasi_newton.hpp);
///  4. accept ŝ (the chain's exact answer to the last loads); then (shed_wake, after
///     the caller has written its outputs of the step) convect and shed the wake.
/// The number of lattice solves of the step is its coupling iteration count.
///
/// A rigid wing is a chain without degrees of freedom (one body welded to the base):
/// the same attachment and load transfer, one lattice solve per step, nothing to
/// iterate. A vacuum run (no air) steps the chain with the external loads only.

#include <Eigen/Core>

#include <functional>
#include <optional>

#include "mbd/base_motion.hpp"
#include "mbd/chain_data.hpp"
#include "mbd/chain_loads.hpp"
#include "mbd/chain_model.hpp"
#include "mbd/generalized_alpha.hpp"
#include "pipeline/fsi/aitken_relaxation.hpp"
#include "pipeline/fsi/interface_quasi_newton.hpp"
#include "pipeline/fsi/wing_attachment.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::fsi {

/// How the sub-iterations of a step update the chain state (docs/fsi.md, "Coupling").
enum class CouplingMethod {
  Aitken,                ///< one Aitken factor for the whole state (aitken_relaxation.hpp)
  InterfaceQuasiNewton,  ///< IQN-ILS on Φ̈ (interface_quasi_newton.hpp); Aitken's factor for the
                         ///< first update of a step (no secant pair yet)
};

struct CouplingSettings {
  CouplingMethod method = CouplingMethod::Aitken;
  int max_iterations = 50;      ///< lattice solves per step before giving up
  double tolerance = 1e-6;      ///< see the file comment [rad]
  double first_relaxation = 0.5;  ///< ω of the very first sub-iteration
};

/// External (non-aerodynamic) loads at time t [s], added to `loads` (e.g. a case's
/// prescribed point loads). Empty: none.
using ExternalLoads = std::function<void(double t, mbd::Loads& loads)>;

struct FsiModel {
  mbd::ChainModel chain;                 ///< the structure (no dofs: a rigid wing)
  mbd::BaseMotion base;                  ///< prescribed wing-base motion
  mbd::GeneralizedAlphaSettings integrator;
  /// Φ(t₀), Φ̇(t₀) [rad, rad/s]; empty: the chain's rest angles, at rest.
  Eigen::VectorXd initial_q, initial_v;
  double frequency = 1.0;                ///< flapping frequency f [Hz] (rate scale of the test)
  CouplingSettings coupling;
  ExternalLoads external_loads;

  bool air = true;                       ///< false: vacuum, no lattice
  uvlm::VortexLatticeModel lattice;      ///< used if air
  WingAttachment attachment;             ///< lattice nodes on the chain (if air)
  double density = 1.225;                ///< ρ [kg/m³]
  Eigen::Vector3d free_stream = Eigen::Vector3d::Zero();  ///< [m/s]
};

struct FsiData {
  explicit FsiData(const FsiModel& model);

  mbd::ChainData chain;
  std::optional<uvlm::VortexLatticeData> lattice;  ///< present if model.air
  mbd::ChainState state;     ///< accepted state (time, Φ, Φ̇, …)
  mbd::ChainState trial;     ///< chain answer of the current sub-iteration
  mbd::ChainState relaxed;   ///< relaxed iterate the lattice is solved on
  mbd::Loads loads;          ///< external + aerodynamic loads of the current solve
  Eigen::Matrix3Xd nodes, node_velocities;  ///< deformed lattice of the last solve [m], [m/s]
  Eigen::VectorXd residual;  ///< Φ̈ change of the last sub-iteration
  AitkenRelaxation aitken;
  InterfaceQuasiNewton quasi_newton;
  Eigen::VectorXd stacked_trial, stacked_next;  ///< (Φ, Φ̇, Φ̈, a) of ŝ and of the next s̃
  long step = 0;             ///< steps taken
  int last_iterations = 0;   ///< lattice solves in the last step
  double last_change = 0.0;  ///< convergence measure at the end of the last step [rad]
  long total_iterations = 0;
};

/// \brief Initial state at time t0: Φ at the rest angles, at rest relative to the base.
void initialize(const FsiModel& model, FsiData& data, double t0);

/// \brief One coupled step (see the file comment).
/// \throws flapsim::NumericalFailure naming step and time when the chain solver fails
///         (mbd::ConvergenceFailure), the coupling does not converge in
///         max_iterations, or loads or states are not finite
/// The wake is left as it was: call shed_wake before the next step.
void coupled_step(const FsiModel& model, FsiData& data, double dt);

/// \brief Accepts the step's lattice solution: convects the wake and sheds a row
/// (uvlm::advance); nothing in vacuum.
/// \throws flapsim::NumericalFailure if the wake storage is exhausted
void shed_wake(const FsiModel& model, FsiData& data);

}  // namespace flapsim::fsi
