#pragma once
/// \file chain_dynamics.hpp
/// \brief The equations of motion of the chain, M(Φ,t) Φ̈ + H(Φ,Φ̇,t) = Q:
/// the mass matrix M = Σ J_vᵀ m J_v + J_ωᵀ I J_ω (the composite-rigid-body matrix,
/// assembled from the body Jacobians), the inertial bias of H by Newton–Euler with the
/// bias accelerations of forward_kinematics (base ω, ω̇ included), and the springs
/// and dampers K(Φ − Φ_rest) + C Φ̇ with the full K and C of the model.

#include "mbd/base_motion.hpp"
#include "mbd/chain_data.hpp"
#include "mbd/chain_loads.hpp"
#include "mbd/chain_model.hpp"

#include <Eigen/Core>

namespace flapsim::mbd {

/// Mass matrix and inertial bias at the state of the last forward_kinematics, into
/// data.mass_matrix and data.inertial_bias.
void compute_mass_matrix_and_bias(const ChainModel& model, ChainData& data);

/// Spring and damper torques K(Φ − Φ_rest) + C Φ̇ into data.spring_force [N m].
void compute_spring_forces(const ChainModel& model, ChainData& data, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& v);

/// Everything at one state: kinematics, M, H (inertial + springs), Q.
/// \param base   base pose at this instant
/// \param loads  external loads (may be an empty Loads(0) for none)
void compute_all_terms(const ChainModel& model, ChainData& data, const BasePose& base,
                       const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Loads& loads);

/// Φ̈ = M⁻¹ (Q − H) at one state [rad/s²]. Leaves data at that state with full
/// accelerations (update_accelerations applied).
/// \param qdd  output, size num_dofs
void forward_dynamics(const ChainModel& model, ChainData& data, const BasePose& base,
                      const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Loads& loads,
                      Eigen::VectorXd& qdd);

}  // namespace flapsim::mbd
