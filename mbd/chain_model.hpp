#pragma once
/// \file chain_model.hpp
/// \brief The constant description of a Hencky bar chain: rigid bodies along the
/// flexural axis, joined by bending and torsion springs (docs/multibody.md).
///
/// Frames. Body frame: origin at the body's inboard joint, y along the body (span,
/// toward the tip), x chordwise toward the leading edge, z = x × y. The chain's root
/// frame R sits in the wing-base frame W at `root_offset`, rotated by `root_rotation`
/// (R_WR; identity: the chain runs along y_W). The pivot (origin of W) is fixed at the
/// ground origin.
///
/// Joint k (child body k, parent body k−1, or the root frame for k = 0):
///   R_{k−1,k} = Rx(θ_k) · Ry(α_k)
/// bending θ_k about the parent's x axis (θ > 0 bends the child toward +z), then
/// torsion α_k about the child's own y axis (Ry(α) turns the leading edge +x toward −z:
/// nose-down for α > 0, opposite to the base rotation α of WingKinematics, which enters as Ry(−α)).
/// The joint sits at the parent's outboard joint point (`outboard_joint` of body k−1,
/// or the root offset for k = 0).
///
/// Root attachment. Rigid (the papers): body 0 is welded to the root frame, so
/// Φ = [θ₁, α₁, …, θ_{N−1}, α_{N−1}] (0-based; [θ₂, α₂, …] in the papers' 1-based
/// numbering). With `welded_bodies` = w > 1 (a wing clamped over more than the first
/// body, e.g. the robofly's root edge) bodies 0 … w−1 are all welded and Φ starts at
/// joint w. Sprung (a Hencky cantilever, the reduction stage): joint 0 joins the
/// root frame to body 0 with its own springs (2EI/a for a uniform beam) and
/// Φ = [θ₀, α₀, …].

#include <Eigen/Core>

#include <string>
#include <vector>

namespace flapsim::mbd {

/// One rigid body of the chain; all quantities in its own body frame.
struct ChainBody {
  double length = 0.0;                                    ///< along y [m]
  double mass = 0.0;                                      ///< [kg]
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();  ///< [m], body frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about the centre of mass, body axes [kg m²]
  Eigen::Vector3d outboard_joint = Eigen::Vector3d::Zero();  ///< next joint [m]; usually (0, length, 0)
};

/// The joint inboard of a body: two rotational springs with optional dampers. When the
/// chain has a full stiffness (ChainModel::stiffness_matrix) the springs here are not
/// used; the dampers and rest angles are used unless a damping matrix is given.
struct ChainJoint {
  double bend_stiffness = 0.0;    ///< k_θ [N m/rad]
  double twist_stiffness = 0.0;   ///< k_α [N m/rad]
  double bend_damping = 0.0;      ///< c_θ [N m s/rad]
  double twist_damping = 0.0;     ///< c_α [N m s/rad]
  double bend_rest = 0.0;         ///< θ at zero spring moment [rad]
  double twist_rest = 0.0;        ///< α at zero spring moment [rad]
};

enum class RootAttachment {
  rigid,   ///< body 0 welded to the root frame (the papers' Φ = [θ₂, α₂, …])
  sprung,  ///< body 0 hinged to the root frame by joint 0 (Hencky cantilever)
};

struct ChainModel {
  std::vector<ChainBody> bodies;   ///< root to tip
  /// joints[k] is the joint inboard of body k (same size as bodies). With a rigid root
  /// joints[0] is not used.
  std::vector<ChainJoint> joints;
  RootAttachment root = RootAttachment::rigid;
  /// Bodies welded to the root frame with a rigid root (≥ 1; ignored for a sprung root).
  int welded_bodies = 1;
  /// Full joint stiffness K over Φ [N m/rad]: the elastic energy is
  /// ½ (Φ − Φ_rest)ᵀ K (Φ − Φ_rest), with bend–twist and joint-to-joint coupling
  /// (docs/multibody.md, "Joint stiffness"). Empty: the diagonal of the joints' springs.
  Eigen::MatrixXd stiffness_matrix;
  /// Full damping C over Φ [N m s/rad] (Rayleigh dissipation ½ Φ̇ᵀ C Φ̇). Empty: the
  /// diagonal of the joints' dampers.
  Eigen::MatrixXd damping_matrix;
  Eigen::Vector3d root_offset = Eigen::Vector3d::Zero();      ///< root point in W [m]
  Eigen::Matrix3d root_rotation = Eigen::Matrix3d::Identity();  ///< R_WR
  /// Gravity in the ground frame [m/s²]. Default off: the papers flap in vacuum and
  /// the insect wing's weight is negligible against its inertial loads; set
  /// (0, 0, −9.81) to include it.
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();

  int num_bodies() const { return static_cast<int>(bodies.size()); }
  /// First body with a joint (its own dofs): 1 for a rigid root, 0 for a sprung one.
  int first_jointed_body() const {
    return root == RootAttachment::rigid ? (welded_bodies > 1 ? welded_bodies : 1) : 0;
  }
  /// Number of generalized coordinates, 2 per jointed body.
  int num_dofs() const { return 2 * (num_bodies() - first_jointed_body()); }
  /// Index of θ of the joint inboard of `body` in Φ (α is the next one); −1 if none.
  int dof_of_body(int body) const {
    return body < first_jointed_body() ? -1 : 2 * (body - first_jointed_body());
  }

  /// The joint stiffness K over Φ: stiffness_matrix, or the joints' k_θ, k_α on the
  /// diagonal [N m/rad].
  Eigen::MatrixXd stiffness() const;
  /// The damping C over Φ: damping_matrix, or the joints' c_θ, c_α on the diagonal [N m s/rad].
  Eigen::MatrixXd damping() const;
  /// Diagonal of stiffness() [N m/rad].
  Eigen::VectorXd stiffness_diagonal() const;
  /// Diagonal of damping() [N m s/rad].
  Eigen::VectorXd damping_diagonal() const;
  /// Multiplies every spring (the joints' and the full matrix) by \p factor (> 0).
  void scale_stiffness(double factor);
  /// Rest angles over Φ [rad].
  Eigen::VectorXd rest_angles() const;

  /// Total mass [kg].
  double total_mass() const;

  /// Checks sizes, positive masses (≥ 0 for welded bodies) and lengths, symmetric positive semi-definite
  /// inertia satisfying the triangle inequality, non-negative springs and dampers,
  /// and full stiffness and damping matrices (when given) of size num_dofs, symmetric
  /// and positive semi-definite.
  /// \throws std::invalid_argument naming the body or joint
  void validate() const;
};

/// A uniform Euler–Bernoulli cantilever of length L cut into n rigid bars of
/// length a = L/n (the Hencky chain): sprung root with k = 2EI/a, 2GJ/a (half cell),
/// interior joints EI/a, GJ/a. Each bar carries its own distributed mass m'a with
/// centre at (0, a/2, 0), I_xx = I_zz = m'a³/12 (+ torsional part on I_zz, thin plate),
/// I_yy = i_α a (mass moment of inertia about the axis per length).
/// \param length                    L [m]
/// \param bending_stiffness         EI [N m²]
/// \param torsional_stiffness       GJ [N m²]
/// \param mass_per_length           m' [kg/m]
/// \param torsional_inertia_per_length  i_α [kg m]
/// \param num_bodies                n ≥ 1
ChainModel make_uniform_cantilever_chain(double length, double bending_stiffness,
                                         double torsional_stiffness, double mass_per_length,
                                         double torsional_inertia_per_length, int num_bodies);

}  // namespace flapsim::mbd
