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
#include <array>

namespace flapsim::mbd {

struct WingKinematics {
  double frequency = 0.0;           ///< flapping frequency f [Hz]
  PeriodicSignal sweep;             ///< φ(s) [rad]
  PeriodicSignal deviation;         ///< θ(s) [rad]
  PeriodicSignal rotation;          ///< α(s) [rad]
  double rotation_phase = 0.0;      ///< δψ [cycles]
  double stroke_plane_angle = 0.0;  ///< β [rad]
  /// Translation of the pivot in the ground frame [m] as signals of the phase s = f·t (not
  /// shifted by δψ): surge along x_G, lateral along y_G, heave along z_G; zero by default.
  PeriodicSignal surge, lateral, heave;
  /// True if the pivot moves: surge, lateral or heave is not constant.
  bool pivot_translates() const {
    return !surge.is_constant() || !lateral.is_constant() || !heave.is_constant();
  }
  /// True if the base oscillates at the wingbeat frequency: a sweep, deviation, rotation or
  /// pivot translation that is not constant. A wing that only revolves has no wingbeat (its
  /// frequency_hz sets the time unit), so nothing drives it at that frequency.
  bool oscillates() const {
    return !sweep.is_constant() || !deviation.is_constant() || !rotation.is_constant() || pivot_translates();
  }
  /// A steady revolution added to the sweep (revolving-wing experiments: Dickinson et al.
  /// 1999, Usherwood & Ellington 2002): φ gains Ω_r(t), the rate rising from 0 to Ω over the
  /// ramp τ as Ω (1 − cos(π t/τ))/2 (no jump of the rate or of its derivative at 0 and τ),
  /// constant after it. Ω < 0 moves the wing as on the downstroke (leading edge first at the
  /// angle of attack α). Zero by default: the flapping wing.
  struct Revolution {
    double rate = 0.0;  ///< Ω [rad/s]
    double ramp = 0.0;  ///< τ [s] (0: at Ω from t = 0)
    bool active() const { return rate != 0.0; }
    /// The revolution's angle [rad], rate [rad/s] and acceleration [rad/s²] at time t [s] ≥ 0.
    AngleSample at(double t) const;
  };
  Revolution revolution;

  /// A signal of the kinematics with its case-file key.
  struct NamedSignal {
    const char* name;  ///< "sweep", "deviation", "rotation", "surge", "lateral", "heave"
    const PeriodicSignal* signal;
    bool angle;  ///< [rad]; else a length [m]
  };
  /// The six signals in case-file order (sweep, deviation, rotation, surge, lateral, heave).
  std::array<NamedSignal, 6> named_signals() const {
    return {{{"sweep", &sweep, true},
             {"deviation", &deviation, true},
             {"rotation", &rotation, true},
             {"surge", &surge, false},
             {"lateral", &lateral, false},
             {"heave", &heave, false}}};
  }

  struct Angles {
    AngleSample sweep, deviation, rotation;  ///< [rad], [rad/s], [rad/s²]
  };
  /// Euler angles and their time derivatives at time t [s] (δψ applied).
  Angles angles(double t) const;

  /// Orientation R_GW, angular velocity and angular acceleration (ground frame) at t [s],
  /// and the pivot's position, velocity and acceleration.
  BasePose pose(double t) const;
};

/// The Euler angles of the convention [rad]: φ (sweep), θ (deviation), α (rotation).
struct StrokeAngles {
  double sweep = 0.0;      ///< φ [rad]
  double deviation = 0.0;  ///< θ [rad]
  double rotation = 0.0;   ///< α [rad]
};

/// \brief The stroke rotation R_SW = Rz(φ) · Rx(θ) · Ry(−α) of given angles: the wing
/// frame W in the stroke-plane frame S (WingKinematics::pose is R_GS times this).
Eigen::Matrix3d stroke_rotation(const StrokeAngles& angles);

/// \brief The inverse of stroke_rotation: the angles of a rotation R_SW,
///   θ = asin(R₂₁), φ = atan2(−R₀₁, R₁₁), α = atan2(R₂₀, R₂₂)
/// (unique for |θ| < 90°; angles in (−180°, 180°]).
StrokeAngles stroke_angles(const Eigen::Matrix3d& rotation_sw);

/// The base motion the multibody stage follows.
BaseMotion make_base_motion(const WingKinematics& kinematics);

/// Elementary rotations [rad] (right-handed, active): R·v rotates v about the axis.
Eigen::Matrix3d rotation_x(double angle);
Eigen::Matrix3d rotation_y(double angle);
Eigen::Matrix3d rotation_z(double angle);

}  // namespace flapsim::mbd
