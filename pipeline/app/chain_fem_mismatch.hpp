#pragma once
/// \file chain_fem_mismatch.hpp
/// \brief The warning about a chain that misses the FEM's first bending or torsion mode:
/// `flapsim reduce` says it when it makes the chain, and records the comparison in the
/// chain file ([fem_comparison], chain_file.hpp); `run`, `check` and `sweep` of that chain
/// file repeat it, so a user who runs from a saved chain sees it too, and say it of a wing
/// they reduce in process (structure_source.cpp compares it as reduce does; docs/reduction.md).

#include <string>

#include "pipeline/app/fsi_setup.hpp"
#include "reduction/reduction_report.hpp"

namespace flapsim::app {

/// Chain against FEM, first bending or torsion frequency: beyond this relative error [-]
/// the chain is said not to represent the wing well. A convention (a beam's first modes
/// within 10 %), stated in docs/reduction.md.
inline constexpr double kChainFemMismatch = 0.10;

/// \brief Whether \p m is a mode both models have and the chain misses by more than
/// kChainFemMismatch.
bool misses_fem_mode(const reduction::ModeMatch& m);

/// Chain against FEM, a static row of report.md (tip deflection under the tip force and twist
/// under the tip torque, read in the chain's coordinates at the measuring body; bending rotation
/// conjugate to a moment spread over the chain's tip body, on both sides): beyond this relative
/// error [-] reduce warns. The same convention as the modes (docs/reduction.md, "Checking the
/// chain against the FEM").
inline constexpr double kChainFemStaticMismatch = 0.10;

/// \brief Whether the chain's static response \p m misses the FEM's by more than
/// kChainFemStaticMismatch (a FEM value of 0, whose error is NaN, is not a miss).
bool misses_fem_static(const reduction::StaticMatch& m);

/// \brief Whether the chain's bodies are shorter than the FEM's mean element edge: each body's
/// section is then measured from less than one element, and more bodies no longer approach
/// the FEM (a 2.5 mm fruit-fly wing on 0.05 mm elements, first bending against the FEM:
/// +0.95, +2.5, -0.87, -9.5 % at 6, 24, 48, 100 bodies; docs/reduction.md).
bool bodies_shorter_than_elements(const reduction::ChainFemComparison& c);

/// \brief "" or reduce's warning that the bodies are shorter than the FEM's elements, with
/// the largest body count that keeps them an element long.
std::string short_bodies_warning(const reduction::ChainFemComparison& c);

/// \brief The advice for a chain that misses the FEM: more bodies, unless they are already
/// shorter than the FEM's elements (then a finer mesh).
std::string more_bodies_advice(const reduction::ChainFemComparison& c);

/// \brief "" or reduce's warning about the static rows the chain misses (each named with both
/// values and its error; docs/reduction.md, "Measured limitation"), pointing at \p report.
std::string static_mismatch_warning(const reduction::ChainFemComparison& c, const std::string& report);

/// \brief "" or one line for a run whose chain misses the FEM's first bending or torsion
/// mode: a chain file whose [fem_comparison] says so, or a wing reduced in process (each kind missed named with its
/// frequencies, relative error and MAC). With --spring-scale S the chain's frequencies are
/// those of the file × √S (every spring × S, the masses unchanged), and the error is taken
/// on them.
std::string saved_chain_fem_warning(const FsiSetup& setup);

/// \brief "" or one line for a run whose chain misses a static row of reduce's comparison
/// with the FEM by more than kChainFemStaticMismatch (static_mismatch_warning's rows): a chain
/// file whose [fem_comparison] records them, or a wing reduced in process. The rows are the
/// chain's as reduced, whatever --spring-scale (saved_chain_fem_warning names the scale).
std::string saved_chain_static_warning(const FsiSetup& setup);

}  // namespace flapsim::app
