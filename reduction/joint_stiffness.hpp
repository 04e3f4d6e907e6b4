#pragma once
/// \file joint_stiffness.hpp
/// \brief The chain's joint stiffness from the station compliance
/// (docs/reduction.md, "Joint stiffness by reciprocity").
///
/// The chain's jointed bodies f … N−1 each have a station (their mid-span); the joint
/// angles are differences of the stations' rotations, Φ = D r with r = [θ_f, φ_f, θ_{f+1},
/// …] and the clamp (or the welded bodies) not rotating:
///   θ-joint j = θ_j − θ_{j−1},  α-joint j = φ_j − φ_{j−1}.
/// A joint torque Q acts on the stations as the station moments Dᵀ Q (a moment pair on
/// the two bodies of the joint). Equal static response of chain and FEM to every joint
/// load, K⁻¹ Q = D C_rr Dᵀ Q, gives
///   K = (D C_rr Dᵀ)⁻¹,
/// symmetric positive definite because C_rr is and D is invertible; a full matrix that
/// keeps bend–twist coupling and joint-to-joint coupling.

#include <Eigen/Core>

#include <vector>

#include "reduction/station_compliance.hpp"

namespace flapsim::reduction {

struct JointStiffness {
  Eigen::MatrixXd stiffness;   ///< K over Φ [N m/rad]
  Eigen::MatrixXd compliance;  ///< K⁻¹ = D C_rr Dᵀ [rad/(N m)]
  Eigen::MatrixXd difference;  ///< D: station rotations → joint angles (2n × 2n)
  /// Smallest and largest eigenvalue of K [N m/rad] (> 0: positive definite).
  double min_eigenvalue = 0.0, max_eigenvalue = 0.0;
  /// The paper's diagonal springs from the same data: k = 1 / (K⁻¹)_jj, the joint's
  /// rotation under its own unit moment pair with every coupling dropped [N m/rad].
  Eigen::VectorXd diagonal_springs() const;
};

/// \brief K from the compliance of the jointed bodies' stations (station-major, 3 per
/// station: w, θ, φ), in the order of the bodies.
/// \throws ReductionFailure if D C_rr Dᵀ is not positive definite (a band without free nodes)
JointStiffness joint_stiffness(const Eigen::MatrixXd& station_compliance);

/// \brief Flexural axis at each station: the chordwise offset n from the station's
/// reference point at which a transverse force on the station causes no twist of it,
/// n_fa = C_φw / C_φφ (a force F at n is the station load (F, 0, −nF)) [m].
std::vector<double> flexural_axis_offsets(const Eigen::MatrixXd& station_compliance);

}  // namespace flapsim::reduction
