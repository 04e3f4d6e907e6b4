#pragma once
/// \file chain_structure.hpp
/// \brief The bar chain (mbd) as the structure of a coupled run (structure.hpp): the
/// chain's implicit generalized-α step, the lattice riding on its bodies
/// (wing_attachment.hpp) and the panel loads going back to them (load_transfer.hpp).
/// A rigid wing is a chain without degrees of freedom (one body welded to the base).
///
/// The state relaxed between sub-iterations is (Φ, Φ̇, Φ̈, a): within a step all four are
/// affine in Φ̈, so one relaxation factor on all of them keeps a consistent generalized-α
/// state; the interface residual is Φ̈ (docs/fsi.md, "Coupling").

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

#include "mbd/base_motion.hpp"
#include "mbd/chain_data.hpp"
#include "mbd/chain_loads.hpp"
#include "mbd/chain_model.hpp"
#include "mbd/generalized_alpha.hpp"
#include "pipeline/fsi/structure.hpp"
#include "pipeline/fsi/wing_attachment.hpp"
#include "uvlm/leading_edge_response.hpp"

namespace flapsim::fsi {

/// External (non-aerodynamic) loads at time t [s], added to `loads` (e.g. a case's
/// prescribed point loads). Empty: none.
using ExternalLoads = std::function<void(double t, mbd::Loads& loads)>;

/// The chain, its integrator, its initial state and the lattice attached to it.
class ChainStructureModel : public StructureModel {
 public:
  mbd::ChainModel chain;                 ///< the structure (no dofs: a rigid wing)
  mbd::BaseMotion base_motion;           ///< prescribed wing-base motion
  mbd::GeneralizedAlphaSettings integrator;
  /// Φ(t₀), Φ̇(t₀) [rad, rad/s]; empty: the chain's rest angles, at rest.
  Eigen::VectorXd initial_q, initial_v;
  ExternalLoads external_loads;
  WingAttachment attachment;             ///< lattice nodes on the chain (empty in vacuum)

  int num_dofs() const override { return chain.num_dofs(); }
  int surface_nodes() const override { return static_cast<int>(attachment.nodes.size()); }
  const mbd::BaseMotion& base() const override { return base_motion; }
  std::unique_ptr<StructureData> make_data() const override;
  const Eigen::Matrix3Xd& reference_surface() const override { return attachment.reference_nodes; }
};

/// The chain's kinematics, states and loads during a run.
class ChainStructureData : public StructureData {
 public:
  explicit ChainStructureData(const ChainStructureModel& model);

  void initialize(double t0) override;
  double time() const override { return state.time; }
  void set_external_loads(double t) override;
  void add_panel_loads(const uvlm::PanelLoads& panels) override;
  void prescribe(double t) override;
  void solve(double dt) override;
  void linearise_panel_loads(PanelLoadResponse& response) override;
  void refresh_panel_load_response(PanelLoadResponse& response) override;
  void start_iterate() override {
    relaxed = trial;
    chain.load_damping.active = has_added_mass_;  // the sub-iterations' solves
  }
  void pose_iterate() override;
  void surface(Eigen::Matrix3Xd& positions, Eigen::Matrix3Xd& velocities) const override;
  double change(double frequency) const override;
  void residual(Eigen::VectorXd& r) const override;
  void trial_vector(Eigen::VectorXd& x) const override;
  void set_iterate(const Eigen::VectorXd& x) override;
  void relax(double omega) override;
  void accept() override {
    state = trial;
    chain.load_damping.active = false;  // not in the next step's predictor
  }
  int interface_size() const override { return model_.chain.num_dofs(); }
  long split_steps() const override { return chain.step.split_steps; }
  int max_step_pieces() const override { return chain.step.max_substeps; }
  long restarted_steps() const override { return chain.step.restarted_steps; }
  StructureReadout readout() const override;
  void joint_angles(Eigen::VectorXd& q) const override { q = state.q; }

  const ChainStructureModel& model() const { return model_; }

  mbd::ChainData chain;      ///< kinematics of the current pose (see structure.hpp)
  mbd::ChainState state;     ///< accepted state (time, Φ, Φ̇, …)
  mbd::ChainState trial;     ///< the chain's answer of the current sub-iteration
  mbd::ChainState relaxed;   ///< the iterate the lattice is solved on
  mbd::Loads loads;          ///< external + aerodynamic loads of the current solve

 private:
  const ChainStructureModel& model_;  ///< not owned
  // Scratch of linearise_panel_loads.
  Eigen::Matrix3Xd base_positions_, base_velocities_, unit_positions_, unit_velocities_, node_change_;
  uvlm::PanelLoads panel_change_;
  mbd::Loads change_loads_;
  Eigen::VectorXd gravity_load_, rates_;
  bool has_added_mass_ = false;  ///< chain.load_damping.matrix holds a linearisation
  // The held linearisation: D's part without the leading-edge force, and per joint
  // coordinate the leading-edge force's held column (panel_load_response.hpp).
  Eigen::MatrixXd pressure_damping_;
  std::vector<uvlm::LeadingEdgeColumn> edge_columns_;
  bool edge_response_ = false;
  void set_damping(PanelLoadResponse& response);
};

/// \brief The chain parts of a run's structure, for outputs that show the chain (joint
/// angles, chain.vtp, markers on bodies).
/// \throws std::logic_error if the structure is not a chain
const ChainStructureModel& chain_structure(const StructureModel& model);
const ChainStructureData& chain_structure(const StructureData& data);

}  // namespace flapsim::fsi
