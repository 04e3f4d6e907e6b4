#pragma once
/// \file station_mode_kind.hpp
/// \brief Names an FEM mode from the motion of the chain's stations (the beam), so that
/// film modes are not called bending (docs/reduction.md, "Mode kinds from the stations").
///
/// In each station's band the nodes' u_z is split into the rigid-section motion
/// B u_k (u_k = A_kᵀ x, the station's averaged motion) and the rest (camber, film
/// bulging). The *beam share* is the mass-weighted share of the rigid-section part,
/// Σ W (B u)² / Σ W u_z², over all bands. A mode with a beam share below one half is a
/// film mode; otherwise it is bending or torsion by where the joint stiffness stores its
/// energy: Φ = T u from the stations' motion u (joint_stiffness.hpp), bending when Φ_θᵀ K_θθ Φ_θ ≥ Φ_αᵀ K_αα
/// Φ_α. Before either, a mode whose bands move mostly in the wing's plane (Σ m (u_x² + u_y²) above half of Σ
/// m |u|²) is an in-plane mode: the beam share, a share of u_z alone, says nothing of it, and the chain,
/// out-of-plane bending and torsion only, has no such mode.

#include <Eigen/Core>

#include <string>
#include <vector>

#include "reduction/chain_lumping.hpp"

namespace flapsim::reduction {

enum class StationModeKind { bending, torsion, film, in_plane };

/// "bending", "torsion", "film", "in-plane".
std::string to_string(StationModeKind kind);

struct StationModeMeasures {
  double beam_share = 0.0;     ///< mass-weighted share of u_z that the stations' rigid sections carry [-]
  double bending_share = 0.0;  ///< share of the joint-stiffness energy in the θ block [-]
  double in_plane_share = 0.0;  ///< mass-weighted share of the bands' motion in the wing's plane [-]
  StationModeKind kind = StationModeKind::film;
  Eigen::VectorXd
      joint_angles;  ///< Φ = T u: the mode in the chain's coordinates [rad] (the MAC's, reduction_report.cpp)
};

/// \brief Measures and kind of the FEM mode shape \p shape (full DOF vector).
StationModeMeasures classify_by_stations(const LumpedChain& chain, const Eigen::VectorXd& shape);

/// \brief Kinds of every column of \p shapes.
std::vector<StationModeMeasures> classify_modes_by_stations(const LumpedChain& chain, const Eigen::MatrixXd& shapes);

}  // namespace flapsim::reduction
