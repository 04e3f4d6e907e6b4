#pragma once
/// \file chain_kinematics.hpp
/// \brief Forward kinematics of the bar chain: body poses, velocities, bias
/// accelerations and Jacobians in the ground frame, and points fixed in bodies
/// (the FSI coupling moves its aerodynamic nodes with these).

#include "mbd/base_motion.hpp"
#include "mbd/chain_data.hpp"
#include "mbd/chain_model.hpp"

#include <Eigen/Core>

namespace flapsim::mbd {

/// Fills data.bodies: rotation, origin, centre of mass, their velocities, the joint
/// axes, the Jacobians d(v_com, ω)/dΦ̇ and the bias accelerations (Φ̈ = 0, base ω̇ included).
/// \param base  pose of the wing-base frame W at this instant (pivot at the ground origin)
/// \param q     Φ [rad], size model.num_dofs()
/// \param v     Φ̇ [rad/s]
void forward_kinematics(const ChainModel& model, ChainData& data, const BasePose& base,
                        const Eigen::VectorXd& q, const Eigen::VectorXd& v);

/// Turns the bias accelerations of forward_kinematics into full accelerations for a
/// given Φ̈ [rad/s²]. Call once after forward_kinematics.
void update_accelerations(const ChainModel& model, ChainData& data, const Eigen::VectorXd& qdd);

/// Ground position [m] of a point fixed in a body, given in body coordinates [m].
Eigen::Vector3d point_position(const ChainData& data, int body, const Eigen::Vector3d& point_body);

/// Ground velocity [m/s] of a point fixed in a body (body coordinates [m]).
Eigen::Vector3d point_velocity(const ChainData& data, int body, const Eigen::Vector3d& point_body);

/// Ground acceleration [m/s²] of a point fixed in a body; valid after update_accelerations.
Eigen::Vector3d point_acceleration(const ChainData& data, int body,
                                   const Eigen::Vector3d& point_body);

/// Rotation of joint angles: Rx(θ)·Ry(α).
Eigen::Matrix3d joint_rotation(double bend, double twist);

}  // namespace flapsim::mbd
