#pragma once
/// \file root_clamp_warning.hpp
/// \brief The warning `mesh`, `check`, `modes`, `reduce` and an FEM run give for a root clamp
/// that holds only film: no vein node at or below clamp_y, and either the wing has veins (a
/// spar drawn from just above the clamp line) or the clamped nodes span little of the chord
/// (a pointed root). The wing then hangs on its membrane: a film wing's spar 0.4 mm above the
/// clamp line gave a first mode of 5.7 Hz against 36.6 Hz clamped, a 0.5 mm plate with a
/// pointed root (one node clamped) 3.3 Hz against 43.5 Hz (docs/wing_file.md, "Checks").

#include <string>

#include "fem/mesh.hpp"
#include "wings/loader/wing_model.hpp"

namespace flapsim::fem {

/// Clamped nodes spanning less than this share of the mean chord, with no vein among them,
/// hold the wing by a point.
inline constexpr double kNarrowClampChordShare = 0.25;

/// \brief "" or the warning for a root clamp (the nodes at or below wing.clamp_y) that holds
/// no vein node and either the wing has veins or its clamped nodes span less than
/// kNarrowClampChordShare of the mean chord.
std::string root_clamp_warning(const Mesh& mesh, const wings::Wing& wing);

}  // namespace flapsim::fem
