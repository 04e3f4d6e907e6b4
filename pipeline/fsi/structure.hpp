#pragma once
/// \file structure.hpp
/// \brief The structure a coupled step drives, as the coupling sees it: a constant
/// StructureModel and the mutable StructureData it makes (docs/fsi.md, "Structures").
///
/// The coupling (coupled_step.hpp) knows nothing else of the structure: it gives it loads
/// (the panel forces of the lattice at their points), asks it to solve a step, reads the
/// surface the lattice rides on (positions and velocities of the lattice nodes), and
/// relaxes its iterate between sub-iterations. Each kind of structure implements this
/// once: the bar chain (chain_structure.hpp); a rigid wing is a chain without degrees of
/// freedom. The design follows the solver registry of SHARPy (del Carre et al. 2019,
/// docs/references.md): the case chooses the structure, the coupled step is one code.
///
/// States of a step t_n → t_{n+1}:
///   accepted s_n — the last accepted state (time());
///   trial ŝ      — the structure's own answer to the loads of the last solve();
///   iterate s̃    — what the lattice is solved on: start_iterate() sets it to ŝ,
///                  relax()/set_iterate() move it, accept() makes ŝ the new s_n.
/// The relaxation works on one vector per state (trial_vector, set_iterate: every
/// quantity that defines the state, all affine in the residual within a step) and on a
/// residual of the interface (residual(): ŝ − s̃ in the quantity the structure's solve
/// responds to), so Aitken and IQN-ILS (aitken_relaxation.hpp,
/// interface_quasi_newton.hpp) apply to any structure.

#include <Eigen/Core>

#include <memory>
#include <stdexcept>
#include <string>

#include "mbd/base_motion.hpp"
#include "uvlm/vortex_lattice.hpp"

namespace flapsim::fsi {

/// A structural solve that failed (no convergence, a non-finite state): its text says
/// which structure and why; the coupling adds the step and the time (NumericalFailure).
class StructureFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StructureData;
class PanelLoadResponse;

/// What a run records of a structure at its accepted state (history.csv, summary.json),
/// defined alike for every structure so that runs compare column by column (docs/fsi.md,
/// "Outputs"). Sections: the chain's last body and its outer body (the one at 5/6 of the
/// length); the FEM's best-fit rigid rotation of its nodes in the outer tenth of the span
/// and in the band ±R/20 about 5/6 of the span (fem_readout.cpp).
struct StructureReadout {
  /// Rotation of the tip section, ground ← wing frame W, relative to its undeformed
  /// orientation (the base's rotation for an undeformed wing) [-].
  Eigen::Matrix3d tip_rotation = Eigen::Matrix3d::Identity();
  /// The same for the outer section [-].
  Eigen::Matrix3d outer_rotation = Eigen::Matrix3d::Identity();
  /// The tip's bend and twist relative to the base [rad]: the rotation of the chain's last
  /// body, or of the FEM's tip section, from its rest orientation, in the wing frame W,
  /// as Rx(bend) Ry(twist) (tip_deflection.hpp; the chain's joint convention,
  /// mbd/chain_model.hpp), about x_W and y_W whatever axis a chain lies along.
  double tip_bend = 0.0, tip_twist = 0.0;
  /// Force [N] and moment about the pivot [N m] the base exerts on the wing, ground frame
  /// (inertial, aerodynamic, gravity and point loads together), and the power it supplies,
  /// ω·M + v·F at the pivot [W].
  Eigen::Vector3d drive_force = Eigen::Vector3d::Zero(), drive_moment = Eigen::Vector3d::Zero();
  double drive_power = 0.0;
  /// The tip point, ground frame [m]: the chain's end (the last body's outboard joint, on
  /// its axis); of the FEM's nodes at the largest reference span coordinate y_W (the
  /// outline's tip or tip edge), the one nearest the span axis.
  /// Its trajectory is the run's tip_path.vtp.
  Eigen::Vector3d tip_position = Eigen::Vector3d::Zero();
};

/// What a structure is (constant during a run).
class StructureModel {
 public:
  virtual ~StructureModel() = default;
  /// Unknowns of the structure; 0: a rigid wing (its pose is prescribed, nothing to iterate).
  virtual int num_dofs() const = 0;
  /// Lattice nodes the structure carries (the attachment's count).
  virtual int surface_nodes() const = 0;
  /// The prescribed motion of the wing base (the clamp) [s → pose].
  virtual const mbd::BaseMotion& base() const = 0;
  /// A fresh workspace and state for a run of this model.
  virtual std::unique_ptr<StructureData> make_data() const = 0;
  /// The lattice nodes as the undeformed structure carries them, in the wing frame W [m],
  /// lattice order (3 × surface_nodes()): the chain at its rest angles, the FEM's shell at
  /// its reference mesh. The rigid wing's surface at time t is this moved with the base.
  virtual const Eigen::Matrix3Xd& reference_surface() const = 0;

  /// \brief The lattice nodes on the undeformed wing moved with the prescribed base motion at
  /// \p t [s]: x = p(t) + R(t) X, ground frame [m] (\p positions resized to 3 × surface_nodes()).
  /// A run's surface minus this is the wing's deformation (wing.vtp displacement_m).
  void rigid_surface(double t, Eigen::Matrix3Xd& positions) const {
    const mbd::BasePose pose = base()(t);
    positions.noalias() = pose.rotation * reference_surface();
    positions.colwise() += pose.position;
  }
};

/// A structure's state and workspace during a run (made by StructureModel::make_data).
class StructureData {
 public:
  virtual ~StructureData() = default;

