#pragma once
/// \file nonlinear_dynamics.hpp
/// \brief Geometrically nonlinear dynamics of the co-rotational FEM: implicit
/// generalized-α (Chung & Hulbert 1993) in the Lie-group form of Arnold &
/// Brüls 2007 (equilibrium at t_{n+1}, pseudo-accelerations a), Newton
/// iterations on the free DOFs with the symbolic analysis of the Newton matrix
/// done once (CHOLMOD supernodal LLᵀ of the symmetrised tangent, or sparse LU:
/// DynamicsOptions::tangent) and the factor kept across steps, no allocation in
/// the step (CHOLMOD's and SparseLU's own buffers, and the rare LU fallback,
/// excepted).
///
/// Per step (h = Δt, q ⊕ w: x + w_t and exp(ŵ_r) R):
///   q_{n+1} = q_n ⊕ h Δ,  Δ = v_n + h(½ − β) a_n + hβ a_{n+1}
///   v_{n+1} = v_n + h(1 − γ) a_n + hγ a_{n+1}
///   (1 − α_m) a_{n+1} + α_m a_n = (1 − α_f) v̇_{n+1} + α_f v̇_n
///   M v̇_{n+1} + f_int(q_{n+1}, v_{n+1}) = f_ext(t_{n+1})
/// with α_m = (2ρ∞ − 1)/(ρ∞ + 1), α_f = ρ∞/(ρ∞ + 1), γ = ½ − α_m + α_f,
/// β = ¼(1 − α_m + α_f)². Velocities are (ẋ, ω) with ω the spatial angular
/// velocity; the mass (nonlinear_assembly.hpp) is rotation-invariant and the
/// nodal rotary inertia isotropic, so M v̇ is the exact inertial force, with
/// no gyroscopic term. The Newton matrix is c_M M + K_T (+ damping) with
/// c_M = (1 − α_m)/((1 − α_f)βh²); the tangent operator of exp on the
/// rotation increment (I + O(h|ω|)) is left out of it.
///
/// Newton (docs/fem.md, "Cost"):
/// - Predictor: the free nodes carried rigidly with the driven base from t_n to
///   t_{n+1} (the rotation and translation of the first driven node), the
///   deformation in the base frame kept; or q_n at rest (no driven motion); or
///   the last converged answer of the same step (StepStart::PreviousSolution,
///   for the sub-iterations of a coupled step).
/// - Modified Newton: the factorised Newton matrix (newton_matrix.hpp) is kept
///   across iterations and steps, turned with the base's rotation, and made
///   anew from the current tangent when the residual falls by less than
///   DynamicsOptions::refactor_rate in an iteration, when h changes, or when a
///   step with the kept matrix fails (the step is then redone with a fresh
///   matrix every iteration). A new matrix made after a correction takes its
///   geometric terms from the elements' forces along that correction taken
///   linearly (DynamicsOptions::linearised_geometric_force); with them, a matrix
///   made in another step (or piece) gives a solve one correction, then a new
///   one is made.
/// - CHOLMOD LLᵀ of the symmetrised tangent by default, sparse LU when LLᵀ
///   finds it not positive definite (a frame released from a large deflection:
///   measured in docs/fem.md), or the consistent tangent by LU on request.
///
/// Base motion. The wing moves with its prescribed base motion in the ground
/// frame: the clamp nodes are driven (position, rotation and their rates
/// prescribed at t_{n+1}) and every other node is free. The co-rotational
/// elements take any rigid rotation exactly (stress-free, test
/// fem.NonlinearStatic.RigidRotationOfWholeModelIsStressFree), so the large
/// flapping rotation needs no moving frame and no fictitious (centrifugal,
/// Coriolis, Euler) forces: they arise from M v̇ in the inertial frame.
///
/// Damping (optional): stiffness-proportional damping a₁ Bᵀ k ḋ of each element's own
/// deformation rate, ḋ = (d_{n+1} − d_n)/h (first order; zero for any rigid motion, so the
/// flapping is not damped: corotational_kernel.hpp EicrDamping). Mass-proportional damping is not
/// offered: in the ground frame it would damp the rigid flapping motion.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/constraints.hpp"
#include "fem/load_damping.hpp"
#include "fem/nonlinear_assembly.hpp"

