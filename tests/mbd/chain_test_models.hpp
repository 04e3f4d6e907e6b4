#pragma once
// Chains, base motions and loads shared by the multibody tests.

#include "mbd/angle_units.hpp"
#include "mbd/base_motion.hpp"
#include "mbd/chain_loads.hpp"
#include "mbd/chain_model.hpp"
#include "mbd/wing_kinematics.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>


namespace flapsim::mbd::test {

constexpr double kPi = 3.14159265358979323846;

// The rotation-phase paper's 3-body validation system (Table 1; also
// cases/chains/three_body.toml): bodies of 1.61 cm, 13.27 / 13.01 / 7.48 mg, the
// table's "inertia moment" taken as the torsional moment I_yy about the centre of
// mass. Not given by the paper, chosen and documented in docs/multibody.md: centre of
// mass 1 mm behind the flexural axis at mid-length (couples bending and torsion),
// I_xx = mL²/12 (slender bar), I_zz = I_xx + I_yy (thin plate), rigid root, springs
// k_θ = 4e-3 / 2e-3 N m/rad and k_α = 1e-3 / 5e-4 N m/rad at joints 2 / 3, dampers
// c_θ = 1e-6, c_α = 1e-7 N m s/rad.
inline ChainModel three_body_chain() {
  ChainModel m;
  m.root = RootAttachment::rigid;
  const double L = 0.0161;
  const double mass[3] = {13.27e-6, 13.01e-6, 7.48e-6};
  const double i_twist[3] = {0.47e-10, 3.84e-10, 1.26e-10};
  const double k_bend[3] = {0.0, 4e-3, 2e-3};
  const double k_twist[3] = {0.0, 1e-3, 5e-4};
  for (int i = 0; i < 3; ++i) {
    ChainBody b;
    b.length = L;
    b.mass = mass[i];
    b.center_of_mass = Eigen::Vector3d(-1e-3, 0.5 * L, 0.0);
    const double ix = mass[i] * L * L / 12.0;
    b.inertia = Eigen::Vector3d(ix, i_twist[i], ix + i_twist[i]).asDiagonal();
    b.outboard_joint = Eigen::Vector3d(0.0, L, 0.0);
    m.bodies.push_back(b);
    ChainJoint j;
    j.bend_stiffness = k_bend[i];
    j.twist_stiffness = k_twist[i];
    if (i > 0) {
      j.bend_damping = 1e-6;
      j.twist_damping = 1e-7;
    }
    m.joints.push_back(j);
  }
  return m;
}

// The same system with a full joint stiffness and damping over Φ = [θ₂, α₂, θ₃, α₃]:
// the diagonal of three_body_chain plus bend–twist coupling within each joint and
// coupling between the two joints (symmetric positive definite: checked by the tests),
// as `flapsim reduce` produces (docs/reduction.md, "Joint stiffness by reciprocity").
inline ChainModel three_body_chain_coupled() {
  ChainModel m = three_body_chain();
  Eigen::Matrix4d k;
  k << 4e-3, 8e-4, -1.2e-3, 3e-4,  //
      8e-4, 1e-3, 2e-4, -2e-4,     //
      -1.2e-3, 2e-4, 2e-3, 4e-4,   //
      3e-4, -2e-4, 4e-4, 5e-4;
  Eigen::Matrix4d c;
  c << 1e-6, 1e-7, -2e-7, 0.0,  //
      1e-7, 1e-7, 0.0, -1e-8,   //
      -2e-7, 0.0, 1e-6, 2e-8,   //
      0.0, -1e-8, 2e-8, 1e-7;
  m.stiffness_matrix = k;
  m.damping_matrix = c;
  return m;
}

constexpr double kThreeBodyFrequency = 26.0;  // [Hz], rotation-phase paper eq. 5

// Eq. 5 of the rotation-phase paper in our convention R_GW = Rz(φ) Rx(θ) Ry(−α):
// φ = 60° cos 2πft, θ = 10° cos 4πft, and the paper's α = −60° sin 2πft measured from
// the vertical becomes α = 90° − 60° sin 2πft (as eq. 7, docs/kinematics.md).
inline WingKinematics three_body_kinematics() {
  WingKinematics k;
  k.frequency = kThreeBodyFrequency;
  k.sweep = PeriodicSignal::harmonic(0.0, {60.0 * kDegToRad}, {});
  k.deviation = PeriodicSignal::harmonic(0.0, {0.0, 10.0 * kDegToRad}, {});
  k.rotation = PeriodicSignal::harmonic(90.0 * kDegToRad, {}, {-60.0 * kDegToRad});
  return k;
}

// Eq. 6: Fx = 0.02 sin 2πft N, Fz = 0.04 cos 2πft N (ground components; our z is up,
// the paper's Z down: the sign of Fz is kept as written, our +z) at the joint between
// bodies 2 and 3 = outboard joint of body index 1.
inline void three_body_loads(double t, Loads& loads) {
  const double w = 2.0 * kPi * kThreeBodyFrequency;
  loads.clear();
  loads.add_force(1, Eigen::Vector3d(0.0, 0.0161, 0.0),
                  Eigen::Vector3d(0.02 * std::sin(w * t), 0.0, 0.04 * std::cos(w * t)),
                  LoadFrame::ground);
}

// A base that stays put (identity pose, no rotation).
inline BaseMotion fixed_base() {
  return [](double) { return BasePose{}; };
}

// A smooth, fully three-dimensional base motion with non-zero ω̇ about every axis.
inline WingKinematics wobbling_kinematics(double f) {
  WingKinematics k;
  k.frequency = f;
  k.sweep = PeriodicSignal::harmonic(0.1, {0.6}, {0.2});
  k.deviation = PeriodicSignal::harmonic(0.05, {0.1}, {0.15, 0.05});
  k.rotation = PeriodicSignal::harmonic(1.2, {0.3}, {-0.5});
  k.stroke_plane_angle = 0.2;
  return k;
}

// A 4-body chain with a sprung root, a non-trivial root offset and rotation, centres of
// mass off the axis and full (non-diagonal) inertia tensors: exercises every term.
inline ChainModel general_chain() {
  ChainModel m;
  m.root = RootAttachment::sprung;
  m.root_offset = Eigen::Vector3d(0.002, 0.003, -0.001);
  m.root_rotation = Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, 0.1, 1.0).normalized()).toRotationMatrix();
  for (int i = 0; i < 4; ++i) {
    ChainBody b;
    b.length = 0.01 + 0.002 * i;
    b.mass = 1e-5 * (1.0 + 0.3 * i);
    b.center_of_mass = Eigen::Vector3d(-0.001 + 0.0005 * i, 0.5 * b.length, 0.0003);
    Eigen::Matrix3d I;
    I << 3.0, 0.4, -0.2, 0.4, 1.0, 0.3, -0.2, 0.3, 3.5;
    b.inertia = I * 1e-10 * (1.0 + 0.2 * i);
    b.outboard_joint = Eigen::Vector3d(0.0002, b.length, -0.0001);
    m.bodies.push_back(b);
    ChainJoint j;
    j.bend_stiffness = 2e-3 / (1.0 + i);
    j.twist_stiffness = 6e-4 / (1.0 + i);
    j.bend_damping = 2e-7;
    j.twist_damping = 5e-8;
    j.bend_rest = 0.05 * i;
    j.twist_rest = -0.02 * i;
    m.joints.push_back(j);
  }
  return m;
}

}  // namespace flapsim::mbd::test