  /// \brief The initial state at t0 (at its rest configuration unless the model says
  /// otherwise), with the structure's own external loads at t0.
  /// \throws StructureFailure
  virtual void initialize(double t0) = 0;
  /// Time of the accepted state [s].
  virtual double time() const = 0;

  /// \brief The loads of the next solve: the structure's external loads at time t [s]
  /// (prescribed point loads, gravity is the model's) and no aerodynamic load.
  virtual void set_external_loads(double t) = 0;
  /// \brief Adds the lattice's panel forces [N] at their points of action [m] (ground
  /// frame), transferred at the structure's current pose so that force and moment are kept.
  virtual void add_panel_loads(const uvlm::PanelLoads& panels) = 0;

  /// \brief Rigid structure (num_dofs() == 0): the prescribed pose at t [s] becomes the
  /// accepted state.
  virtual void prescribe(double t) = 0;
  /// \brief Solves the step of dt [s] from the accepted state with the current loads: the
  /// trial state ŝ. On return the structure's pose (surface()) is the trial's.
  /// \throws StructureFailure
  virtual void solve(double dt) = 0;
  /// \brief The next solves may stop at \p factor (≥ 1) times the structure's own convergence
  /// tolerance: an intermediate answer of the coupling, far from its fixed point. 1 (the
  /// default): full accuracy, which the accepted state must have. Returns the factor the
  /// structure will use: 1 for a structure solved to its accuracy whatever the factor (the chain).
  virtual double set_solve_accuracy(double factor) {
    (void)factor;
    return 1.0;
  }
  /// \brief The factor of the structure's own tolerance whose convergence test the last
  /// solve's answer passed (≤ the factor asked; ≤ 1: an answer asked for loosely that meets
  /// the full accuracy all the same, which the coupled step then need not solve again).
  virtual double solved_accuracy() const { return 1.0; }
  /// \brief Takes the lattice's linearised added-mass response at its last solve
  /// (panel_load_response.hpp) into the solves of the sub-iterations, of this step and of
  /// the following ones until the coupling gives a new one (not the predictors): the
  /// structure's step then answers its own velocity as the air's added mass would, which
  /// the coupling otherwise learns over sub-iterations; the coupling's fixed point is
  /// unchanged. A structure that cannot use it ignores it (the default).
  virtual void linearise_panel_loads(PanelLoadResponse& response) { (void)response; }
  /// \brief At a step that takes no new linearisation: the parts of the held one that
  /// follow the lattice's last solve (the leading-edge force's, which turns with the sign
  /// of each strip's leading-edge circulation; panel_load_response.hpp) evaluated anew.
  virtual void refresh_panel_load_response(PanelLoadResponse& response) { (void)response; }
  /// The iterate s̃ := ŝ (the predictor of a step).
  virtual void start_iterate() = 0;
  /// \brief Puts the structure's pose at the iterate s̃ (its time is the trial's).
  virtual void pose_iterate() = 0;
  /// \brief Lattice nodes on the current pose: positions [m] and velocities [m/s], ground
  /// frame, lattice order (matrices sized by the caller to 3 × surface_nodes()).
  virtual void surface(Eigen::Matrix3Xd& positions, Eigen::Matrix3Xd& velocities) const = 0;

  /// \brief Convergence measure between ŝ and s̃ [rad for rotations; the structure's
  /// documented scale], \p frequency [Hz] scales rates to per flapping radian.
  virtual double change(double frequency) const = 0;
  /// The interface residual ŝ − s̃ (the quantity Aitken's factor is computed on).
  virtual void residual(Eigen::VectorXd& r) const = 0;
  /// Every quantity of ŝ as one vector (IQN-ILS combines these).
  virtual void trial_vector(Eigen::VectorXd& x) const = 0;
  /// s̃ := the state of the vector \p x (as trial_vector writes it), at the trial's time.
  virtual void set_iterate(const Eigen::VectorXd& x) = 0;
  /// s̃ += ω (ŝ − s̃) for every quantity of the state.
  virtual void relax(double omega) = 0;
  /// The accepted state := ŝ (the structure's exact answer to the last loads).
  virtual void accept() = 0;

  /// Length of residual() (the size of the relaxation's secant vectors).
  virtual int interface_size() const = 0;

  /// \brief A step whose coupling did not converge: the structure may solve its steps more
  /// finely from now on (a different, closer answer to the same loads), and the coupled step
  /// then tries the step's coupling once more. Returns whether it did; false (the default):
  /// nothing finer to offer, the step fails.
  virtual bool refine_after_stall() { return false; }

  /// Steps whose structural solve had to be split into smaller pieces since the start
  /// (step halving), and the most pieces one step needed (1: none split).
  virtual long split_steps() const = 0;
  virtual int max_step_pieces() const = 0;
  /// Steps that failed even in pieces and were solved as a restart of the time scheme
  /// (the chain's backward-Euler restart, docs/multibody.md "Step halving"); 0 (the default)
  /// for a structure without one.
  virtual long restarted_steps() const { return 0; }

  /// The run's record of the accepted state (not used by the coupling).
  virtual StructureReadout readout() const = 0;
  /// The structure's joint angles for history.csv [rad] (the chain's Φ: bend, twist per
  /// jointed body); empty for a structure without joints (a rigid wing, the FEM).
  virtual void joint_angles(Eigen::VectorXd& q) const = 0;
};

}  // namespace flapsim::fsi
