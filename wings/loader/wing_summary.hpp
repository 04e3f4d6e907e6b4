#pragma once
/// \file wing_summary.hpp
/// \brief A short human-readable summary of a wing (what `flapsim check` prints).

#include <string>

#include "wings/loader/wing_model.hpp"

namespace flapsim::wings {

/// Multi-line text: span [mm], area [mm²], mean chord [mm], aspect ratio, r2/R,
/// veins, membrane, estimated mass [mg], clamp and mesh sizes.
std::string describe_wing(const Wing& wing);

}  // namespace flapsim::wings
