#pragma once
/// \file wing_kinematics.hpp
/// \brief Wing-base kinematics: sweep φ, deviation θ and rotation α as periodic
/// signals of the stroke phase, the rotation phase δψ, and the resulting wing-frame
/// orientation, angular velocity and acceleration.
///
/// Convention (docs/kinematics.md): R_GW = R_GS · Rz(φ) · Rx(θ) · Ry(−α), with
/// R_GS = Ry(β) for a stroke plane tilted by β about the ground y axis (β = 0: hover,
/// horizontal stroke plane). Chord x_W = cosα·x' + sinα·z_S: α = 90° puts the chord
/// normal to the stroke plane; the geometric angle of attack is α on the downstroke
/// (φ̇ < 0) and 180° − α on the upstroke, the leading edge leading both times.
/// The rotation phase shifts sweep and deviation: φ(t) = φ_signal(f·t + δψ);
/// δψ < 0 advances the rotation relative to stroke reversal.

#include "mbd/base_motion.hpp"
#include "mbd/periodic_signal.hpp"

#include <Eigen/Geometry>  // callers use cross products of the pose vectors

namespace flapsim::mbd {

struct WingKinematics {
  double frequency = 0.0;           ///< flapping frequency f [Hz]
  PeriodicSignal sweep;             ///< φ(s) [rad]
  PeriodicSignal deviation;         ///< θ(s) [rad]
  PeriodicSignal rotation;          ///< α(s) [rad]
  double rotation_phase = 0.0;      ///< δψ [cycles]
  double stroke_plane_angle = 0.0;  ///< β [rad]

  struct Angles {
    AngleSample sweep, deviation, rotation;  ///< [rad], [rad/s], [rad/s²]
  };
  /// Euler angles and their time derivatives at time t [s] (δψ applied).
  Angles angles(double t) const;

  /// Orientation R_GW, angular velocity and angular acceleration (ground frame) at t [s].
  BasePose pose(double t) const;
};

/// The base motion the multibody stage follows.
BaseMotion make_base_motion(const WingKinematics& kinematics);

/// Elementary rotations [rad] (right-handed, active): R·v rotates v about the axis.
Eigen::Matrix3d rotation_x(double angle);
Eigen::Matrix3d rotation_y(double angle);
Eigen::Matrix3d rotation_z(double angle);

}  // namespace flapsim::mbd
