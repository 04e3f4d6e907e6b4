#pragma once
/// \file chain_lumping.hpp
/// \brief Lumping the clamped FEM into an N_b-body Hencky bar chain on the flexural
/// axis: bodies with the mass, centre of mass and inertia tensor of their strip,
/// joint springs from the cell compliances under a unit moment and a unit torque
/// (docs/reduction.md, "Lumping into a Hencky bar chain").

#include <vector>

#include "mbd/chain_model.hpp"
#include "reduction/clamped_wing_analysis.hpp"

namespace flapsim::reduction {

/// The chain and where it came from.
struct LumpedChain {
  mbd::ChainModel chain;         ///< root frame = axis frame at the pivot
  double body_length = 0.0;      ///< a = s_tip / N_b [m]
  std::vector<double> joint_s;   ///< axis position of each body's inboard joint [m]
  /// Axis positions of the sections whose rotations under the unit moment / torque
  /// gave each joint's springs (the joint's cell; zero for a rigid root) [m].
  std::vector<double> cell_start, cell_end;
  double fem_mass = 0.0;         ///< Φᵀ M Φ mass of the FEM [kg]
};

/// \brief Lumps the FEM into \p num_bodies equal bodies from the pivot to the tip.
/// \param analysis    the clamped FEM and its load cases
/// \param num_bodies  N_b ≥ 1
/// \throws std::invalid_argument if a joint's cell reaches into the loaded tip zone
///         (too many bodies for the tip zone: lower N_b or the zone length)
LumpedChain lump_into_chain(const ClampedWingAnalysis& analysis, int num_bodies = 10);

}  // namespace flapsim::reduction
