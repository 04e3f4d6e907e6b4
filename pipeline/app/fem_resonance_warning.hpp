#pragma once
/// \file fem_resonance_warning.hpp
/// \brief The near-resonance warning of a `kind = "fem"` case, as the chain's
/// (near_resonance_warning, flexibility_warnings.hpp) from the FEM's own natural modes: the
/// wing clamped where the run drives it, in vacuum, from the mesh and materials the run
/// uses (the case's element sizes), by the modal solver of `flapsim modes`
/// (fem/modal_solver.hpp). A 13 mm wing of a 4 µm membrane (tests/data/
/// bumblebee_forewing_4um.toml), its first mode 186.5 Hz, flapped at 150 Hz on its FEM: its
/// tip bent past 75° within a fifth of a wingbeat, and nothing warned; the chain of the same
/// wing was warned.

#include <string>
#include <vector>

#include "fem/mode_classification.hpp"
#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// At most this many modes are solved for (fem_resonance_modes): a wing with more below
/// 2.83 f is warned about from its lowest ones.
inline constexpr int kMaxFemResonanceModes = 32;

/// The FEM's lowest natural modes, lowest first.
struct FemNaturalModes {
  std::vector<double> frequencies_hz;  ///< [Hz]
  std::vector<fem::ModeKind> kinds;    ///< fem::classify_modes (the shape column of `flapsim modes`)
};

/// \brief The lowest modes of a `kind = "fem"` case's FEM (clamped as the run drives it:
/// FemStructureModel::dynamics.eliminated; K and M assembled as `flapsim modes` does):
/// 4 modes, then twice as many while the highest found lies below highest_resonant_mode_hz
/// (2.83 f), up to kMaxFemResonanceModes. Empty for any other case.
/// \throws what fem::solve_modes throws (a mechanism, Lanczos not converging)
FemNaturalModes fem_resonance_modes(const io::Case& c, const FsiSetup& setup);

/// \brief "" or the warning for a `kind = "fem"` case with a mode of its FEM whose dynamic
/// amplification at the wingbeat frequency f or at 2 f is kResonantAmplification or more
/// (strongest_resonance, the chain's band: 0.82…1.41 f or 1.63…2.83 f); names the mode, its
/// kind by its shape, its frequency, the ratio and the amplification. "" if the modal solve
/// fails (the run's own solves then speak). A first mode below the band (below
/// lowest_resonant_mode_hz, 0.82 f) is warned instead as a wing driven above its first mode:
/// it deforms against its base by about as much as the base moves (a 300 mm veinless film
/// of 37.5 µm flapped at 100 Hz stopped in its FEM's first step with nothing said but its
/// Mach number and its film).
std::string fem_near_resonance_warning(const io::Case& c, const FsiSetup& setup);

}  // namespace flapsim::app
