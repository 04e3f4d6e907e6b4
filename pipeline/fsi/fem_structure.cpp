#include "pipeline/fsi/fem_structure.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>
#include <string>

#include "pipeline/fsi/stop_request.hpp"

namespace flapsim::fsi {

FemStructureModel::FemStructureModel(fem::StructuralModel structural_model, std::vector<int> clamped_nodes,
                                     mbd::BaseMotion base, const fem::DynamicsOptions& options,
                                     const Eigen::Matrix3Xd& lattice_nodes, int chordwise, int spanwise,
                                     double length, const Eigen::Vector3d& gravity)
    : structural(std::move(structural_model)),
      corotational(fem::make_corotational_model(structural)),
      dynamics(fem::make_dynamics_model(corotational, std::move(clamped_nodes), options)),
      base_motion(std::move(base)),
      attachment(lattice_nodes.cols() > 0 ? attach_wing_to_fem(structural.mesh, lattice_nodes, chordwise, spanwise)
                                          : FemAttachment{}),
      length_scale(length),
      gravity_loads([&] {
        if (gravity.isZero(0.0)) return Eigen::VectorXd();
        Eigen::VectorXd g = Eigen::VectorXd::Zero(corotational.num_dofs());
        for (int n = 0; n < corotational.num_nodes(); ++n) g.segment<3>(fem::dof_index(n, fem::UX)) = gravity;
        return Eigen::VectorXd(corotational.mass * g);
      }()) {}

fem::DynamicsOptions coupled_dynamics_options(fem::DynamicsOptions options, double coupling_tolerance,
                                              int steps_per_cycle) {
  const double r = options.rho_infinity;
  const double am = (2.0 * r - 1.0) / (r + 1.0), af = r / (r + 1.0);
  const double gamma = 0.5 - am + af, beta = 0.25 * (1.0 - am + af) * (1.0 - am + af);
  const double rho = std::clamp(options.refactor_rate, 1e-3, 0.9);
  const double rate = std::max(1.0, gamma / beta * steps_per_cycle / (2.0 * std::numbers::pi));
  options.increment_tolerance = 0.01 * coupling_tolerance * (1.0 - rho) / rho / rate;
  return options;
}

std::unique_ptr<StructureData> FemStructureModel::make_data() const {
  return std::make_unique<FemStructureData>(*this);
}

FemStructureData::FemStructureData(const FemStructureModel& model)
    : model_(model), loads_(Eigen::VectorXd::Zero(model.corotational.num_dofs())) {}

namespace {

// The motion of the driven (clamp) nodes at time t: the base pose, the wing frame's origin
// at the pivot (the FEM's nodes are in W).
fem::PrescribedMotion clamp_motion(const FemStructureModel& m, double t) {
  const mbd::BasePose p = m.base_motion(t);
  return fem::rigid_prescribed_motion(m.dynamics, Eigen::Vector3d::Zero(), p.position, p.velocity, p.acceleration,
                                      p.rotation, p.angular_velocity, p.angular_acceleration);
}

}  // namespace

void FemStructureData::initialize(double t0) {
  // At rest relative to the base: every node moves rigidly with it at t0.
  const mbd::BasePose p = model_.base_motion(t0);
  const fem::CorotationalModel& c = model_.corotational;
  fem::CorotationalState state = fem::reference_state(c);
  Eigen::VectorXd v0 = Eigen::VectorXd::Zero(c.num_dofs());
  for (int n = 0; n < c.num_nodes(); ++n) {
    const Eigen::Vector3d r = p.rotation * c.reference_positions[static_cast<std::size_t>(n)];
    state.position[static_cast<std::size_t>(n)] = p.position + r;
    state.rotation[static_cast<std::size_t>(n)] = p.rotation;
    v0.segment<3>(fem::dof_index(n, fem::UX)) = p.velocity + p.angular_velocity.cross(r);
    v0.segment<3>(fem::dof_index(n, fem::RX)) = p.angular_velocity;
  }
  set_external_loads(t0);
  accepted_loads_ = loads_;
  accepted_unsteady_loads_ = unsteady_loads_;
  pieces_ = 1;
  steps_without_failure_ = 0;
  failed_this_step_ = false;
  split_steps_ = 0;
  max_pieces_ = 1;
  try {
    dynamics_ = std::make_unique<fem::DynamicsData>(model_.dynamics, state, v0, loads_);
  } catch (const std::exception& e) {
    throw StructureFailure(std::string("FEM: ") + e.what());
  }
  dynamics_->time = t0;
  accepted_ = Saved{dynamics_->state, dynamics_->velocity, dynamics_->acceleration, dynamics_->pseudo_acceleration,
                    dynamics_->time};
  read_trial();
  iterate_x_ = trial_x_;
  iterate_v_ = trial_v_;
  accepted_v_ = earlier_v_ = earliest_v_ = trial_v_;
  added_mass_ = LumpedAddedMass{};
  added_mass_dropped_ = false;
  iterating_ = false;
  accepted_steps_ = 0;
  pose_is_trial_ = true;
}

void FemStructureData::set_external_loads(double) {
  if (model_.gravity_loads.size() > 0)
    loads_ = model_.gravity_loads;
  else
    loads_.setZero();
  unsteady_loads_.setZero(loads_.size());
}

void FemStructureData::add_panel_loads(const uvlm::PanelLoads& panels) {
  loads_velocity_ = pose_is_trial_ ? trial_v_ : iterate_v_;
  const Eigen::Matrix3Xd& x = pose_is_trial_ ? trial_x_ : iterate_x_;
  add_panel_loads_to_fem(model_.attachment, model_.structural.mesh, x, panels, loads_);
  if (panels.unsteady_force.cols() > 0)  // panel loads made by hand (tests) may have none
    add_panel_forces_to_fem(model_.attachment, model_.structural.mesh, x, panels.unsteady_force, panels.point,
                            unsteady_loads_);
}

void FemStructureData::prescribe(double) {
  throw std::logic_error("FemStructureData::prescribe: the FEM always has degrees of freedom");
}

void FemStructureData::restore_accepted() {
  dynamics_->state = accepted_.state;
  dynamics_->velocity = accepted_.velocity;
  dynamics_->acceleration = accepted_.acceleration;
  dynamics_->pseudo_acceleration = accepted_.pseudo_acceleration;
  dynamics_->time = accepted_.time;
}

void FemStructureData::read_trial() {
  const int nn = model_.corotational.num_nodes();
  trial_x_.resize(3, nn);
  trial_v_.resize(3, nn);
  for (int n = 0; n < nn; ++n) {
    trial_x_.col(n) = dynamics_->state.position[static_cast<std::size_t>(n)];
    trial_v_.col(n) = dynamics_->velocity.segment<3>(fem::dof_index(n, fem::UX));
  }
}

bool FemStructureData::solve_in_pieces(double dt, int pieces, std::string& failure) {
  const double t0 = accepted_.time;
  const double h = dt / pieces;
  // The air's added mass, in steps solved whole (see fem_structure.hpp): the sub-iterations'
  // measured from the velocities the lattice was solved with, the predictor's from those
  // extrapolated from the last three steps (as the predictor's loads are).
  if (pieces > 1 && !added_mass_.nodes.empty()) {
    added_mass_ = LumpedAddedMass{};
    added_mass_dropped_ = true;
  }
  const fem::NodalLoadDamping* damping = nullptr;
  if (!added_mass_.nodes.empty()) {
    if (!iterating_ && accepted_steps_ >= 2)
      predicted_velocity_ = 3.0 * accepted_v_ - 3.0 * earlier_v_ + earliest_v_;
    else if (!iterating_)
      predicted_velocity_ = 2.0 * accepted_v_ - earlier_v_;
    damping = added_mass_load(t0 + dt, iterating_ ? loads_velocity_ : predicted_velocity_);
  }
  for (int k = 1; k <= pieces; ++k) {
    check_stop();  // a step in many pieces can take minutes (stop_request.hpp)
    const double t = k == pieces ? t0 + dt : t0 + k * h;
    const fem::PrescribedMotion motion = clamp_motion(model_, t);
    const Eigen::VectorXd* f = &loads_;
    if (k < pieces) {  // see fem_structure.hpp, "Step halving"
      const double s = static_cast<double>(k) / pieces;
      piece_loads_ = accepted_loads_ + s * (loads_ - accepted_loads_) +
                     (1.0 - s) * (unsteady_loads_ - accepted_unsteady_loads_);
      f = &piece_loads_;
    }
    // A sub-iteration after the first starts Newton from the last answer of this step (of
    // this piece): the answer to the given loads is the same to the solver's tolerance
    // (fem_structure.hpp).
    const fem::StepResult r = fem::step(model_.dynamics, *dynamics_, h, *f, &motion,
                                        fem::StepStart::PreviousSolution, accuracy_, damping);
    if (!r.converged) {
      failure = r.failure;
      return false;
    }
    solved_accuracy_ = std::max(solved_accuracy_, r.tolerance_met);
  }
  return true;
}

const fem::NodalLoadDamping* FemStructureData::added_mass_load(double t, const Eigen::Matrix3Xd& reference) {
  const Eigen::Matrix3d R = model_.base_motion(t).rotation;  // the nodes set by linearise_panel_loads
  for (std::size_t i = 0; i < added_mass_.blocks.size(); ++i)
    damping_.blocks[i] = R * added_mass_.blocks[i] * R.transpose();
  damping_.reference_velocity = &reference;
  damping_.scale = 1.0;
  return &damping_;
}

void FemStructureData::linearise_panel_loads(PanelLoadResponse& response) {
  if (model_.attachment.nodes.empty() || !model_.lumped_added_mass || added_mass_dropped_) return;
  added_mass_ = lump_added_mass(model_.attachment, model_.structural.mesh, response,
                                model_.base_motion(dynamics_->time).rotation, model_.surface_nodes());
  damping_.nodes = added_mass_.nodes;
  damping_.blocks.resize(added_mass_.blocks.size());
}

void FemStructureData::solve(double dt) {
  std::string failure;
  for (;;) {
    restore_accepted();
    dynamics_->keep_warm_starts(pieces_);
    solved_accuracy_ = 0.0;
    if (solve_in_pieces(dt, pieces_, failure)) break;
    if (pieces_ >= kMaxFemStepPieces)
      throw StructureFailure("FEM: " + failure + " (the step in " + std::to_string(pieces_) + " pieces)");
    pieces_ *= 2;
    failed_this_step_ = true;
  }
  read_trial();
  pose_is_trial_ = true;
}

void FemStructureData::start_iterate() {
  iterating_ = true;
  iterate_x_ = trial_x_;
  iterate_v_ = trial_v_;
}

void FemStructureData::surface(Eigen::Matrix3Xd& positions, Eigen::Matrix3Xd& velocities) const {
  fem_surface_nodes(model_.attachment, model_.structural.mesh, pose_is_trial_ ? trial_x_ : iterate_x_,
                    pose_is_trial_ ? trial_v_ : iterate_v_, positions, velocities);
}

double FemStructureData::change(double frequency) const {
  const double rate_scale = 2.0 * std::numbers::pi * frequency;  // [rad/s] per flapping radian
  const double dx = (trial_x_ - iterate_x_).lpNorm<Eigen::Infinity>();
  const double dv = (trial_v_ - iterate_v_).lpNorm<Eigen::Infinity>() / rate_scale;
  return std::max(dx, dv) / model_.length_scale;
}

void FemStructureData::residual(Eigen::VectorXd& r) const {
  r = Eigen::Map<const Eigen::VectorXd>(trial_x_.data(), trial_x_.size()) -
      Eigen::Map<const Eigen::VectorXd>(iterate_x_.data(), iterate_x_.size());
}

void FemStructureData::trial_vector(Eigen::VectorXd& x) const {
  const Eigen::Index n = trial_x_.size();
  x.resize(2 * n);
  x.head(n) = Eigen::Map<const Eigen::VectorXd>(trial_x_.data(), n);
  x.tail(n) = Eigen::Map<const Eigen::VectorXd>(trial_v_.data(), n);
}

void FemStructureData::set_iterate(const Eigen::VectorXd& x) {
  const Eigen::Index n = trial_x_.size();
  iterate_x_ = Eigen::Map<const Eigen::Matrix3Xd>(x.data(), 3, n / 3);
  iterate_v_ = Eigen::Map<const Eigen::Matrix3Xd>(x.data() + n, 3, n / 3);
}

void FemStructureData::relax(double omega) {
  iterate_x_ += omega * (trial_x_ - iterate_x_);
  iterate_v_ += omega * (trial_v_ - iterate_v_);
}

bool FemStructureData::refine_after_stall() {
  if (pieces_ >= kMaxFemStepPieces) return false;
  pieces_ *= 2;
  failed_this_step_ = true;  // kept for kFemStepsBeforeJoining steps, as after a failed solve
  return true;
}

void FemStructureData::accept() {
  iterating_ = false;
  earliest_v_ = earlier_v_;
  earlier_v_ = accepted_v_;
  accepted_v_ = trial_v_;
  ++accepted_steps_;
  accepted_ = Saved{dynamics_->state, dynamics_->velocity, dynamics_->acceleration, dynamics_->pseudo_acceleration,
                    dynamics_->time};
  accepted_loads_ = loads_;
  accepted_unsteady_loads_ = unsteady_loads_;
  if (pieces_ > 1) ++split_steps_;
  max_pieces_ = std::max(max_pieces_, pieces_);
  steps_without_failure_ = failed_this_step_ ? 0 : steps_without_failure_ + 1;
  failed_this_step_ = false;
  if (pieces_ > 1 && steps_without_failure_ >= kFemStepsBeforeJoining) {
    pieces_ /= 2;
    steps_without_failure_ = 0;
  }
}

}  // namespace flapsim::fsi
