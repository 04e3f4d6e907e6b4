#include "pipeline/fsi/chain_structure.hpp"

#include <numbers>

#include "mbd/chain_energy.hpp"
#include "mbd/chain_kinematics.hpp"
#include "mbd/convergence_failure.hpp"
#include "pipeline/fsi/load_transfer.hpp"
#include "pipeline/fsi/panel_load_response.hpp"
#include "pipeline/fsi/phase_analysis.hpp"
#include "pipeline/fsi/tip_deflection.hpp"

namespace flapsim::fsi {

std::unique_ptr<StructureData> ChainStructureModel::make_data() const {
  return std::make_unique<ChainStructureData>(*this);
}

ChainStructureData::ChainStructureData(const ChainStructureModel& model)
    : chain(model.chain), loads(model.chain.num_bodies()), model_(model),
      change_loads_(model.chain.num_bodies()) {}

void ChainStructureData::initialize(double t0) {
  const int n = model_.chain.num_dofs();
  const Eigen::VectorXd q0 = model_.initial_q.size() == n ? model_.initial_q : model_.chain.rest_angles();
  const Eigen::VectorXd v0 = model_.initial_v.size() == n ? model_.initial_v : Eigen::VectorXd::Zero(n);
  set_external_loads(t0);
  try {
    state = mbd::make_initial_state(model_.chain, chain, model_.base_motion, t0, q0, v0, loads);
  } catch (const mbd::ConvergenceFailure& e) {
    throw StructureFailure("multibody: " + e.reason());
  }
  trial = state;
  relaxed = state;
}

void ChainStructureData::set_external_loads(double t) {
  loads.clear();
  if (model_.external_loads) model_.external_loads(t, loads);
}

void ChainStructureData::add_panel_loads(const uvlm::PanelLoads& panels) {
  fsi::add_panel_loads(model_.attachment, chain, panels, loads);
}

void ChainStructureData::prescribe(double t) {
  const Eigen::VectorXd none;
  mbd::forward_kinematics(model_.chain, chain, model_.base_motion(t), none, none);
  state.time = t;
  state.step += 1;
}

void ChainStructureData::solve(double dt) {
  // The loads were found at the iterate: the added mass acts on the step's departure from it.
  if (chain.load_damping.active) chain.load_damping.reference = relaxed.v;
  try {
    mbd::advance(model_.chain, chain, model_.base_motion, model_.integrator, state, dt, loads, trial);
  } catch (const mbd::ConvergenceFailure& e) {
    throw StructureFailure("multibody: " + e.reason());
  }
}

// D = −∂Q/∂Φ̇ of the lattice's added-mass response at the iterate's pose (the one the lattice
// was solved on): column j from the node velocities of Φ̇ + e_j less those of Φ̇ (exactly
// linear in Φ̇ at a pose), their force change, and its generalized force at the pose.
void ChainStructureData::linearise_panel_loads(PanelLoadResponse& response) {
  const int n = model_.chain.num_dofs();
  if (n == 0 || model_.attachment.nodes.empty()) return;
  // Sub-steps: the term would act in none of them (mbd::LoadDamping acts in a step solved whole).
  if (model_.integrator.substeps > 1) return;
  const mbd::BasePose pose = model_.base_motion(relaxed.time);
  const int nodes = model_.surface_nodes();
  for (Eigen::Matrix3Xd* m : {&base_positions_, &base_velocities_, &unit_positions_, &unit_velocities_})
    m->resize(3, nodes);
  mbd::forward_kinematics(model_.chain, chain, pose, relaxed.q, relaxed.v);
  deformed_nodes(model_.attachment, chain, base_positions_, base_velocities_);
  change_loads_.clear();
  mbd::compute_generalized_loads(model_.chain, chain, change_loads_);  // gravity alone
  gravity_load_ = chain.generalized_load;
  panel_change_.point = response.points();
  pressure_damping_.resize(n, n);
  edge_columns_.resize(static_cast<std::size_t>(n));
  edge_response_ = response.edge_responds();
  for (int j = 0; j < n; ++j) {
    rates_ = relaxed.v;
    rates_(j) += 1.0;
    mbd::forward_kinematics(model_.chain, chain, pose, relaxed.q, rates_);
    deformed_nodes(model_.attachment, chain, unit_positions_, unit_velocities_);
    node_change_ = unit_velocities_ - base_velocities_;
    response.force_change(node_change_, panel_change_.force, edge_columns_[static_cast<std::size_t>(j)]);
    change_loads_.clear();
    fsi::add_panel_loads(model_.attachment, chain, panel_change_, change_loads_);
    mbd::compute_generalized_loads(model_.chain, chain, change_loads_);
    pressure_damping_.col(j) = gravity_load_ - chain.generalized_load;
  }
  mbd::forward_kinematics(model_.chain, chain, pose, relaxed.q, relaxed.v);  // the iterate's pose again
  has_added_mass_ = true;
  set_damping(response);
}

void ChainStructureData::refresh_panel_load_response(PanelLoadResponse& response) {
  if (!has_added_mass_ || !edge_response_) return;
  mbd::forward_kinematics(model_.chain, chain, model_.base_motion(relaxed.time), relaxed.q, relaxed.v);
  change_loads_.clear();
  mbd::compute_generalized_loads(model_.chain, chain, change_loads_);  // gravity alone
  gravity_load_ = chain.generalized_load;
  set_damping(response);
}

// D = the held part + the leading-edge force's columns evaluated at the lattice's last
// solve, transferred at the iterate's pose (the chain's kinematics; gravity_load_ of it).
void ChainStructureData::set_damping(PanelLoadResponse& response) {
  mbd::LoadDamping& damping = chain.load_damping;
  damping.matrix = pressure_damping_;
  if (edge_response_) {
    panel_change_.point = response.points();
    for (int j = 0; j < damping.matrix.cols(); ++j) {
      response.edge_force_change(edge_columns_[static_cast<std::size_t>(j)], panel_change_.force);
      change_loads_.clear();
      fsi::add_panel_loads(model_.attachment, chain, panel_change_, change_loads_);
      mbd::compute_generalized_loads(model_.chain, chain, change_loads_);
      damping.matrix.col(j) += gravity_load_ - chain.generalized_load;
    }
  }
  damping.active = true;  // its reference rate: the iterate's at each solve()
}

void ChainStructureData::pose_iterate() {
  mbd::forward_kinematics(model_.chain, chain, model_.base_motion(trial.time), relaxed.q, relaxed.v);
}

void ChainStructureData::surface(Eigen::Matrix3Xd& positions, Eigen::Matrix3Xd& velocities) const {
  deformed_nodes(model_.attachment, chain, positions, velocities);
}

double ChainStructureData::change(double frequency) const {
  const double rate_scale = 2.0 * std::numbers::pi * frequency;  // [rad/s] per flapping radian
  const double dq = (trial.q - relaxed.q).lpNorm<Eigen::Infinity>();
  const double dv = (trial.v - relaxed.v).lpNorm<Eigen::Infinity>() / rate_scale;
  return std::max(dq, dv);
}

void ChainStructureData::residual(Eigen::VectorXd& r) const { r = trial.qdd - relaxed.qdd; }

// (Φ, Φ̇, Φ̈, a) as one vector, and back (time and step stay those of the trial).
void ChainStructureData::trial_vector(Eigen::VectorXd& x) const {
  const Eigen::Index n = trial.q.size();
  x.resize(4 * n);
  x << trial.q, trial.v, trial.qdd, trial.a;
}

void ChainStructureData::set_iterate(const Eigen::VectorXd& x) {
  const Eigen::Index n = relaxed.q.size();
  relaxed.q = x.segment(0, n);
  relaxed.v = x.segment(n, n);
  relaxed.qdd = x.segment(2 * n, n);
  relaxed.a = x.segment(3 * n, n);
  relaxed.time = trial.time;
  relaxed.step = trial.step;
}

void ChainStructureData::relax(double omega) {
  relaxed.q += omega * (trial.q - relaxed.q);
  relaxed.v += omega * (trial.v - relaxed.v);
  relaxed.qdd += omega * (trial.qdd - relaxed.qdd);
  relaxed.a += omega * (trial.a - relaxed.a);
  relaxed.time = trial.time;
  relaxed.step = trial.step;
}

const ChainStructureModel& chain_structure(const StructureModel& model) {
  if (const auto* c = dynamic_cast<const ChainStructureModel*>(&model)) return *c;
  throw std::logic_error("chain_structure: the run's structure is not a bar chain");
}

const ChainStructureData& chain_structure(const StructureData& data) {
  if (const auto* c = dynamic_cast<const ChainStructureData*>(&data)) return *c;
  throw std::logic_error("chain_structure: the run's structure is not a bar chain");
}

StructureReadout ChainStructureData::readout() const {
  const mbd::ChainModel& c = model_.chain;
  StructureReadout r;
  const auto relative = [&](int body) -> Eigen::Matrix3d {
    return chain.bodies[static_cast<std::size_t>(body)].rotation * c.root_rotation.transpose();
  };
  r.tip_rotation = relative(c.num_bodies() - 1);
  r.tip_position = mbd::point_position(chain, c.num_bodies() - 1, c.bodies.back().outboard_joint);
  r.outer_rotation = relative(outer_body(c));
  if (state.q.size() > 0) {
    // The tip body's rotation relative to its rest orientation, in W: R_WR Π(Φ) Π(Φ_rest)ᵀ
    // R_WRᵀ with Π(Φ) = Π_k Rx(θ_k) Ry(α_k) over the joints (welded bodies add nothing),
    // read as the FEM's tip section is (tip_deflection.hpp).
    const auto joints = [](const Eigen::VectorXd& q) {
      Eigen::Matrix3d p = Eigen::Matrix3d::Identity();
      for (Eigen::Index k = 0; k + 1 < q.size(); k += 2) p = p * mbd::joint_rotation(q(k), q(k + 1));
      return p;
    };
    const TipDeflection tip = tip_deflection(c.root_rotation * joints(state.q) *
                                             joints(c.rest_angles()).transpose() * c.root_rotation.transpose());
    r.tip_bend = tip.bend;
    r.tip_twist = tip.twist;
  }
  const mbd::BasePose pose = model_.base_motion(time());
  const mbd::BaseReaction reaction = mbd::base_reaction(c, chain, pose, loads);
  r.drive_force = reaction.force;
  r.drive_moment = reaction.moment;
  r.drive_power = mbd::base_power(c, chain, pose, loads);
  return r;
}

}  // namespace flapsim::fsi
