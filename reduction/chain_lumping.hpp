#pragma once
/// \file chain_lumping.hpp
/// \brief Lumping the clamped FEM into an N_b-body Hencky bar chain on the flexural
/// axis: bodies with the mass, centre of mass and inertia tensor of their strip, and
/// the joint stiffness K from the stations' compliance by reciprocity
/// (docs/reduction.md, "Lumping into a Hencky bar chain", "Joint stiffness by reciprocity").

#include <vector>

#include "mbd/chain_model.hpp"
#include "reduction/clamped_wing_analysis.hpp"
#include "reduction/joint_stiffness.hpp"
#include "reduction/station_compliance.hpp"

namespace flapsim::reduction {

/// How the chain's springs are made from the joint stiffness K.
enum class SpringModel {
  full,      ///< K itself: bend–twist and joint-to-joint coupling (exact at the stations)
  diagonal,  ///< the papers' independent springs k = 1/(K⁻¹)_jj (coupling dropped)
};

/// The chain and where it came from.
struct LumpedChain {
  mbd::ChainModel chain;         ///< root frame = axis frame at the pivot
  double body_length = 0.0;      ///< a = s_tip / N_b [m]
  std::vector<double> joint_s;   ///< axis position of each body's inboard joint [m]
  double fem_mass = 0.0;         ///< Φᵀ M Φ mass of the FEM [kg]
  /// The stations of the jointed bodies (mid-span and outboard joint of each, in turn)
  /// and their compliance.
  StationCompliance stations;
  /// The jointed bodies (0-based) and the flexural axis n_fa at their mid-spans from C [m].
  std::vector<int> station_body;
  std::vector<double> flexural_axis_n;
  /// K = (T C Tᵀ)⁻¹ over the chain's Φ and its inverse.
  JointStiffness joint_stiffness;
  SpringModel springs = SpringModel::full;
};

/// \brief Refuses an \p num_bodies-body chain whose every body lies inside the root clamp (its
/// mid-span within it): nothing would move.
/// \throws ReductionInputLimit naming the clamp's reach and the body length
void check_bodies_outside_clamp(const ClampedWingAnalysis& analysis, int num_bodies);

/// \brief Lumps the FEM into \p num_bodies equal bodies from the pivot to the tip.
/// Bodies whose mid-span lies inside the root clamp are welded to the root.
/// \param analysis    the clamped FEM
/// \param num_bodies  N_b ≥ 1
/// \param springs     full K (default) or the diagonal springs
/// \throws ReductionFailure in words (body numbers from 1) when a body's section has
///         too few free FEM nodes or every body lies in the clamp
LumpedChain lump_into_chain(const ClampedWingAnalysis& analysis, int num_bodies = 10,
                            SpringModel springs = SpringModel::full);

}  // namespace flapsim::reduction
