#pragma once
/// \file fem_structure.hpp
/// \brief The wing's own FEM as the structure of a coupled run (structure.hpp): the
/// co-rotational shells and veins of fem/ (nonlinear_dynamics.hpp: generalized-α, Newton,
/// large rotations), moving in the ground frame with its clamp nodes driven by the base
/// motion, and the lattice riding on its shell (fem_attachment.hpp). docs/fsi.md, "The FEM as
/// the structure".
///
/// What the coupling relaxes is the interface: the translations and velocities of the FEM's
/// nodes, (x, v), which alone place the lattice; the interface residual is x̂ − x̃ (Aitken's
/// factor on the displacements, the same factor on the velocities). Each solve restarts the
/// step from the accepted state; its Newton starts from the step's last answer (the first
/// solve of a step from the rigid-base predictor), so the structure's answer ŝ to given
/// loads does not depend on the iterate to the FEM's tolerance, which
/// coupled_dynamics_options puts at 1 % of the coupling's; the accepted state is ŝ, the
/// FEM's own converged step. An intermediate solve may stop at a looser tolerance
/// (set_solve_accuracy: the coupled step asks for 1 % of its current change; coupled_step.hpp).
///
/// Step halving: a step whose Newton fails is redone in 2, 4, … up to kMaxFemStepPieces equal
/// pieces, the loads interpolated linearly in time from the accepted step's to the new ones
/// (the clamp driven at each piece's end) except for their unsteady part, the pressure's
/// ρ (∂Γ/∂t) A n (uvlm::PanelLoads::unsteady_force), which each piece takes as the new step's:
/// it is the step's mean rate (Γₙ₊₁ − Γₙ)/Δt with the first-order rate, so held over the step
/// its impulse is the air's added mass times the step's change of velocity, where interpolated
/// from the last step's rate it lags half a step, and on a wing as light as its added mass
/// (μ = m_a/m ≫ 1) the lag made a sawtooth of period 2Δt that decays by only μ/(2 + μ) a
/// step (docs/fsi.md, "Split steps: the unsteady load held"). A step solved whole takes its
/// loads at its end, as generalized-α does. A thin film wrinkles under compression faster than
/// a coupled step (its tangent turns indefinite at the mesh's wavelength: docs/fsi.md, "Film
/// wings"); in a shorter piece the step's inertia c_M ρt ∝ 1/h² weighs more against the
/// negative geometric stiffness and Newton converges (with ρ∞ = 0, which damps the film's
/// unresolved oscillations out, the 25 µm film wings needed up to 8 and 32 pieces). The
/// count of pieces is kept for the step's sub-iterations
/// (the structure's answer to given loads then stays one function of them), carried into the
/// next step, and halved again after kFemStepsBeforeJoining steps solved without a failure. A
/// run that never fails is solved whole, unchanged to the bit.
///
/// The air's added mass (linearise_panel_loads, `numerics.added_mass`): the lattice's
/// response lumped to the nodes (fem_added_mass.hpp) acts in every solve of a step solved
/// whole as a load −D (v_{n+1} − ṽ) (fem/load_damping.hpp): in the sub-iterations ṽ is the
/// velocity the lattice was solved with (the load vanishes at the coupling's fixed point),
/// in the predictor the velocity extrapolated from the last steps, as its loads are (and
/// the Newton matrix it keeps for the sub-iterations has D). A run whose step is split drops
/// it for good: in pieces it made the film wings' coupling slower; a thin film goes without it
/// from the start (FemStructureModel::lumped_added_mass; docs/fsi.md, "Added mass in the
/// coupling").

#include <Eigen/Core>

#include <memory>
#include <vector>

#include "fem/nonlinear_assembly.hpp"
#include "fem/nonlinear_dynamics.hpp"
#include "fem/structural_model.hpp"
#include "mbd/base_motion.hpp"
#include "pipeline/fsi/fem_added_mass.hpp"
#include "pipeline/fsi/fem_attachment.hpp"
#include "pipeline/fsi/structure.hpp"

