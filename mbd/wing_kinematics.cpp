#include "mbd/wing_kinematics.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace flapsim::mbd {

Eigen::Matrix3d rotation_x(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  R << 1, 0, 0,
       0, c, -s,
       0, s, c;
  return R;
}

Eigen::Matrix3d rotation_y(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  R << c, 0, s,
       0, 1, 0,
       -s, 0, c;
  return R;
}

Eigen::Matrix3d rotation_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  R << c, -s, 0,
       s, c, 0,
       0, 0, 1;
  return R;
}

Eigen::Matrix3d stroke_rotation(const StrokeAngles& a) {
  return rotation_z(a.sweep) * rotation_x(a.deviation) * rotation_y(-a.rotation);
}

StrokeAngles stroke_angles(const Eigen::Matrix3d& r) {
  StrokeAngles a;
  a.deviation = std::asin(std::clamp(r(2, 1), -1.0, 1.0));
  a.sweep = std::atan2(-r(0, 1), r(1, 1));
  a.rotation = std::atan2(r(2, 0), r(2, 2));
  return a;
}

namespace {

/// Signal derivatives per cycle -> per second: d/dt = f·d/ds.
AngleSample per_second(AngleSample a, double f) {
  a.rate *= f;
  a.acceleration *= f * f;
  return a;
}

}  // namespace

AngleSample WingKinematics::Revolution::at(double t) const {
  AngleSample r;
  if (t < 0.0 || rate == 0.0) return r;  // τ = 0: at Ω from t = 0 itself
  if (t >= ramp) {
    // ∫₀^τ Ω (1 − cos(π u/τ))/2 du = Ω τ/2, then Ω per second.
    r.value = rate * (0.5 * ramp + (t - ramp));
    r.rate = rate;
    return r;
  }
  const double w = std::numbers::pi / ramp;  // [rad/s]
  r.value = 0.5 * rate * (t - std::sin(w * t) / w);
  r.rate = 0.5 * rate * (1.0 - std::cos(w * t));
  r.acceleration = 0.5 * rate * w * std::sin(w * t);
  return r;
}

WingKinematics::Angles WingKinematics::angles(double t) const {
  const double s = frequency * t;                 // stroke phase [cycles]
  const double shifted = s + rotation_phase;      // sweep and deviation run δψ ahead
  Angles a;
  a.sweep = per_second(sweep.at_phase(shifted), frequency);
  if (revolution.active()) {
    const AngleSample r = revolution.at(t);
    a.sweep.value += r.value;
    a.sweep.rate += r.rate;
    a.sweep.acceleration += r.acceleration;
  }
  a.deviation = per_second(deviation.at_phase(shifted), frequency);
  a.rotation = per_second(rotation.at_phase(s), frequency);
  return a;
}

BasePose WingKinematics::pose(double t) const {
  const Angles a = angles(t);
  const double phi = a.sweep.value, theta = a.deviation.value, alpha = a.rotation.value;
  const double dphi = a.sweep.rate, dtheta = a.deviation.rate, dalpha = a.rotation.rate;

  const Eigen::Matrix3d R_GS = rotation_y(stroke_plane_angle);
  const Eigen::Matrix3d Rz = rotation_z(phi);
  const Eigen::Matrix3d RzRx = Rz * rotation_x(theta);

  // Axes of the three elementary rotations, in the stroke-plane frame S:
  // sweep about z_S, deviation about the swept x axis, rotation (by −α) about the
  // swept-and-deviated span axis.
  const Eigen::Vector3d a1 = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d a2 = Rz.col(0);
  const Eigen::Vector3d a3 = RzRx.col(1);

  // ω = φ̇ a1 + θ̇ a2 − α̇ a3. Differentiating, a2 turns with the sweep (φ̇ a1) and
  // a3 with sweep and deviation (φ̇ a1 + θ̇ a2); a1 is fixed in S.
  const Eigen::Vector3d omega_S = dphi * a1 + dtheta * a2 - dalpha * a3;
  const Eigen::Vector3d da2 = dphi * a1.cross(a2);
  const Eigen::Vector3d da3 = (dphi * a1 + dtheta * a2).cross(a3);
  const Eigen::Vector3d domega_S = a.sweep.acceleration * a1 + a.deviation.acceleration * a2 -
                                   a.rotation.acceleration * a3 + dtheta * da2 - dalpha * da3;

  BasePose p;
  p.rotation = R_GS * stroke_rotation({phi, theta, alpha});
  p.angular_velocity = R_GS * omega_S;  // S does not rotate relative to G
  p.angular_acceleration = R_GS * domega_S;
  const double phase = frequency * t;
  const PeriodicSignal* axes[3] = {&surge, &lateral, &heave};
  for (int i = 0; i < 3; ++i) {
    const AngleSample x = per_second(axes[i]->at_phase(phase), frequency);
    p.position(i) = x.value;
    p.velocity(i) = x.rate;
    p.acceleration(i) = x.acceleration;
  }
  return p;
}

BaseMotion make_base_motion(const WingKinematics& kinematics) {
  return [k = kinematics](double t) { return k.pose(t); };
}

}  // namespace flapsim::mbd