namespace flapsim::fem {

/// Integrator settings.
struct DynamicsOptions {
  double rho_infinity = 1.0;     ///< spectral radius at h → ∞ (1: no numerical dissipation)
  /// Newton iterations per attempt: with the kept matrix, then (if that fails) a new matrix
  /// every iteration. The kept matrix's attempt stops sooner at a correction beyond π rad
  /// (nonlinear_dynamics.cpp, kDivergedCorrection).
  int max_iterations = 25;
  double tolerance = 1e-10;      ///< ‖r_free‖ ≤ tolerance · force scale of the step
  double stiffness_damping = 0.0;  ///< a₁ [s], Rayleigh stiffness-proportional (co-rotational)
  /// Newton matrix: SymmetricLower (CHOLMOD LLᵀ, LU if not positive definite) or
  /// Consistent (sparse LU of the non-symmetric tangent).
  TangentForm tangent = TangentForm::SymmetricLower;
  /// Also converged when the largest Newton correction is below this fraction
  /// of the model's size (translations) or this many radians (rotations):
  /// the residual of a small motion can sit at its round-off floor.
  double increment_tolerance = 1e-13;
  /// Keep the factorised Newton matrix across iterations and steps (modified
  /// Newton); false: a new tangent and factorisation every iteration.
  bool reuse_factorization = true;
  /// A kept matrix is made anew when its correction shrinks by less than this factor in an
  /// iteration (‖δx_{k+1}‖ > refactor_rate ‖δx_k‖: its contraction θ, the ratio of successive
  /// corrections; the residual's ratio is no measure, nonlinear_dynamics.cpp).
  double refactor_rate = 0.25;
  /// The first correction of a step solved again (a coupling's next sub-iteration, warm:
  /// StepStart::PreviousSolution) also converges when the contraction θ its matrix showed in
  /// this step (the ratio of its last two corrections) bounds the error it leaves as the rule
  /// below does: η ‖δx‖ ≤ ρ/(1 − ρ) · increment_tolerance, η = (θ/(1 − θ))^0.8, ρ =
  /// refactor_rate (the stopping rule of the simplified Newton iteration, Hairer & Wanner,
  /// Solving Ordinary Differential Equations II, §IV.8; docs/fem.md, "Newton's stop from the
  /// measured contraction"). The rule ‖δx‖ ≤ increment_tolerance bounds that error by the
  /// same amount for the slowest contraction a kept matrix is allowed (ρ); a warm solve whose
  /// one correction meets the bound then needs no second, checking one. Not with line_search.
  bool contraction_stop = true;
  /// Carry the free nodes with the driven base's rigid increment (else start at q_n).
  bool rigid_predictor = true;
  /// A Newton matrix made after a correction takes its geometric terms from the
  /// elements' local forces at the correction's end taken linearly, k (d₀ + B₀ Δu),
  /// instead of k d(u): the stretching a transverse correction puts into a thin membrane
  /// (second order in Δu, a spurious membrane force) then stays out of the matrix
  /// (Magisano, Leonetti & Garcea 2017; docs/fem.md, "Cost"). The converged answer is the
  /// same (the residual is not changed). Linear shells and frames; not with line_search.
  /// With it, a matrix kept from another step (or piece) gives a solve one correction.
  bool linearised_geometric_force = true;
  /// Keep a Newton matrix for each piece of a step its caller solves in pieces
  /// (DynamicsData::keep_warm_starts), so that a piece solved again (the coupling's next
  /// sub-iteration) starts with the matrix made for it; false: one kept matrix, the last one
  /// made. Measured (docs/fem.md, "A kept matrix for each piece"): the film wings' runs
  /// about twice as fast. Off here (one matrix, the solver's own default); a coupled run's
  /// case key `[structure] newton_matrix_per_piece` turns it on by default.
  bool matrix_per_piece = false;
  /// Scale each Newton correction by a line search on the slope δxᵀ r along it
  /// (regula falsi, at most 8 force evaluations; docs/fsi.md "Film wings":
  /// the 25 µm film converges with it and not without).
  bool line_search = false;
};

/// Where a step's Newton iterations start.
enum class StepStart {
  Predictor,         ///< the predictor of DynamicsOptions (rigid or at rest)
  PreviousSolution,  ///< the last converged answer of this same step (same t_n and Δt), if any
};

/// Work done since the data were made (for benchmarks and reports).
struct SolverCounters {
  long steps = 0;               ///< converged steps
  long iterations = 0;          ///< Newton iterations (linear solves)
  long factorizations = 0;      ///< Newton matrices factorised
  long lu_fallbacks = 0;        ///< of which refused by LLᵀ (then LDLᵀ, or LU: newton_matrix.hpp)
  long retries = 0;             ///< steps redone with a fresh matrix every iteration
};

/// Memory the kept Newton matrices of a step solved in pieces may take together [bytes]
/// (DynamicsData::keep_warm_starts; as NewtonMatrix::factor_bytes counts them: the LLᵀ, so
/// with the LDLᵀ an indefinite matrix also gets, up to twice this). The 25 µm MAV film wing
/// (4860 DOFs, steps in up to 16 pieces) ran with 143 MB more with them (486 MB in all since
/// the LDLᵀ too is kept in two parts).
inline constexpr double kKeptMatricesBytes = 256.0e6;

/// The constant part: model, which nodes are driven, which DOFs are fixed.
struct DynamicsModel {
  const CorotationalModel* structure = nullptr;  ///< must outlive the model and its data
  std::vector<int> driven_nodes;   ///< nodes whose motion is prescribed (all 6 DOFs)
  Constraints eliminated;          ///< driven nodes' DOFs (and any fixed DOF)
  DynamicsOptions options;
  double alpha_m = 0.0, alpha_f = 0.0, beta = 0.0, gamma = 0.0;  ///< from rho_infinity
  double size = 0.0;                   ///< bounding-box diagonal of the reference nodes [m]
  std::vector<int> fixed_not_driven;   ///< DOFs held at their initial values
};

/// \brief Build the constant part; `fixed_dofs` stay at their initial values.
DynamicsModel make_dynamics_model(const CorotationalModel& structure, std::vector<int> driven_nodes,
                                  const DynamicsOptions& options = {}, const std::vector<int>& fixed_dofs = {});

/// Motion of the driven nodes at t_{n+1}, one entry per DynamicsModel::driven_nodes.
struct PrescribedMotion {
  std::vector<Eigen::Vector3d> position, velocity, acceleration;  ///< [m, m/s, m/s²]
  std::vector<Eigen::Matrix3d> rotation;                          ///< reference → current
  std::vector<Eigen::Vector3d> angular_velocity, angular_acceleration;  ///< spatial [rad/s, rad/s²]
};

/// \brief Rigid motion of the driven nodes: x = c + Q (X − X₀), R = Q, with the
/// rates of a rigid body (velocity v_c, spatial ω, α) about the point X₀ → c.
PrescribedMotion rigid_prescribed_motion(const DynamicsModel& model, const Eigen::Vector3d& X0,
                                         const Eigen::Vector3d& c, const Eigen::Vector3d& vc,
                                         const Eigen::Vector3d& ac, const Eigen::Matrix3d& Q,
                                         const Eigen::Vector3d& omega, const Eigen::Vector3d& alpha);

/// Outcome of one step.
struct StepResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;   ///< last ‖r_free‖ / force scale
  /// The smallest tolerance_scale whose stopping test the answer passed (≤ the one asked):
  /// an answer asked for loosely may meet the full accuracy all the same (≤ 1).
  double tolerance_met = 0.0;
  std::string failure;     ///< why it stopped (empty when converged)
};