namespace flapsim::fsi {

/// The FEM, which of its nodes the base drives, and the lattice on its shell. Built in
/// place and never copied (the dynamics model points into the co-rotational model).
/// Most pieces one coupled step of the FEM is split into (measured at most 8 on the 75 mm and
/// 32 on the MAV 25 µm film wing at 80 steps a wingbeat; the bound caps a hopeless step's
/// work at 511 pieces' Newton solves), and the steps solved without a failure after which
/// the count of pieces is halved again: after each one (with 4, until 30 Nov, the MAV film
/// wing's five wingbeats solved 360 of 400 steps in pieces, 91 piece solves a step in its
/// first wingbeat; with 1, 230 and 48, and the run took 21 % less CPU time: docs/fsi.md, "Step
/// halving of the FEM").
inline constexpr int kMaxFemStepPieces = 256;
inline constexpr int kFemStepsBeforeJoining = 1;

class FemStructureModel : public StructureModel {
 public:
  /// \param structural     mesh (in the wing frame W, origin at the pivot) and materials
  /// \param clamped_nodes  the nodes the base drives (all six DOFs)
  /// \param lattice_nodes  lattice nodes in W, (nc+1)(ns+1) columns [m] (empty: vacuum)
  /// \param length_scale   the wing's span [m]: the scale of the coupling's change measure
  /// \param gravity        g in the ground frame [m/s²] (zero: none)
  FemStructureModel(fem::StructuralModel structural, std::vector<int> clamped_nodes, mbd::BaseMotion base,
                    const fem::DynamicsOptions& options, const Eigen::Matrix3Xd& lattice_nodes, int chordwise,
                    int spanwise, double length_scale, const Eigen::Vector3d& gravity = Eigen::Vector3d::Zero());
  FemStructureModel(const FemStructureModel&) = delete;
  FemStructureModel& operator=(const FemStructureModel&) = delete;

  int num_dofs() const override { return corotational.num_dofs(); }
  int surface_nodes() const override { return static_cast<int>(attachment.nodes.size()); }
  const mbd::BaseMotion& base() const override { return base_motion; }
  std::unique_ptr<StructureData> make_data() const override;
  const Eigen::Matrix3Xd& reference_surface() const override { return attachment.reference_nodes; }

  const fem::StructuralModel structural;
  const fem::CorotationalModel corotational;
  const fem::DynamicsModel dynamics;
  const mbd::BaseMotion base_motion;
  const FemAttachment attachment;
  const double length_scale;  ///< [m]
  /// Whether the sub-iterations take the lattice's added mass (linearise_panel_loads): the
  /// case setup leaves it out for a thin film's FEM (docs/fsi.md, "Added mass in the coupling").
  bool lumped_added_mass = true;
  /// Whether solved_accuracy() reports the factor a loose answer met (the coupled step then
  /// keeps an answer that met the full accuracy instead of solving again), or the factor
  /// asked (every loose answer solved again): the case setup asks the latter of a thin
  /// film, whose coupling follows its path (docs/fsi.md, "One coupled step").
  bool keep_met_loose_answers = true;
  /// The weight M g of every node (g at each translational DOF, through the FEM's mass
  /// matrix: its resultant is the FEM's mass times g, its moment that of the mass
  /// distribution) [N]; empty without gravity.
  const Eigen::VectorXd gravity_loads;
};

/// \brief The FEM's Newton tolerance in a coupled run, from the coupling's: the coupling
/// converges when max(|δx|, |δv|/(2πf)) ≤ τ L between sub-iterations (change()), and the
/// FEM's own error should be well below that, so that its answer to given loads does not
/// depend on where its Newton started (the warm start of a sub-iteration). A modified
/// Newton whose corrections contract by ρ ≤ refactor_rate leaves an error of at most
/// ρ/(1 − ρ) times its last correction ε L; the velocity error is γ/(βΔt) times it, i.e.
/// (γ/β)(N/2π) ε L per flapping radian at N steps per cycle. Asked: both below 1 % of τ:
///   ε = 0.01 τ (1 − ρ)/ρ / max(1, (γ/β) N/(2π))
/// (τ = 1e-6, N = 100, ρ∞ = 1, ρ = 0.25: ε = 9.4e-10). Returns `options` with
/// increment_tolerance = ε (translations relative to the model size, rotations in rad).
fem::DynamicsOptions coupled_dynamics_options(fem::DynamicsOptions options, double coupling_tolerance,
                                              int steps_per_cycle);

/// The FEM's states during a run.
class FemStructureData : public StructureData {
 public:
  explicit FemStructureData(const FemStructureModel& model);

