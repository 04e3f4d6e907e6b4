#pragma once
/// \file chain_data.hpp
/// \brief The mutable workspace of the chain algorithms (Pinocchio's Data): body
/// poses, velocities and Jacobians, mass matrix, force vectors and the integrator's
/// quasi-Newton matrices. Sized once from a ChainModel; the time loop allocates
/// nothing. One ChainData per thread.

#include "mbd/chain_model.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products in every chain algorithm
#include <Eigen/LU>

#include <vector>

namespace flapsim::mbd {

/// Kinematic state of one body in the ground frame G, filled by forward_kinematics.
struct BodyKinematics {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< R_GB
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();   ///< inboard joint position [m]
  Eigen::Vector3d com = Eigen::Vector3d::Zero();      ///< centre of mass [m]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< ω [rad/s]
  Eigen::Vector3d origin_velocity = Eigen::Vector3d::Zero();   ///< [m/s]
  Eigen::Vector3d com_velocity = Eigen::Vector3d::Zero();      ///< [m/s]
  /// Accelerations. After forward_kinematics: the bias part (Φ̈ = 0, the base's ω̇
  /// included); after update_accelerations: the full values for a given Φ̈.
  Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();  ///< [rad/s²]
  Eigen::Vector3d origin_acceleration = Eigen::Vector3d::Zero();   ///< [m/s²]
  Eigen::Vector3d com_acceleration = Eigen::Vector3d::Zero();      ///< [m/s²]
  Eigen::Matrix3d inertia_ground = Eigen::Matrix3d::Zero();  ///< R I R^T about the com [kg m²]
  Eigen::Vector3d bend_axis = Eigen::Vector3d::Zero();   ///< unit θ axis of its inboard joint
  Eigen::Vector3d twist_axis = Eigen::Vector3d::Zero();  ///< unit α axis of its inboard joint
  /// d(com velocity)/dΦ̇ and d(ω)/dΦ̇, 3 × n (columns of outboard joints are zero).
  Eigen::MatrixXd com_jacobian;
  Eigen::MatrixXd angular_jacobian;
};

/// Workspace of the quasi-Newton solve of one implicit step.
struct StepWorkspace {
  Eigen::MatrixXd jacobian;             ///< ∂residual/∂Φ̈_{n+1}, kept across steps
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  bool jacobian_valid = false;
  double jacobian_dt = 0.0;             ///< step size the Jacobian was built for [s]
  Eigen::VectorXd x, dx, r, r_new, dr, jdx, q, v, a, scratch, scratch2;
  int last_iterations = 0;              ///< quasi-Newton iterations of the last step
  int last_refreshes = 0;               ///< Jacobian rebuilds in the last step
  long total_refreshes = 0;             ///< Jacobian rebuilds since construction
  int last_substeps = 1;                ///< pieces the last step was solved in (sub-steps and halves)
  long split_steps = 0;                 ///< steps that needed halving since construction
  int max_substeps = 1;                 ///< most pieces of one halved step since construction
  /// Steps that failed even in halves and were solved as a restart (backward Euler,
  /// generalized_alpha.hpp) since construction.
  long restarted_steps = 0;
  bool jacobian_restart = false;  ///< the kept Jacobian is the restart's (backward Euler)
  /// The load damping D (ChainData::load_damping) the Jacobian holds (zero: none); the
  /// Jacobian is corrected by the difference when the caller changes D.
  Eigen::MatrixXd jacobian_damping;
};

/// A linear part of the external loads' dependence on Φ̇ that the caller knows (e.g. the
/// air's added mass, pipeline/fsi/chain_structure.cpp): while active, the step solves with
///     Q(Φ̇) = Q_given − D (Φ̇ − Φ̇_ref),
/// Q_given the generalized force of the Loads (found at Φ̇_ref). At Φ̇ = Φ̇_ref the step is
/// the same; the term only makes the step respond to its own velocity as the loads would.
/// Φ̇_ref is the rate at the step's end, so the term acts in a step solved whole only: in
/// the pieces of a step solved in sub-steps or halves (generalized_alpha.cpp) an earlier
/// piece's rate differs from it at the fixed point too, and the term would move the
/// coupled answer (with it in every piece a run found another fixed point; in the last
/// piece alone it made runs fail that converge without it).
struct LoadDamping {
  Eigen::MatrixXd matrix;     ///< D = −∂Q/∂Φ̇ [N m s/rad]
  Eigen::VectorXd reference;  ///< Φ̇_ref [rad/s]
  bool active = false;
  double step_start = 0.0, step_end = 0.0;  ///< the step being solved [s] (set by advance)
};

struct ChainData {
  explicit ChainData(const ChainModel& model);

  std::vector<BodyKinematics> bodies;
  Eigen::MatrixXd mass_matrix;      ///< M(Φ, t) [kg m²]
  Eigen::VectorXd inertial_bias;    ///< velocity-product and base-motion terms of H [N m]
  Eigen::VectorXd spring_force;     ///< K(Φ − Φ_rest) + C Φ̇ [N m]
  Eigen::VectorXd generalized_load; ///< Q from the Loads and gravity [N m]
  Eigen::MatrixXd stiffness, damping;  ///< copies of the model's K and C (full)
  Eigen::MatrixXd stiffness_abs;       ///< |K| entry by entry (round-off bound of K Φ)
  Eigen::VectorXd rest;                ///< the model's rest angles [rad]
  Eigen::VectorXd deflection;          ///< scratch Φ − Φ_rest [rad]
  Eigen::MatrixXd inertia_times_jacobian;    ///< 3 × n scratch for the mass matrix
  LoadDamping load_damping;  ///< inactive unless the caller sets it (generalized_alpha.cpp)
  StepWorkspace step;
};

}  // namespace flapsim::mbd
