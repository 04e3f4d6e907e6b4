#pragma once
/// \file trailing_edge_first_warning.hpp
/// \brief A warning for a wing that moves through the air trailing edge first.
///
/// The lattice sheds its wake at the wing file's trailing edge (the Kutta condition there)
/// and treats the other edge's suction as `leading_edge` says: it assumes that the trailing
/// edge trails. A wing whose angle of attack in the stream passes 90° (a revolving plate
/// set at 160°, a forward-flying wing's upstroke that the stream outruns) has its
/// geometric leading edge trailing, and its loads are then not a wing's: a plate revolving
/// in still air at 160° with `leading_edge = "none"` gave CL +1.64, CD −0.60 and a
/// negative aerodynamic power (CP −0.76), the air driving the wing (docs/kinematics.md,
/// "Which edge leads").

#include <string>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// The share of the last wingbeat that the span axis at r2·R spends moving trailing edge
/// first, weighted by the air's speed squared there (the dynamic pressure): the samples of
/// io::angle_of_attack_in_stream over the period before the run's end whose |angle| exceeds
/// 90° (by more than 1e-6 rad: a wing set at 90°, as a passively pitching film wing's root,
/// moves broadside), 720 of them. 0 without air or where the air is still against the wing
/// throughout.
double trailing_edge_first_share(const io::Case& c, const FsiSetup& setup);

/// Shares of this or more are warned (to kTrailingEdgeFirstRoundOff): the wing file's
/// trailing edge leads for as much of the wingbeat as it trails, or more. A symmetric hover
/// stroke whose rotation is written about 0° instead of 90° (`rotation = { sin_deg = [40.0]
/// }`: 40° on the downstroke, 220° on the upstroke) flies one half-stroke trailing edge first,
/// a share of exactly one half. (A hover whose rotation is far advanced has a smaller share:
/// the rotation-phase study's δψ = −0.20 0.31, the hawkmoth's stroke in a 10 m/s stream 0.24;
/// their lattice loads are suspect over that part, docs/kinematics.md.)
inline constexpr double kTrailingEdgeFirstShare = 0.5;

/// The share's round-off allowance: a half-stroke flown trailing edge first sums to one half
/// only to the rounding of its 720 samples' sums, which may fall on either side of it.
inline constexpr double kTrailingEdgeFirstRoundOff = 1e-9;

/// \brief "" or the warning for a run in air whose trailing_edge_first_share reaches
/// kTrailingEdgeFirstShare.
std::string trailing_edge_first_warning(const io::Case& c, const FsiSetup& setup);

}  // namespace flapsim::app
