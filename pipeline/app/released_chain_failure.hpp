#pragma once
/// \file released_chain_failure.hpp
/// \brief What to add to a run's numerical failure when its chain was released from bent
/// joints: such a start rings in the chain's stiffest modes, far faster than a step, and in
/// air the coupling can diverge on them while ρ∞ leaves them undamped (docs/case_file.md,
/// "[structure]": the flat plate of test app.SplitStepAddedMass as 8 bodies, every joint
/// bent 1°, stopped at steps 2–7 at 60–120 steps a cycle with ρ∞ = 0.9 and ran with 0.7).

#include <string>

#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// ρ∞ at or below which every released start of the measurements above ran.
inline constexpr double kReleasedChainRhoInfinity = 0.7;

/// \brief "" or a sentence for the failure of a flexible case in air whose chain starts with
/// nonzero `initial_angles_deg` or `initial_rates_deg_per_s`, failed within its first
/// cycle (failed_step, 0-based, below steps_per_cycle) with rho_infinity above
/// kReleasedChainRhoInfinity: names the key and its line, and the remedy.
std::string released_chain_at_failure(const io::Case& c, long failed_step);

}  // namespace flapsim::app
