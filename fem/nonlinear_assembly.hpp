#pragma once
/// \file nonlinear_assembly.hpp
/// \brief The geometrically nonlinear (co-rotational) FEM: its constant model,
/// its state (node positions and nodal rotation matrices), and the assembly of
/// internal forces and of the tangent on the free DOFs without allocation.
///
/// DOFs as in mesh.hpp (6·node + d). Translational DOFs are displacements;
/// rotational "DOFs" are spatial spins: an increment Δ moves a node by
/// x ← x + Δ_t and R ← exp(Δ̂_r) R (nodal_rotation.hpp). Forces and tangents are
/// conjugate to these increments (moments about global axes).
///
/// Mass: rotation-invariant, so it stays constant in any rigid motion and the
/// rotational equations carry no gyroscopic term.
/// - Shells: the linear element's mass unchanged: consistent translational mass
///   (the same in x, y, z) and the lumped rotary inertia ρh³/12·A/3, the same
///   about all three axes; an isotropic nodal inertia j has Euler equations
///   j ω̇ = m, exact in finite rotation.
/// - Frames: the consistent mass of linear interpolation, ρAℓ/6·[2 1; 1 2] in
///   x, y, z, and the torsional inertia ρI_pℓ/2 lumped on each node about all
///   three axes. The Hermite bending mass of frame_element.hpp couples nodal
///   translations with rotations through the element axes and is not
///   invariant in a rigid rotation; its isotropic replacement also gives the
///   rotary inertia of bending ρI_p (twice the physical ρI) — negligible for
///   slender veins, stated in docs/fem.md.

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fem/assembly.hpp"
#include "fem/constraints.hpp"
#include "fem/corotational_frame.hpp"
#include "fem/corotational_shell.hpp"
#include "fem/film_hinge.hpp"
#include "fem/film_triangle.hpp"
#include "fem/structural_model.hpp"

namespace flapsim::fem {

/// How the shells' membrane responds to compression.
enum class MembraneLaw {
  Elastic,       ///< linear in the co-rotated frame, compression as tension
  TensionField,  ///< no compression: wrinkles or slack (tension_field_membrane.hpp)
  /// The shells are films: membrane only, translations only, the tension-field law on
  /// the Green strain (film_triangle.hpp); no bending, no drilling. The rotations of
  /// nodes that no frame touches carry nothing and are fixed (make_dynamics_model).
  Film,
};

/// Constant co-rotational model.
struct CorotationalModel {
  MembraneLaw membrane_law = MembraneLaw::Elastic;
  std::vector<Eigen::Vector3d> reference_positions;  ///< X [m]
  std::vector<CorotationalShell> shells;
  std::vector<FilmTriangle> films;  ///< MembraneLaw::Film: one per shell, same order
  std::vector<FilmHinge> hinges;    ///< MembraneLaw::Film: the films' bending, one per interior edge
  std::vector<CorotationalFrame> frames;
  SparseMatrix mass;  ///< rotation-invariant mass (see above), full numbering
  int num_nodes() const { return static_cast<int>(reference_positions.size()); }
  int num_dofs() const { return kDofsPerNode * num_nodes(); }
};

/// \brief The rotational DOFs no element stiffens: of every node that only film
/// triangles touch (MembraneLaw::Film); empty for other laws.
std::vector<int> film_only_rotation_dofs(const CorotationalModel& model);

/// \brief The co-rotational model of a linear structural model (same mesh,
/// elements, materials). Throws std::invalid_argument on degenerate elements.
CorotationalModel make_corotational_model(const StructuralModel& model,
                                          MembraneLaw membrane_law = MembraneLaw::Elastic);

/// Current configuration.
struct CorotationalState {
  std::vector<Eigen::Vector3d> position;  ///< x [m]
  std::vector<Eigen::Matrix3d> rotation;  ///< R: reference → current
};

/// \brief The undeformed configuration (x = X, R = I).
CorotationalState reference_state(const CorotationalModel& model);

/// \brief x += Δ_t, R ← exp(Δ̂_r) R for every node; Δ a full DOF vector.
void apply_increment(CorotationalState& state, const Eigen::VectorXd& increment);

/// \brief Nodal displacements x − X and rotation vectors log(R) as a full DOF vector.
Eigen::VectorXd displacement_vector(const CorotationalModel& model, const CorotationalState& state);

/// Extra terms of one evaluation (dynamics).
struct TangentExtras {
  double mass_scale = 0.0;                     ///< c_M: adds c_M·M to the tangent [1/s²]
  double damping = 0.0;  ///< a₁ [s]: stiffness-proportional damping of the elements' deformation rate
  /// 1/h [1/s]: the deformation rate (d − d_n)/h of the damping, d_n recorded by
  /// NonlinearAssembler::record_step_start; 0: no damping.
  double damping_rate = 0.0;
  /// The geometric terms of the tangent from each element's local force at the end of the
  /// last Newton correction taken linearly, k (d₀ + B₀ Δu), instead of k d(u) at the current
  /// state (the mixed, "MIP" Newton of Magisano, Leonetti & Garcea 2017; linear shells and
  /// frames): NonlinearAssembler::record_correction_path must have recorded the correction.
  bool linearised_geometric_force = false;
};

/// How the tangent is stored.
enum class TangentForm {
  SymmetricLower,  ///< geometric part symmetrised, lower triangle (for LLᵀ/LDLᵀ)
  Consistent,      ///< the non-symmetric spin-variable tangent, both triangles (for LU)
};

/// Assembles internal forces (all DOFs) and the tangent on the free DOFs
/// (fixed pattern) of one model. Buffers are sized once.
class NonlinearAssembler {
 public:
  /// \param constraints  DOFs fixed or driven: eliminated from the tangent
  NonlinearAssembler(const CorotationalModel& model, Constraints constraints,
                     TangentForm form = TangentForm::SymmetricLower);