  void initialize(double t0) override;
  double time() const override { return accepted_.time; }
  void set_external_loads(double t) override;
  void add_panel_loads(const uvlm::PanelLoads& panels) override;
  void prescribe(double t) override;
  void solve(double dt) override;
  double set_solve_accuracy(double factor) override { return accuracy_ = factor > 1.0 ? factor : 1.0; }
  double solved_accuracy() const override { return model_.keep_met_loose_answers ? solved_accuracy_ : accuracy_; }
  void linearise_panel_loads(PanelLoadResponse& response) override;
  void start_iterate() override;
  void pose_iterate() override { pose_is_trial_ = false; }
  void surface(Eigen::Matrix3Xd& positions, Eigen::Matrix3Xd& velocities) const override;
  double change(double frequency) const override;
  void residual(Eigen::VectorXd& r) const override;
  void trial_vector(Eigen::VectorXd& x) const override;
  void set_iterate(const Eigen::VectorXd& x) override;
  void relax(double omega) override;
  void accept() override;
  bool refine_after_stall() override;
  int interface_size() const override { return 3 * model_.corotational.num_nodes(); }
  long split_steps() const override { return split_steps_; }
  int max_step_pieces() const override { return max_pieces_; }
  StructureReadout readout() const override;  // fem_readout.cpp
  void joint_angles(Eigen::VectorXd& q) const override { q.resize(0); }

  /// The FEM's current (trial, after solve; else accepted) state.
  const fem::DynamicsData& dynamics() const { return *dynamics_; }
  /// Node translations [m] and velocities [m/s] of the trial ŝ.
  const Eigen::Matrix3Xd& trial_positions() const { return trial_x_; }
  /// The lattice's added mass lumped to the nodes (fem_added_mass.hpp), base frame; empty
  /// before the coupling has linearised it.
  const LumpedAddedMass& added_mass() const { return added_mass_; }

 private:
  struct Saved {  // the accepted state, to restart each solve from
    fem::CorotationalState state;
    Eigen::VectorXd velocity, acceleration, pseudo_acceleration;
    double time = 0.0;
  };
  void restore_accepted();
  void read_trial();
  /// The step from the accepted state in `pieces` equal pieces; false (the state undefined,
  /// the reason in `failure`) when a piece's Newton fails.
  bool solve_in_pieces(double dt, int pieces, std::string& failure);

  /// The lumped added mass in ground axes at t [s], measured from `reference` [m/s].
  const fem::NodalLoadDamping* added_mass_load(double t, const Eigen::Matrix3Xd& reference);

  const FemStructureModel& model_;  ///< not owned
  std::unique_ptr<fem::DynamicsData> dynamics_;
  Saved accepted_;
  Eigen::VectorXd loads_;                  ///< nodal loads of the next solve [N, N m]
  Eigen::VectorXd accepted_loads_;         ///< the accepted step's loads [N, N m]
  Eigen::VectorXd piece_loads_;            ///< one piece's loads (interpolated) [N, N m]
  Eigen::VectorXd unsteady_loads_;         ///< the part of loads_ from the pressure's ρ ∂Γ/∂t [N, N m]
  Eigen::VectorXd accepted_unsteady_loads_;  ///< the accepted step's [N, N m]
  int pieces_ = 1;                         ///< pieces of the current step's solves
  int steps_without_failure_ = 0;          ///< accepted steps since a solve last failed
  bool failed_this_step_ = false;          ///< a solve of the current step needed more pieces
  long split_steps_ = 0;                   ///< accepted steps solved in more than one piece
  int max_pieces_ = 1;                     ///< most pieces of one accepted step
  Eigen::Matrix3Xd trial_x_, trial_v_;     ///< ŝ's node translations and velocities
  Eigen::Matrix3Xd iterate_x_, iterate_v_; ///< s̃'s
  bool pose_is_trial_ = true;              ///< the surface follows ŝ (else s̃)
  double solved_accuracy_ = 1.0;           ///< the last solve's (the largest of its pieces')
  double accuracy_ = 1.0;                  ///< the next solve's tolerance, in multiples of the FEM's
  // The air's added mass (linearise_panel_loads; solve_in_pieces).
  LumpedAddedMass added_mass_;             ///< base frame; empty: none
  bool added_mass_dropped_ = false;        ///< a step was split: none for the rest of the run
  fem::NodalLoadDamping damping_;          ///< added_mass_ in ground axes, for a solve
  bool iterating_ = false;                 ///< between start_iterate() and accept()
  Eigen::Matrix3Xd loads_velocity_;        ///< node velocities the loads were found at [m/s]
  Eigen::Matrix3Xd accepted_v_, earlier_v_, earliest_v_;  ///< node velocities of s_n, s_{n−1}, s_{n−2} [m/s]
  Eigen::Matrix3Xd predicted_velocity_;    ///< 3 v_n − 3 v_{n−1} + v_{n−2} (2 v_n − v_{n−1}): the predictor's reference [m/s]
  long accepted_steps_ = 0;                ///< steps accepted since initialize()
};

}  // namespace flapsim::fsi
