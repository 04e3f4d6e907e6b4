#include "fem/nonlinear_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/CholmodSupport>

#include "fem/newton_matrix.hpp"
#include "fem/nodal_rotation.hpp"
#include "fem/serial_openmp_regions.hpp"

namespace flapsim::fem {

namespace {
constexpr double kMaxRotationCorrection = 0.3;  ///< largest nodal rotation per Newton correction [rad]
/// A correction asking to turn a node by more than π (or to move it by more than π times the
/// structure's size) linearises nothing: an attempt with a kept matrix that makes one stops
/// at once and the step goes on to full Newton, instead of after max_iterations. Full
/// Newton itself goes on (its corrections scaled to kMaxRotationCorrection): a film's
/// wrinkling step recovered after a single such correction (docs/fem.md, "A kept matrix's
/// Newton that diverges stops").
constexpr double kDivergedCorrection = std::numbers::pi;
constexpr int kParallelNodes = 512;  ///< node loops of a Newton iteration on all threads from this many nodes
}  // namespace

DynamicsModel make_dynamics_model(const CorotationalModel& structure, std::vector<int> driven_nodes,
                                  const DynamicsOptions& options, const std::vector<int>& fixed_dofs) {
  DynamicsModel m;
  m.structure = &structure;
  m.driven_nodes = std::move(driven_nodes);
  m.eliminated = Constraints(structure.num_dofs());
  m.eliminated.clamp_nodes(m.driven_nodes);
  std::vector<int> fixed = fixed_dofs;
  for (int d : film_only_rotation_dofs(structure)) fixed.push_back(d);
  for (int d : fixed) m.eliminated.fix_dof(d);
  std::vector<char> driven(static_cast<size_t>(structure.num_nodes()), 0);
  for (int n : m.driven_nodes) driven[static_cast<size_t>(n)] = 1;
  for (int d : fixed)
    if (!driven[static_cast<size_t>(d / kDofsPerNode)]) m.fixed_not_driven.push_back(d);
  if (structure.num_nodes() > 0) {
    Eigen::Vector3d lo = structure.reference_positions[0], hi = lo;
    for (const auto& p : structure.reference_positions) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    m.size = (hi - lo).norm();
  }
  m.options = options;
  const double r = options.rho_infinity;
  if (!(r >= 0.0 && r <= 1.0)) throw std::invalid_argument("make_dynamics_model: rho_infinity must be in [0, 1]");
  m.alpha_m = (2.0 * r - 1.0) / (r + 1.0);
  m.alpha_f = r / (r + 1.0);
  m.gamma = 0.5 - m.alpha_m + m.alpha_f;
  m.beta = 0.25 * (1.0 - m.alpha_m + m.alpha_f) * (1.0 - m.alpha_m + m.alpha_f);
  return m;
}

PrescribedMotion rigid_prescribed_motion(const DynamicsModel& model, const Eigen::Vector3d& X0,
                                         const Eigen::Vector3d& c, const Eigen::Vector3d& vc,
                                         const Eigen::Vector3d& ac, const Eigen::Matrix3d& Q,
                                         const Eigen::Vector3d& w, const Eigen::Vector3d& al) {
  PrescribedMotion p;
  for (int n : model.driven_nodes) {
    const Eigen::Vector3d r = Q * (model.structure->reference_positions[static_cast<size_t>(n)] - X0);
    p.position.push_back(c + r);
    p.velocity.push_back(vc + w.cross(r));
    p.acceleration.push_back(ac + al.cross(r) + w.cross(w.cross(r)));
    p.rotation.push_back(Q);
    p.angular_velocity.push_back(w);
    p.angular_acceleration.push_back(al);
  }
  return p;
}

struct DynamicsData::Work {
  Work(const CorotationalModel& m, const Constraints& c, TangentForm form)
      : assembler(m, c, form), mass_assembler(m, c, TangentForm::SymmetricLower), form(form) {
    matrices.push_back(KeptMatrix{std::make_unique<NewtonMatrix>(form, assembler.free_dofs())});
  }
  NonlinearAssembler assembler;
  NonlinearAssembler mass_assembler;  ///< only for M_ff at the start
  TangentForm form;
  bool matrix_per_piece = false;  ///< DynamicsOptions::matrix_per_piece
  /// The kept Newton matrices: one; with matrix_per_piece, for a caller that splits its
  /// steps, one per piece (keep_warm_starts, within kKeptMatricesBytes), so that a piece
  /// solved again (the next coupling sub-iteration) finds the matrix made for it.
  struct KeptMatrix {
    std::unique_ptr<NewtonMatrix> matrix;
    double start = 0.0;  ///< t_n of the step (or piece) it was made in [s]
    long made = -1;      ///< the factorisation count when it was made (-1: never)
    /// The last ratio of two successive corrections with it, θ (−1: none measured yet;
    /// DynamicsOptions::contraction_stop).
    double contraction = -1.0;
    double contraction_start = -1.0;  ///< t_n of the step (or piece) it was measured in [s]
  };
  std::vector<KeptMatrix> matrices;
  std::size_t last_made = 0;  ///< the matrix factorised last
  CorotationalState trial;
  Eigen::VectorXd f_int, inertia, r, dx, increment, v1, vdot1, a1;
  Eigen::VectorXd damping_force;  ///< the NodalLoadDamping's load, full numbering [N]
  bool damping_written = false;   ///< damping_force has nonzero entries
  /// The last converged answers (full increments) and the t_n, Δt each was made from: one
  /// by default, one per piece for a caller that splits its steps (keep_warm_starts).
  struct WarmStart {
    Eigen::VectorXd increment;
    double time = 0.0, h = 0.0;
    bool valid = false;
  };
  std::vector<WarmStart> warm_starts;
  std::size_t next_warm_start = 0;  ///< the slot a new answer goes to (round robin)
  Eigen::VectorXd du;              ///< a Newton correction (full)
  Eigen::VectorXd increment0, a10, v10, vdot10;  ///< the iterate a line search starts from
  std::vector<Eigen::Matrix3d> rotation0;        ///< its trial rotations
  std::vector<char> rotations_free;  ///< per node: its three rotations are free
  Eigen::VectorXd last_dx;  ///< the last Newton correction applied (free DOFs)
};

void DynamicsData::keep_warm_starts(int count) {
  Work& w = *work_;
  const std::size_t n = static_cast<std::size_t>(std::max(1, count));
  if (n <= w.warm_starts.size()) return;
  const Eigen::Index dofs = w.warm_starts.front().increment.size();
  w.warm_starts.resize(n);
  for (Work::WarmStart& k : w.warm_starts) k.increment.resize(dofs);
  // With matrix_per_piece as many kept matrices as pieces, within kKeptMatricesBytes (the
  // first one's factor size, once it has been made; before, one).
  if (!w.matrix_per_piece) return;
  const double bytes = w.matrices.front().matrix->factor_bytes();
  const std::size_t fit = bytes > 0.0 ? static_cast<std::size_t>(std::max(1.0, kKeptMatricesBytes / bytes)) : 1;
  while (w.matrices.size() < std::min(n, fit))
    w.matrices.push_back(Work::KeptMatrix{std::make_unique<NewtonMatrix>(w.form, w.assembler.free_dofs())});
}

DynamicsData::DynamicsData(const DynamicsModel& model, const CorotationalState& s, const Eigen::VectorXd& v0,
                           const Eigen::VectorXd& f_ext0)
    : state(s), velocity(v0), work_(std::make_unique<Work>(*model.structure, model.eliminated, model.options.tangent)) {
  const CorotationalModel& cm = *model.structure;
  const int n = cm.num_dofs();
  if (v0.size() != n || f_ext0.size() != n)
    throw std::invalid_argument("DynamicsData: velocity or load size does not match the DOF count");
  Work& w = *work_;
  w.trial = s;
  w.matrix_per_piece = model.options.matrix_per_piece;
  w.f_int.resize(n);
  w.inertia.resize(n);
  w.damping_force.setZero(n);
  w.increment.resize(n);
  w.v1.resize(n);
  w.vdot1.resize(n);
  w.a1.resize(n);
  w.warm_starts.resize(1);
  w.warm_starts.front().increment.resize(n);
  w.du.resize(n);
  w.rotations_free.assign(static_cast<std::size_t>(cm.num_nodes()), 0);
  w.rotation0.resize(static_cast<std::size_t>(cm.num_nodes()));
  w.increment0.resize(n);
  w.a10.resize(n);
  w.v10.resize(n);
  w.vdot10.resize(n);
  for (int node = 0; node < cm.num_nodes(); ++node)
    w.rotations_free[static_cast<std::size_t>(node)] =
        !model.eliminated.is_fixed(kDofsPerNode * node + 3) && !model.eliminated.is_fixed(kDofsPerNode * node + 4) &&
        !model.eliminated.is_fixed(kDofsPerNode * node + 5);
  const auto& free = w.assembler.free_dofs();
  w.r.resize(static_cast<Eigen::Index>(free.size()));
  w.last_dx.resize(static_cast<Eigen::Index>(free.size()));
  w.dx.resize(static_cast<Eigen::Index>(free.size()));
  acceleration = Eigen::VectorXd::Zero(n);
  w.assembler.evaluate(state, w.f_int, false);
  if (!free.empty()) {
    w.mass_assembler.load_mass_into_tangent();
    const SerialOpenMpRegions cholmod_on_this_thread;  // CHOLMOD's fixed 4-thread teams
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> mllt;
    mllt.cholmod().print = 0;  // the reason below, not CHOLMOD's own warning on stderr
    mllt.compute(w.mass_assembler.tangent());
    if (mllt.info() != Eigen::Success)
      throw std::runtime_error("DynamicsData: the free mass matrix is singular (a node or rotation without mass: "
                               "the wing file's thicknesses, densities or vein sizes at or near zero)");
    for (size_t i = 0; i < free.size(); ++i) w.r(static_cast<Eigen::Index>(i)) = f_ext0(free[i]) - w.f_int(free[i]);
    w.dx = mllt.solve(w.r);
    for (size_t i = 0; i < free.size(); ++i) acceleration(free[i]) = w.dx(static_cast<Eigen::Index>(i));
  }
  pseudo_acceleration = acceleration;
}

DynamicsData::~DynamicsData() = default;

double DynamicsData::strain_energy() const { return work_->assembler.evaluate(state, work_->f_int, false); }

double DynamicsData::kinetic_energy() const {
  const SparseMatrix& M = work_->assembler.model().mass;
  return 0.5 * velocity.dot(M * velocity);
}

namespace {

/// The rotation of the driven base (its first driven node) in a state; I without one.
Eigen::Matrix3d base_frame(const DynamicsModel& model, const CorotationalState& s) {
  return model.driven_nodes.empty() ? Eigen::Matrix3d::Identity()
                                    : s.rotation[static_cast<std::size_t>(model.driven_nodes.front())];
}

}  // namespace

StepResult step(const DynamicsModel& model, DynamicsData& d, double h, const Eigen::VectorXd& f_ext,
                const PrescribedMotion* pm, StepStart start, double tolerance_scale,
                const NodalLoadDamping* damping) {
  const CorotationalModel& cm = *model.structure;
  DynamicsData::Work& w = *d.work_;
  const std::vector<int>& free = w.assembler.free_dofs();
  const Eigen::Index nf = static_cast<Eigen::Index>(free.size());
  if (f_ext.size() != cm.num_dofs()) throw std::invalid_argument("step: load vector size does not match the DOF count");
  if (pm != nullptr && pm->position.size() != model.driven_nodes.size())
    throw std::invalid_argument("step: one prescribed motion per driven node is required");
  if (!(tolerance_scale >= 1.0)) throw std::invalid_argument("step: tolerance_scale must be at least 1");
  if (damping != nullptr && (damping->nodes.size() != damping->blocks.size() ||
                             damping->reference_velocity == nullptr ||
                             damping->reference_velocity->cols() != cm.num_nodes()))
    throw std::invalid_argument("step: the load damping needs a block per node and a velocity per model node");
  // The damping's rate (d − d_n)/h needs each element's deformation at this step's start.
  if (model.options.stiffness_damping != 0.0) w.assembler.record_step_start(d.state);
  if (w.damping_written) w.damping_force.setZero();
  w.damping_written = damping != nullptr;
  // The kept matrix to start with: the one made for this step (or piece: the same t_n and
  // Δt) if there is one, else the last one made; a new one goes to the former, else to the
  // matrix made longest ago.
  std::size_t own = w.matrices.size(), use = w.last_made;
  for (std::size_t i = 0; i < w.matrices.size(); ++i)
    if (w.matrices[i].made >= 0 && w.matrices[i].start == d.time && w.matrices[i].matrix->step_size() == h) own = i;
  if (own < w.matrices.size()) {
    use = own;
  } else {
    own = 0;
    for (std::size_t i = 1; i < w.matrices.size(); ++i)
      if (w.matrices[i].made < w.matrices[own].made) own = i;
  }
  // One Newton solve of the step: from the warm start or the predictor, with the kept
  // matrix (reuse) or a fresh one every iteration.
  auto newton_step = [&](const DynamicsData::Work::WarmStart* warm, bool reuse) -> StepResult {
    SolverCounters& count = d.counters_;
    const double am = model.alpha_m, af = model.alpha_f, be = model.beta, ga = model.gamma;
    StepResult res;

    // Predictor (the increment q_n → q_{n+1}; the rates follow from the scheme):
    // - warm: the last converged answer of this step;
    // - rigid: every node carried with the base's rigid increment (rotation ΔQ about the first
    //   driven node p): x̃ = p_{n+1} + ΔQ (x_n − p_n), R̃ = ΔQ R_n; the deformation seen from the
    //   base is kept, so a flapping wing starts where its base has taken it;
    // - else q_{n+1} = q_n. (Extrapolating with v̇_n put the stiff, unresolved modes, rotations
    //   of small rotary inertia with ωh ≫ 1, far off and Newton diverged.)
    if (warm != nullptr) {
      w.increment = warm->increment;
    } else if (model.options.rigid_predictor && pm != nullptr && !model.driven_nodes.empty()) {
      const auto p0 = static_cast<std::size_t>(model.driven_nodes.front());
      const Eigen::Matrix3d dQ = pm->rotation.front() * d.state.rotation[p0].transpose();
      const Eigen::Vector3d spin = rotation_vector(dQ);
      for (std::size_t i = 0; i < d.state.position.size(); ++i) {
        const Eigen::Index o = static_cast<Eigen::Index>(kDofsPerNode * i);
        w.increment.segment<3>(o) =
            pm->position.front() + dQ * (d.state.position[i] - d.state.position[p0]) - d.state.position[i];
        w.increment.segment<3>(o + 3) = spin;
      }
    } else {
      w.increment.setZero();
    }
    for (int i : model.fixed_not_driven) w.increment(i) = 0.0;
    w.a1 = (w.increment / h - d.velocity - h * (0.5 - be) * d.pseudo_acceleration) / (h * be);
    w.v1 = d.velocity + h * (1.0 - ga) * d.pseudo_acceleration + h * ga * w.a1;
    w.vdot1 = ((1.0 - am) * w.a1 + am * d.pseudo_acceleration - af * d.acceleration) / (1.0 - af);
    // Driven nodes: their motion at t_{n+1} as given (or at rest where they are). The node
    // loops here and in apply are shared between the threads node by node (the same bits).
    const int nodes = static_cast<int>(d.state.position.size());
    auto place = [&]() {
#pragma omp parallel for schedule(static) if (nodes > kParallelNodes)
      for (int n = 0; n < nodes; ++n) {
        const auto i = static_cast<size_t>(n);
        w.trial.position[i] = d.state.position[i] + w.increment.segment<3>(static_cast<Eigen::Index>(6 * i));
        w.trial.rotation[i] =
            rotation_matrix(w.increment.segment<3>(static_cast<Eigen::Index>(6 * i + 3))) * d.state.rotation[i];
      }
      for (size_t k = 0; k < model.driven_nodes.size(); ++k) {
        const int n = model.driven_nodes[k];
        if (pm != nullptr) {
          w.trial.position[n] = pm->position[k];
          w.trial.rotation[n] = pm->rotation[k];
        } else {
          w.trial.position[n] = d.state.position[n];
          w.trial.rotation[n] = d.state.rotation[n];
        }
      }
    };
    for (size_t k = 0; k < model.driven_nodes.size(); ++k) {
      const Eigen::Index o = 6 * model.driven_nodes[k];
      if (pm != nullptr) {
        w.v1.segment<3>(o) = pm->velocity[k];
        w.v1.segment<3>(o + 3) = pm->angular_velocity[k];
        w.vdot1.segment<3>(o) = pm->acceleration[k];
        w.vdot1.segment<3>(o + 3) = pm->angular_acceleration[k];
      } else {
        w.v1.segment<6>(o).setZero();
        w.vdot1.segment<6>(o).setZero();
      }
      w.a1.segment<6>(o) = ((1.0 - af) * w.vdot1.segment<6>(o) + af * d.acceleration.segment<6>(o) -
                            am * d.pseudo_acceleration.segment<6>(o)) / (1.0 - am);
    }
    // Fixed (not driven) DOFs stay put.
    for (int i : model.fixed_not_driven) w.increment(i) = w.v1(i) = w.vdot1(i) = w.a1(i) = 0.0;
    place();
    const Eigen::Matrix3d frame = base_frame(model, w.trial);

    const double cM = (1.0 - am) / ((1.0 - af) * be * h * h);  // ∂v̇/∂u [1/s²]
    const double cV = ga / (be * h);                           // ∂v/∂u [1/s]
    TangentExtras ex;
    ex.mass_scale = cM;
    ex.damping = model.options.stiffness_damping;
    ex.damping_rate = ex.damping != 0.0 ? 1.0 / h : 0.0;
    double previous = 0.0;  // the last correction's size
    bool refactor = false;
    bool corrected = false;  // a correction of this solve has been applied (w.last_dx)
    // The correction moves the trial: x ← x + δx and, on a node whose three rotations are
    // free, R ← exp(δω̂) R, the update the tangent linearises (spatial spins); the step's
    // rotation increment is then log(R R_nᵀ) (Arnold & Brüls 2007). Adding δω to the
    // increment instead is off by ½ hΔ × δω, and Newton converged linearly at that rate.
    // Apply α δx (δx = w.dx) from the iterate (increment0, rotation0, rates).
    auto apply = [&](double alpha) {
      w.du.setZero();
      for (Eigen::Index i = 0; i < nf; ++i) w.du(free[static_cast<size_t>(i)]) = alpha * w.dx(i);
#pragma omp parallel for schedule(static) if (nodes > kParallelNodes)
      for (int n = 0; n < nodes; ++n) {
        const auto node = static_cast<std::size_t>(n);
        if (!w.rotations_free[node]) continue;
        const Eigen::Index o = static_cast<Eigen::Index>(kDofsPerNode * node + 3);
        const Eigen::Matrix3d R = rotation_matrix(w.du.segment<3>(o)) * w.rotation0[node];
        w.du.segment<3>(o) = rotation_vector(R * d.state.rotation[node].transpose()) - w.increment0.segment<3>(o);
      }
      for (int g : free) {
        const double du = w.du(g);
        w.increment(g) = w.increment0(g) + du;
        w.a1(g) = w.a10(g) + du / (be * h * h);
        w.v1(g) = w.v10(g) + cV * du;
        w.vdot1(g) = w.vdot10(g) + cM * du;
      }
      place();
    };
    for (int it = 0; it <= model.options.max_iterations; ++it) {
      // A new matrix: none kept, another Δt, full Newton, the kept one contracted too
      // slowly in the last iteration, or (with the linearised geometric terms) it was made
      // in another step and has given this solve its one correction (its next one grows:
      // docs/fem.md, "Cost").
      DynamicsData::Work::KeptMatrix& kept = w.matrices[use];
      const bool new_matrix = !reuse || !kept.matrix->valid() || kept.matrix->step_size() != h || refactor ||
                              (model.options.linearised_geometric_force && corrected && kept.start != d.time);
      refactor = false;
      // A new matrix after a correction: its geometric terms from the elements' forces at
      // the correction's end taken linearly (DynamicsOptions::linearised_geometric_force). The
      // correction's path is retraced from its start (increment0, rotation0) to record the
      // elements' deformations; the trial ends where it was (a line search's α excepted:
      // there the full correction's path is used).
      ex.linearised_geometric_force =
          new_matrix && corrected && model.options.linearised_geometric_force && !model.options.line_search;
      if (ex.linearised_geometric_force) {
        w.dx.swap(w.last_dx);
        for (int point = 0; point < 3; ++point) {
          apply(0.5 * point);
          w.assembler.record_correction_path(w.trial, point);
        }
        w.dx.swap(w.last_dx);
      }
      w.assembler.evaluate(w.trial, w.f_int, new_matrix, ex);
      ex.linearised_geometric_force = false;
      if (new_matrix && damping != nullptr)
        w.assembler.add_translation_blocks(damping->nodes, damping->blocks, damping->scale * cV);
      auto residual = [&](double& scale) {
        w.inertia.noalias() = cm.mass * w.vdot1;
        if (damping != nullptr) {  // s D (v − v_ref), taken from the loads below
          for (std::size_t k = 0; k < damping->nodes.size(); ++k) {
            const int node = damping->nodes[k];
            w.damping_force.segment<3>(dof_index(node, UX)) =
                damping->scale * damping->blocks[k] *
                (w.v1.segment<3>(dof_index(node, UX)) - damping->reference_velocity->col(node));
          }
        }
        double fe = 0.0, fi = 0.0, fm = 0.0;
        for (Eigen::Index i = 0; i < nf; ++i) {
          const int g = free[static_cast<size_t>(i)];
          w.r(i) = f_ext(g) - w.f_int(g) - w.inertia(g) - w.damping_force(g);
          fe += f_ext(g) * f_ext(g);
          fi += w.f_int(g) * w.f_int(g);
          fm += w.inertia(g) * w.inertia(g);
        }
        scale = std::sqrt(std::max({fe, fi, fm}));
        return w.r.norm();
      };
      double scale = 0.0;
      const double rn = residual(scale);
      res.residual = scale > 0.0 ? rn / scale : rn;
      if (!std::isfinite(rn)) {
        res.failure = "t = " + std::to_string(d.time + h) + " s: the residual is not finite";
        return res;
      }
      if (rn <= tolerance_scale * model.options.tolerance * scale || rn == 0.0) {
        res.converged = true;
        res.tolerance_met = rn == 0.0 ? 0.0 : rn / (model.options.tolerance * scale);
        break;
      }
      if (it == model.options.max_iterations) break;
      if (new_matrix) {
        use = own;
        DynamicsData::Work::KeptMatrix& made = w.matrices[own];
        ++count.factorizations;
        made.start = d.time;
        made.made = count.factorizations;
        made.contraction = -1.0;
        w.last_made = own;
        const long fallbacks = made.matrix->lu_fallbacks();
        const bool factorised = made.matrix->factorize(w.assembler.tangent(), frame, h);
        count.lu_fallbacks += made.matrix->lu_fallbacks() - fallbacks;
        if (!factorised) {
          res.failure = "t = " + std::to_string(d.time + h) + " s, iteration " + std::to_string(it) +
                        ": the Newton matrix is singular";
          return res;
        }
      }
      w.matrices[use].matrix->solve(w.r, frame, w.dx);
      ++count.iterations;
      double max_t = 0.0, max_r = 0.0;
      for (Eigen::Index i = 0; i < nf; ++i) {
        const bool translation = free[static_cast<size_t>(i)] % kDofsPerNode < 3;
        double& m = translation ? max_t : max_r;
        m = std::max(m, std::abs(w.dx(i)));
      }
      const double tol_u = tolerance_scale * model.options.increment_tolerance;
      const double size = std::max(max_t / model.size, max_r);
      // Converged when the error left after this correction is within the bound: the
      // correction itself at most tol_u (the bound for the slowest contraction a kept matrix
      // is allowed, ρ), or, for the first correction of a solve again of a step whose matrix
      // contracted by θ there, η ‖δx‖ ≤ ρ/(1 − ρ) tol_u, η = (θ/(1 − θ))^0.8
      // (DynamicsOptions::contraction_stop).
      DynamicsData::Work::KeptMatrix& solving = w.matrices[use];
      const double theta = !new_matrix && it > 0 && previous > 0.0 ? size / previous : -1.0;
      // (a kept matrix is of this Δt: another one's is made anew above)
      const bool measured_here =
          solving.contraction >= 0.0 && solving.contraction < 1.0 && solving.contraction_start == d.time;
      const double eta = model.options.contraction_stop && !model.options.line_search && !new_matrix && it == 0 &&
                                 measured_here
                             ? std::pow(solving.contraction / (1.0 - solving.contraction), 0.8)
                             : -1.0;
      if (theta >= 0.0) {
        solving.contraction = theta;
        solving.contraction_start = d.time;
      }
      const double rho = std::min(model.options.refactor_rate, 0.9);
      const bool small_increment = (max_t <= tol_u * model.size && max_r <= tol_u) ||
                                   (eta >= 0.0 && max_r <= kMaxRotationCorrection &&
                                    eta * size <= rho / (1.0 - rho) * tol_u);
      // Contraction of a kept matrix: the ratio of successive corrections (the residual's
      // ratio is no measure: the first correction of a thin membrane stretches it and
      // raises the residual, by 20–200 on the hawkmoth, whatever the matrix). Too slow: a
      // new matrix at this iterate; growing: this correction is dropped as well.
      if (!new_matrix && it > 0 && !small_increment && size > model.options.refactor_rate * previous) {
        refactor = true;
        if (size > previous) continue;
      }
      if (reuse && size > kDivergedCorrection) {
        res.failure = "t = " + std::to_string(d.time + h) + " s, iteration " + std::to_string(it) +
                      ": Newton with a kept matrix diverges (a correction of " + std::to_string(size) + " rad)";
        return res;
      }
      previous = size;
      // A correction that turns a node by more than kMaxRotationCorrection is
      // scaled down to it: far from the solution, the linearisation of the
      // rotations (exp(ω̂) ≈ I + ω̂) no longer holds and full corrections ran off.
      if (max_r > kMaxRotationCorrection) w.dx *= kMaxRotationCorrection / max_r;
      w.last_dx = w.dx;
      corrected = true;
      w.increment0 = w.increment;
      w.a10 = w.a1;
      w.v10 = w.v1;
      w.vdot10 = w.vdot1;
      for (std::size_t node = 0; node < w.rotations_free.size(); ++node) w.rotation0[node] = w.trial.rotation[node];
      apply(1.0);
      if (model.options.line_search && !small_increment) {
        // s(α) = δxᵀ r(q + α δx): the slope of the step's incremental potential along the
        // correction (Crisfield 1991, §9.3); a full step is kept when |s(1)| ≤ ½ s(0).
        const double s0 = w.dx.dot(w.r);
        double lo = 0.0, s_lo = s0, hi = 1.0;
        auto slope = [&]() {
          w.assembler.evaluate(w.trial, w.f_int, false, ex);
          double scale_unused = 0.0;
          residual(scale_unused);
          return w.dx.dot(w.r);
        };
        double s_hi = slope();
        if (s0 > 0.0 && std::isfinite(s_hi) && std::abs(s_hi) > 0.5 * s0 && s_hi < 0.0) {
          double alpha = 1.0;
          for (int k = 0; k < 8; ++k) {
            alpha = lo + (hi - lo) * s_lo / (s_lo - s_hi);  // regula falsi on the bracket
            alpha = std::clamp(alpha, lo + 0.05 * (hi - lo), hi - 0.05 * (hi - lo));
            apply(alpha);
            const double sa = slope();
            if (std::abs(sa) <= 0.5 * s0) break;
            if (sa > 0.0) { lo = alpha; s_lo = sa; } else { hi = alpha; s_hi = sa; }
          }
        }
      }
      if (small_increment) {
        res.iterations = it + 1;
        res.converged = true;
        // The same two tests at the scale they pass with (1: the full accuracy).
        const double tol_1 = model.options.increment_tolerance;
        res.tolerance_met = std::max(max_t / (tol_1 * model.size), max_r / tol_1);
        if (eta >= 0.0 && max_r <= kMaxRotationCorrection)
          res.tolerance_met = std::min(res.tolerance_met, eta * size / (rho / (1.0 - rho) * tol_1));
        break;
      }
    }
    if (!res.converged) {
      res.failure = "t = " + std::to_string(d.time + h) + " s: Newton did not converge in " +
                    std::to_string(model.options.max_iterations) + " iterations (relative residual " +
                    std::to_string(res.residual) + ")";
      return res;
    }
    return res;
  };

  DynamicsData::Work::WarmStart* same_step = nullptr;  // an earlier answer of this step (t_n and Δt)
  for (DynamicsData::Work::WarmStart& k : w.warm_starts)
    if (k.valid && k.time == d.time && k.h == h) same_step = &k;
  const DynamicsData::Work::WarmStart* warm = start == StepStart::PreviousSolution ? same_step : nullptr;
  // With a kept Newton matrix first; if that fails, once more with a fresh matrix every
  // iteration (full Newton).
  StepResult res = newton_step(warm, model.options.reuse_factorization);
  if (!res.converged && model.options.reuse_factorization) {
    ++d.counters_.retries;
    const int before = res.iterations;
    res = newton_step(nullptr, false);
    res.iterations += before;
  }
  if (!res.converged) return res;
  DynamicsData::Work::WarmStart* slot = same_step;  // the same step's answer is replaced, else the oldest
  if (slot == nullptr) {
    slot = &w.warm_starts[w.next_warm_start];
    w.next_warm_start = (w.next_warm_start + 1) % w.warm_starts.size();
  }
  slot->increment = w.increment;
  slot->time = d.time;
  slot->h = h;
  slot->valid = true;
  std::swap(d.state, w.trial);
  w.trial = d.state;  // same sizes: no allocation
  std::swap(d.velocity, w.v1);
  std::swap(d.acceleration, w.vdot1);
  std::swap(d.pseudo_acceleration, w.a1);
  d.time += h;
  ++d.counters_.steps;
  return res;
}

}  // namespace flapsim::fem
