#pragma once
/// \file base_motion.hpp
/// \brief The prescribed motion of the wing base (the chain's root frame), as
/// the multibody stage needs it: orientation, angular velocity and angular
/// acceleration at time t, and the position, velocity and acceleration of the pivot
/// (zero unless the base translates: heave, surge, lateral).

#include <Eigen/Core>

#include <functional>

namespace flapsim::mbd {

/// Pose of the wing frame W relative to the ground frame G at one instant.
struct BasePose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< R_GW: W coordinates -> G coordinates
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();      ///< ω [rad/s], in G
  Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();  ///< ω̇ [rad/s²], in G
  Eigen::Vector3d position = Eigen::Vector3d::Zero();      ///< pivot position [m], in G
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      ///< pivot velocity [m/s], in G
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  ///< pivot acceleration [m/s²], in G
};

/// t [s] -> pose of the base. Built from WingKinematics (mbd/wing_kinematics.hpp)
/// or from anything else a caller likes.
using BaseMotion = std::function<BasePose(double t)>;

}  // namespace flapsim::mbd