  /// \brief Internal force f_int (full numbering; with damping, the damping force
  /// is included) and, if `tangent`, the free–free tangent. Returns the strain energy [J].
  double evaluate(const CorotationalState& state, Eigen::VectorXd& f_int, bool tangent,
                  const TangentExtras& extras = {});

  /// \brief Overwrite the tangent's values with the free–free mass M_ff.
  void load_mass_into_tangent();

  /// \brief Record the elements' local deformations d at a point of a Newton correction Δu:
  /// `point` 0 at its start, 1 at its middle, 2 at its end. From the three,
  /// d₀ + B₀ Δu = 4 d(½) − 2 d(0) − d(1) + O(Δu³) (TangentExtras::linearised_geometric_force).
  void record_correction_path(const CorotationalState& state, int point);

  /// \brief Record the elements' local deformations d_n at the start of a step (the state
  /// the step starts from): the damping's rate (d − d_n)/h (TangentExtras::damping_rate).
  void record_step_start(const CorotationalState& state);

  /// \brief Adds factor · D_k to the tangent's translation block of each node k (free
  /// DOFs only; the lower triangle for SymmetricLower), after evaluate made it.
  void add_translation_blocks(const std::vector<int>& nodes, const std::vector<Eigen::Matrix3d>& blocks,
                              double factor);

  const SparseMatrix& tangent() const { return tangent_; }  ///< free DOFs (see TangentForm)
  const Constraints& constraints() const { return constraints_; }
  const std::vector<int>& free_dofs() const { return free_dofs_; }
  const CorotationalModel& model() const { return model_; }

 private:
  const CorotationalModel& model_;
  Constraints constraints_;
  TangentForm form_;
  std::vector<int> free_dofs_;
  SparseMatrix tangent_;
  std::vector<double> mass_values_;  ///< M_ff aligned with tangent_'s values
  std::vector<std::array<int, 9>> translation_slots_;  ///< per node, its 3 × 3 block's (-1: not stored)
  std::vector<std::array<int, 18 * 18>> shell_slots_;
  std::vector<std::array<int, 12 * 12>> frame_slots_;
  std::vector<std::array<int, 24 * 24>> hinge_slots_;
  /// The smallest and largest slot an element's tangent fills (none: max, -1).
  std::vector<std::array<int, 2>> shell_slot_range_, frame_slot_range_;
  /// The tangent's values are filled in this many ranges, one a thread (evaluate).
  static constexpr int kScatterParts = 2;
  std::vector<Eigen::Matrix<double, 12, 1>> hinge_f_;
  std::vector<Eigen::Matrix<double, 12, 12>> hinge_K_;
  std::vector<Matrix18d> shell_K_;
  std::vector<Eigen::Matrix<double, 18, 1>> shell_f_;
  std::vector<Matrix12d> frame_K_;
  std::vector<Eigen::Matrix<double, 12, 1>> frame_f_;
  std::vector<double> energy_;
  std::array<std::vector<Eigen::Matrix<double, 18, 1>>, 3> path_shell_d_;  ///< d along a correction
  std::array<std::vector<Eigen::Matrix<double, 12, 1>>, 3> path_frame_d_;
  std::vector<Eigen::Matrix<double, 18, 1>> start_shell_d_;  ///< d at the step's start (damping)
  std::vector<Eigen::Matrix<double, 12, 1>> start_frame_d_;
  /// The deformations d of the shells (all but films', `all_shells`; else the linear ones)
  /// and frames at a state, into the given arrays.
  void record_deformations(const CorotationalState& state, bool all_shells,
                           std::vector<Eigen::Matrix<double, 18, 1>>& shell_d,
                           std::vector<Eigen::Matrix<double, 12, 1>>& frame_d) const;
};

}  // namespace flapsim::fem
