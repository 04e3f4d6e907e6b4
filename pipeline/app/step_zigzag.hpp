#pragma once
/// \file step_zigzag.hpp
/// \brief A motion at the time step's rate in a recorded angle: the angle turns back at two
/// steps in a row (it rises, falls, rises, or the reverse), which a motion the steps resolve
/// never does; a smooth motion turns back at most once in a few steps, at its extremes. Such
/// a motion is the integrator's, not the wing's: an unresolved mode into which the
/// generalized-α scheme pumps energy through the structure's nonlinearity (docs/fem.md,
/// "Energy over 100 periods"), as a thin plate's FEM did with ρ∞ = 0.9 (docs/fsi.md, "A tip
/// that zigzags from step to step").

#include <vector>

namespace flapsim::app {

/// A run whose tip angles zigzag by more than this is warned after it (run_results.hpp) [deg].
/// The nine shipped flexible cases zigzag by 0.23° at most (the 25 µm MAV film's FEM; the
/// hawkmoth's FEM and chain hovers not at all), the phase studies' chains with `shed` by 0.48°
/// (measured 5 Dec); the plates of docs/fsi.md's record by 3–6° with ρ∞ = 0.9 and 0.18° or less
/// with 0.5 but one (1.9°); a slender chain whose twist rang with 3–4 steps a period by 1.3°.
inline constexpr double kStepZigzagWarnedDeg = 1.0;

/// The largest zigzag of an angle series and where it is.
struct StepZigzag {
  double amplitude = 0.0;  ///< half the smallest of the three steps of the zigzag [the series' unit]
  long step = 0;           ///< the 1-based sample of the first turn back (0: none)
};

/// \brief The largest zigzag of \p angle_rad (one sample a step): over each four consecutive
/// samples whose three steps alternate in sign, half the smallest step; steps are taken
/// modulo 2π (an angle through ±180° is no turn back).
StepZigzag largest_step_zigzag(const std::vector<double>& angle_rad);

}  // namespace flapsim::app
