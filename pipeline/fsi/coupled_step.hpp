#pragma once
/// \file coupled_step.hpp
/// \brief One time step of the two-way coupled wing: a structure (structure.hpp: the bar
/// chain, or any other kind) and the vortex lattice (uvlm), strongly coupled by
/// sub-iterations with Aitken relaxation (docs/fsi.md). A constant FsiModel and a mutable
/// FsiData, as in mbd and uvlm. The step knows the structure only through its interface.
///
/// Step t_n → t_{n+1} = t_n + dt:
///  0. predictor: the structure's step with the previous step's aerodynamic loads → s̃⁰;
///  1. the lattice nodes ride on the structure's pose at s̃ᵏ (position and velocity), the
///     lattice is solved at t_{n+1} (wake unchanged), its panel forces go to the structure;
///  2. the structure's step is redone from the same s_n with these loads → ŝᵏ⁺¹;
///  3. converged when the structure stops changing (StructureData::change; for the chain
///        max(‖Φ̂ − Φ̃‖∞, ‖Φ̂̇ − Φ̃̇‖∞ / (2π f)) ≤ tolerance   [rad]);
///     else s̃ᵏ⁺¹ = s̃ᵏ + ωₖ (ŝᵏ⁺¹ − s̃ᵏ) with Aitken's ωₖ on the structure's interface
///     residual, or with CouplingMethod::InterfaceQuasiNewton, from the second
///     sub-iteration on, the IQN-ILS combination of the step's answers ŝ
///     (interface_quasi_newton.hpp); and back to 1;
///  Accuracy of the structure's solves (StructureData::set_solve_accuracy): a sub-iteration
///  that starts from a change δ of the last one solves to max(1, δ / tolerance) times the
///  structure's own tolerance (the FEM's error then stays below 1 % of δ), the predictor to
///  the first change of the previous step; converged on a looser answer, the structure is
///  solved once more with the same loads at full accuracy and the change measured again;
///  4. accept ŝ (the structure's exact answer to the last loads); then (shed_wake, after
///     the caller has written its outputs of the step) convect and shed the wake.
/// The number of lattice solves of the step is its coupling iteration count.
///
/// A rigid wing is a structure without degrees of freedom: the same attachment and load
/// transfer, one lattice solve per step, nothing to iterate. A vacuum run (no air) steps
/// the structure with its external loads only.

#include <Eigen/Core>

#include <memory>
#include <optional>

#include "pipeline/fsi/aitken_relaxation.hpp"
#include "pipeline/fsi/interface_quasi_newton.hpp"
#include "pipeline/fsi/structure.hpp"
#include "uvlm/added_mass.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::fsi {

/// How the sub-iterations of a step update the structure's iterate (docs/fsi.md, "Coupling").
enum class CouplingMethod {
  Aitken,                ///< one Aitken factor for the whole state (aitken_relaxation.hpp)
  InterfaceQuasiNewton,  ///< IQN-ILS on the interface residual (interface_quasi_newton.hpp); Aitken's factor for the
                         ///< first update of a step (no secant pair yet)
};

struct CouplingSettings {
  CouplingMethod method = CouplingMethod::Aitken;
  int max_iterations = 50;      ///< lattice solves per step before giving up
  double tolerance = 1e-6;      ///< see the file comment [rad]
  double first_relaxation = 0.5;  ///< ω of the very first sub-iteration
  /// IQN-ILS only: earlier time steps whose secant pairs are kept (IQN-ILS(q),
  /// interface_quasi_newton.hpp); 0: each step starts without any.
  int reuse_steps = 0;
  /// Intermediate structure solves to 1 % of the coupling's current change (file comment);
  /// false: every solve at the structure's full accuracy.
  bool loose_intermediate_solves = true;
  /// The lattice's added-mass response linearised into the structure's step at the steps
  /// below (StructureData::linearise_panel_loads; docs/fsi.md, "Added mass in the
  /// coupling"); false: the plain partitioned step.
  bool added_mass = true;
  /// Steps between two linearisations of the added mass (the first three steps each get
  /// one: the lattice's ∂Γ/∂t changes from BDF1 to BDF2). Held between them: in the
  /// structure's own coordinates the added mass follows the wing's shape, not its pose.
  int added_mass_every = 10;
  /// After a step that took more lattice solves than this the next step makes it anew
  /// (coupled_step.cpp, added_mass_due).
  int added_mass_stale = 5;
  /// After this many lattice solves of a step without convergence each strip's separated
  /// leading-edge force keeps the side the last solve gave it for the rest of the step
  /// (uvlm/leading_edge_side.hpp: where a strip's leading-edge circulation changes sign the
  /// force jumps and the iterates may alternate between the two sides; docs/fsi.md,
  /// "Coupling"). Steps that converge sooner are not touched.
  int edge_side_hold_after = 10;
  /// After this many lattice solves of a step or more, once the last change is at most
  /// old_wake_hold_change tolerances, the step's further solves take the wing's sums over
  /// the older wake (rows more than the lattice's young_wake_rows steps old) from the
  /// records of its last two solves instead of summing them anew, until a change exceeds
  /// that again, and then for the rest of the step (uvlm/old_wake_hold.hpp; docs/fsi.md,
  /// "One coupled step"): by then the wing moves by about the coupling's last change
  /// between solves. 0: never (the wake is then not kept apart either).
  int old_wake_hold_after = 2;
  /// (see old_wake_hold_after; docs/fsi.md: the held sums are then within the
  /// single-precision sums' rounding)
  double old_wake_hold_change = 100.0;
  /// The predictor's loads: the last accepted step's panel forces extrapolated in time
  /// through this many earlier steps' (0: held, 1: linear, 2: quadratic), each panel's
  /// force vector at its current point (docs/fsi.md, "One coupled step"). Only where the
  /// iteration starts; the answer is the fixed point's.
  int predictor_order = 2;
};

