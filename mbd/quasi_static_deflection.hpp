#pragma once
/// \file quasi_static_deflection.hpp
/// \brief How far the base motion's inertia alone bends a chain if the chain followed it
/// at once: the linear quasi-static deflection, a cheap estimate made before a run.
///
/// At each instant t the chain is held at its rest angles, at rest relative to the base
/// (Φ = Φ_rest, Φ̇ = Φ̈ = 0). The equations of motion M Φ̈ + H(Φ, Φ̇, t) = Q then leave the
/// inertial loads of the base's motion (centrifugal, Euler, Coriolis and the pivot's
/// acceleration; gravity if the model has it) unbalanced, and the springs would take them
/// with
///     K ΔΦ(t) = Q(t) − H(Φ_rest, 0, t)                 (H at rest: inertial terms only)
/// The chain's tip deflection is the sum of the joint angles: bend Σ Δθ_k, twist Σ Δα_k
/// (the same sums `peak_tip_bend_deg` of a run reports). A run's motion is this plus the
/// dynamics: a load applied at once moves an undamped oscillator to twice its static
/// deflection, a harmonic one near a resonance further ([Thomson & Dahleh 1998], ch. 3,
/// docs/references.md). So the estimate is a floor of what a run will show, not a bound.

#include <functional>

#include "mbd/base_motion.hpp"
#include "mbd/chain_data.hpp"
#include "mbd/chain_loads.hpp"
#include "mbd/chain_model.hpp"

namespace flapsim::mbd {

struct QuasiStaticDeflection {
  double tip_bend = 0.0;    ///< largest |Σ Δθ_k| over the samples [rad]
  double tip_twist = 0.0;   ///< largest |Σ Δα_k| over the samples [rad]
  double joint_angle = 0.0; ///< largest |ΔΦ_i| of one joint angle [rad]
  int joint = -1;           ///< the body (0-based) inboard of whose joint that angle is
  bool twist = false;       ///< that angle is a twist (else a bend)
  double time = 0.0;        ///< the instant of the largest tip bend or twist [s]
};

/// \brief The largest linear quasi-static deflection over `samples` instants t = t0 + k T / samples
/// of one period T [s] of the base motion (external loads none).
/// \throws std::invalid_argument if the chain has no joints, K is singular, T ≤ 0 or samples < 1
QuasiStaticDeflection peak_quasi_static_deflection(const ChainModel& model, const BaseMotion& base,
                                                   double period, int samples, double t0 = 0.0);

/// The external loads at instant t [s] on the chain held at its rest angles, at rest relative
/// to the base (`data` holds its body kinematics then): an estimate of the fluid's, say.
using QuasiStaticLoads = std::function<void(double t, const ChainData& data, Loads& loads)>;

/// \brief The same with the external loads of `loads_at` added at each instant to the
/// inertial ones (K ΔΦ = Q_ext + Q − H at rest).
QuasiStaticDeflection peak_quasi_static_deflection(const ChainModel& model, const BaseMotion& base,
                                                   double period, int samples,
                                                   const QuasiStaticLoads& loads_at, double t0 = 0.0);

}  // namespace flapsim::mbd
