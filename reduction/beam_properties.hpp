#pragma once
/// \file beam_properties.hpp
/// \brief The equivalent Euler–Bernoulli beam of a wing: per-station mass, centre of
/// mass, elastic axis, bending and torsional stiffness and torsional mass moment of
/// inertia along the flexural axis (docs/reduction.md).

#include <vector>

#include "reduction/clamped_wing_analysis.hpp"

namespace flapsim::reduction {

/// One beam station: the properties of the cell [s_start, s_end] of the axis.
struct BeamStation {
  double s = 0.0;            ///< cell centre along the axis [m]
  double s_start = 0.0, s_end = 0.0;  ///< cell edges [m]
  double y = 0.0;            ///< y_W of the axis point at s [m]
  double mass_per_length = 0.0;  ///< m′ [kg/m]
  double n_cg = 0.0;         ///< chordwise centre of mass from the axis (+ toward the LE) [m]
  double x_cg = 0.0;         ///< the centre of mass's x_W [m]
  double n_ea = 0.0;         ///< local elastic axis from the axis [m]
  double x_ea = 0.0;         ///< local elastic axis's x_W [m]
  double EI = 0.0;           ///< bending stiffness [N m²]
  double GJ = 0.0;           ///< torsional stiffness [N m²]
  double I_alpha = 0.0;      ///< mass moment of inertia per length about the axis [kg m]
  bool in_tip_zone = false;  ///< stiffness copied from the last cell clear of the loaded tip zone (one zone length inboard)
};

/// The beam.
struct BeamProperties {
  /// The default fitted axis was rejected (it left the planform) and the flexural axis
  /// taken instead (ClampedWingAnalysis::fitted_axis_rejected); its angle [rad].
  bool fitted_axis_rejected = false;
  double fitted_psi_rejected = 0.0;
  AxisFrame axis;
  double s_root = 0.0, s_tip = 0.0;   ///< flexible span along the axis [m]
  double total_mass = 0.0;            ///< FEM mass Φᵀ M Φ [kg]
  double strip_mass_sum = 0.0;        ///< Σ of the stations' masses [kg]
  double n_ea_tip = 0.0;              ///< mean elastic axis from the two tip twists [m]
  /// Twist under the unit bending moment relative to the twist under the unit torque,
  /// at the tip zone's edge: size of the bending–torsion coupling the chain leaves out [-].
  double bend_twist_coupling = 0.0;
  /// Cells whose EI (GJ) is not identified: their sections turned against the unit moment
  /// (torque) or not at all, Δθ·M ≤ 0 (a film beyond its rods: its sections' fit follows the
  /// film, which twists about the spar, not the spar that carries the moment); NaN there.
  int unidentified_ei = 0, unidentified_gj = 0;
  std::vector<BeamStation> stations;
};

/// \brief Extracts the beam: N cells from the clamp to the tip.
/// \param analysis      the clamped FEM and its load cases
/// \param num_stations  number of cells N (≥ 2)
BeamProperties extract_beam_properties(const ClampedWingAnalysis& analysis, int num_stations = 40);

}  // namespace flapsim::reduction