struct FsiModel {
  /// The structure (chain_structure.hpp for the bar chain and the rigid wing). Shared: a
  /// model is copied cheaply and the structure is constant.
  std::shared_ptr<const StructureModel> structure;
  double frequency = 1.0;                ///< flapping frequency f [Hz] (rate scale of the test)
  CouplingSettings coupling;

  bool air = true;                       ///< false: vacuum, no lattice
  uvlm::VortexLatticeModel lattice;      ///< used if air
  double density = 1.225;                ///< ρ [kg/m³]
  Eigen::Vector3d free_stream = Eigen::Vector3d::Zero();  ///< [m/s]

  /// The prescribed motion of the wing base.
  const mbd::BaseMotion& base() const { return structure->base(); }
};

/// Most secant pairs IQN-ILS keeps (at most the structure's DOFs): a step's sub-iterations
/// and the reused steps' pairs stay far below it, and the FEM's interface (every node's
/// position and velocity) would otherwise size the store by its tens of thousands of DOFs.
inline constexpr int kMaxQuasiNewtonPairs = 100;
/// How often a step whose coupling stalled is tried again with a finer structure
/// (StructureData::refine_after_stall: the FEM's step in twice as many pieces each time).
inline constexpr int kStallRetries = 2;

struct FsiData {
  explicit FsiData(const FsiModel& model);

  std::unique_ptr<StructureData> structure;        ///< the structure's state (model.structure)
  std::optional<uvlm::VortexLatticeData> lattice;  ///< present if model.air
  std::optional<uvlm::AddedMassScratch> added_mass_scratch;  ///< present if model.air
  /// Panel forces of the accepted steps before the last one [N] (newest first; the
  /// predictor's extrapolation), how many are held, and the predictor's loads (scratch).
  Eigen::Matrix3Xd earlier_forces[2];
  int earlier_count = 0;
  uvlm::PanelLoads predicted_loads;
  Eigen::Matrix3Xd nodes, node_velocities;  ///< deformed lattice of the last solve [m], [m/s]
  Eigen::VectorXd residual;  ///< interface residual of the last sub-iteration
  AitkenRelaxation aitken;
  InterfaceQuasiNewton quasi_newton;
  Eigen::VectorXd stacked_trial, stacked_next;  ///< the state vectors of ŝ and of the next s̃
  long step = 0;             ///< steps taken
  int last_iterations = 0;   ///< lattice solves in the last step
  /// The step under way: its lattice solves so far (every try) and the structure's change
  /// after the last of them [rad]; what a step that lasts shows on the progress line.
  int step_solves = 0;
  double step_change = 0.0;
  double last_change = 0.0;  ///< convergence measure at the end of the last step [rad]
  double first_change = 0.0;  ///< the last step's change after its first sub-iteration [rad]
  long accuracy_solves = 0;   ///< structure solves repeated at full accuracy (see above)
  long stall_retries = 0;     ///< steps whose coupling was tried again after a stall (coupled_step)
  long total_iterations = 0;

  /// Time of the accepted state [s].
  double time() const { return structure->time(); }
};

/// \brief Initial state at time t0 (the structure's, StructureData::initialize).
/// \throws flapsim::NumericalFailure naming the time when the structure cannot start
void initialize(const FsiModel& model, FsiData& data, double t0);

/// \brief One coupled step (see the file comment).
/// \throws flapsim::NumericalFailure naming step and time when the structure's solve fails
///         (StructureFailure), the coupling does not converge in
///         max_iterations, or loads or states are not finite
/// The wake is left as it was: call shed_wake before the next step.
void coupled_step(const FsiModel& model, FsiData& data, double dt);

/// \brief Accepts the step's lattice solution: convects the wake and sheds a row
/// (uvlm::advance); nothing in vacuum.
/// \throws flapsim::NumericalFailure if the wake storage is exhausted
void shed_wake(const FsiModel& model, FsiData& data);

}  // namespace flapsim::fsi
