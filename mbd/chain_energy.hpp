#pragma once
/// \file chain_energy.hpp
/// \brief Energies and powers of the chain, for energy-balance checks and output:
/// d(T + V)/dt = P_base + P_loads − Φ̇ᵀ C Φ̇, with T the kinetic energy in the ground
/// frame, V the spring energy, P_base the power the prescribed base motion puts in.

#include "mbd/base_motion.hpp"
#include "mbd/chain_data.hpp"
#include "mbd/chain_loads.hpp"
#include "mbd/chain_model.hpp"

#include <Eigen/Core>

namespace flapsim::mbd {

/// Kinetic energy in the ground frame [J] at the state of the last forward_kinematics.
double kinetic_energy(const ChainModel& model, const ChainData& data);

/// Spring energy ½ (Φ − Φ_rest)ᵀ K (Φ − Φ_rest) [J].
double spring_energy(const ChainModel& model, const Eigen::VectorXd& q);

/// Power dissipated by the dampers Φ̇ᵀ C Φ̇ [W] (≥ 0).
double damper_power(const ChainModel& model, const Eigen::VectorXd& v);

/// The force F and the moment N about the pivot that the base exerts on the chain
/// (ground components): what the drive must supply.
struct BaseReaction {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< [N]
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< about the pivot [N m]
};

/// The base's force and moment from the chain's rates of momentum and angular momentum
/// minus the loads and gravity. Needs full accelerations (as base_power).
BaseReaction base_reaction(const ChainModel& model, const ChainData& data, const BasePose& base,
                           const Loads& loads);

/// Power the base puts into the chain [W]: ω_base · N + v_pivot · F, where N (about the
/// pivot) and F are the moment and force the base exerts on the chain, from the chain's
/// rates of momentum and angular momentum minus the loads and gravity. Needs full accelerations
/// (forward_dynamics, or forward_kinematics + update_accelerations).
double base_power(const ChainModel& model, const ChainData& data, const BasePose& base,
                  const Loads& loads);

}  // namespace flapsim::mbd
