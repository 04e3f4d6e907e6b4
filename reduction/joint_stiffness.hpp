#pragma once
/// \file joint_stiffness.hpp
/// \brief The chain's joint stiffness from the station compliance
/// (docs/reduction.md, "Joint stiffness by reciprocity").
///
/// Each jointed body i = 0 … n−1 (the bodies f … N−1 of the chain) has two stations: one
/// at its mid-span and one at its outboard joint. The chain's kinematics are the Hencky
/// chain's: its joints lie on the FEM's deflected axis and its bodies are the chords
/// between them, so a body's bending rotation is the chord slope of the deflections w at
/// its two joints, and its twist is the twist φ of its mid-span station:
///   θ_i = (w_i − w_{i−1}) / a   (w_i at body i's outboard joint; w_{−1} = 0, the inboard
///                                joint of the first jointed body does not move),
///   θ-joint i = θ_i − θ_{i−1},  α-joint i = φ_i − φ_{i−1}   (θ_{−1} = φ_{−1} = 0).
/// With u the stations' motion (w, θ, φ per station) the joint angles are Φ = T u, T = D P:
/// P picks (w at the outboard joint, φ at the mid-span) of each body, D the differences above.
/// A joint load Q acts on the FEM as the station loads Tᵀ Q: a bending moment at a joint
/// becomes three transverse forces at the neighbouring joint stations (±1/a, ∓2/a: the same
/// moments on the chain's bodies), a torque a pair of station torques. Equal static response
/// of chain and FEM to every joint load, K⁻¹ Q = T C Tᵀ Q, gives
///   K = (T C Tᵀ)⁻¹,
/// symmetric positive definite because C is and T has full row rank. A transverse force F at
/// the chain's tip (the last body's outboard joint) is the station load F on that joint
/// station, which is Tᵀ Q for the chain's generalized force Q of F: carried exactly as well.

#include <Eigen/Core>

#include <vector>

#include "reduction/station_compliance.hpp"

namespace flapsim::reduction {

struct JointStiffness {
  Eigen::MatrixXd stiffness;   ///< K over Φ [N m/rad]
  Eigen::MatrixXd compliance;  ///< K⁻¹ = T C Tᵀ [rad/(N m)]
  /// T: the stations' motion (3 per station, mid-span and outboard-joint station of each
  /// jointed body in turn) → joint angles (2n × 6n) [1/m, -, -].
  Eigen::MatrixXd joint_map;
  /// Smallest and largest eigenvalue of K [N m/rad] (> 0: positive definite).
  double min_eigenvalue = 0.0, max_eigenvalue = 0.0;
  /// The paper's diagonal springs from the same data: k = 1 / (K⁻¹)_jj, the joint's
  /// rotation under its own unit joint load with every coupling dropped [N m/rad].
  Eigen::VectorXd diagonal_springs() const;
  /// Joint angles Φ = T u of the stations' motion \p u [rad].
  Eigen::VectorXd joint_angles(const Eigen::VectorXd& u) const { return joint_map * u; }
  /// Station loads Tᵀ Q of the joint loads \p q [N, N m].
  Eigen::VectorXd station_loads(const Eigen::VectorXd& q) const { return joint_map.transpose() * q; }
};

/// \brief The station → joint-angle map T for \p num_bodies jointed bodies of length
/// \p body_length [m], stations ordered (mid-span, outboard joint) per body.
Eigen::MatrixXd chain_joint_map(int num_bodies, double body_length);

/// \brief K from the compliance of the jointed bodies' stations (station-major, 3 per
/// station: w, θ, φ; mid-span and outboard-joint station of each body in turn).
/// \throws ReductionFailure if T C Tᵀ is not positive definite (a band without free nodes)
JointStiffness joint_stiffness(const Eigen::MatrixXd& station_compliance, double body_length);

/// \brief Flexural axis at each station: the chordwise offset n from the station's
/// reference point at which a transverse force on the station causes no twist of it,
/// n_fa = C_φw / C_φφ (a force F at n is the station load (F, 0, −nF)) [m].
std::vector<double> flexural_axis_offsets(const Eigen::MatrixXd& station_compliance);

}  // namespace flapsim::reduction
