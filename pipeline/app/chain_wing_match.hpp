#pragma once
/// \file chain_wing_match.hpp
/// \brief A warning when a case's chain file does not seem to come from the case's wing:
/// the lattice follows the wing's outline while the structure is another wing's
/// (a hawkmoth chain, 33.8 mg, run with a 70.9 mg tapered plate: no word before).

#include <string>

#include "pipeline/app/fsi_setup.hpp"

namespace flapsim::app {

/// Relative difference of mass or length [-] beyond which the chain and the wing are said
/// not to match. `flapsim reduce` keeps the wing's mass (hawkmoth: chain 33.799 mg, wing
/// 33.800 mg) and reaches its tip (48.45 mm for a 48.30 mm span, 49.86 mm for 50 mm); 5 %
/// is a margin above that, a convention.
inline constexpr double kChainWingMismatch = 0.05;

/// \brief "" or the warning for a chain read from a file whose total mass or length
/// (root offset plus the bodies) differs from the case's wing (its estimated mass; its
/// reach along the chain's axis: the span R for an axis along the wing frame's y, the
/// outline's farthest point along a swept axis) by more than kChainWingMismatch; names both
/// numbers of each. (Before: always the span, so a wing's own chain along a swept axis was
/// warned, 34.6 mm against a 32 mm span.)
std::string chain_wing_mismatch_warning(const FsiSetup& setup);

}  // namespace flapsim::app