/// The mutable part: state, rates, work buffers, the factorisation.
class DynamicsData {
 public:
  /// \brief Start at `state` with velocities v0 (full (ẋ, ω)); the initial
  /// acceleration solves M v̇₀ = f_ext0 − f_int on the free DOFs.
  DynamicsData(const DynamicsModel& model, const CorotationalState& state, const Eigen::VectorXd& v0,
               const Eigen::VectorXd& f_ext0);
  ~DynamicsData();
  DynamicsData(const DynamicsData&) = delete;
  DynamicsData& operator=(const DynamicsData&) = delete;

  CorotationalState state;     ///< q_n
  Eigen::VectorXd velocity;    ///< v_n (full)
  Eigen::VectorXd acceleration;  ///< v̇_n (full)
  Eigen::VectorXd pseudo_acceleration;  ///< a_n (full)
  double time = 0.0;           ///< t_n [s]
  /// Elastic energy at q_n [J]: the elements evaluated at q_n when asked (one force
  /// evaluation, about 2 ms on the hawkmoth's default mesh, in the solver's scratch space;
  /// a step does not spend it).
  double strain_energy() const;
  double kinetic_energy() const;  ///< ½ vᵀ M v [J]
  const SolverCounters& counters() const { return counters_; }
  /// \brief Keep the converged answers of the last `count` steps (at least one) as warm
  /// starts (StepStart::PreviousSolution): a caller that solves a step in pieces, and each
  /// piece again in the next sub-iteration, finds every piece's last answer; with
  /// DynamicsOptions::matrix_per_piece as many kept Newton matrices, as far as
  /// kKeptMatricesBytes allows, so that each piece finds the matrix made for it in the last
  /// sub-iteration. Only grows (it allocates when it does).
  void keep_warm_starts(int count);

 private:
  friend StepResult step(const DynamicsModel&, DynamicsData&, double, const Eigen::VectorXd&,
                         const PrescribedMotion*, StepStart, double, const NodalLoadDamping*);
  struct Work;
  std::unique_ptr<Work> work_;
  SolverCounters counters_;
};

/// \brief Advance from t_n to t_n + dt. On failure the data keep t_n's values.
/// \param f_ext       nodal loads at t_{n+1}, full numbering [N, N·m]
/// \param prescribed  driven nodes' motion at t_{n+1} (nullptr: they stay where they are, at rest)
/// \param start       PreviousSolution: start from the answer of the last converged call if
///                    it was made from the same t_n with the same dt (the caller restored
///                    the data to that t_n's state); else the predictor
/// \param tolerance_scale  ≥ 1: Newton stops at this multiple of DynamicsOptions::tolerance
///                    and increment_tolerance (an intermediate answer, e.g. a coupling
///                    sub-iteration far from its fixed point; docs/fsi.md); 1: full accuracy
/// \param damping     a load −s D (v_{n+1} − v_ref) added to f_ext, and s (γ/(βh)) D to the
///                    Newton matrices the step makes (load_damping.hpp); nullptr: none
StepResult step(const DynamicsModel& model, DynamicsData& data, double dt, const Eigen::VectorXd& f_ext,
                const PrescribedMotion* prescribed, StepStart start = StepStart::Predictor,
                double tolerance_scale = 1.0, const NodalLoadDamping* damping = nullptr);

}  // namespace flapsim::fem
