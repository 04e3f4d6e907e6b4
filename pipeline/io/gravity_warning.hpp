#pragma once
/// \file gravity_warning.hpp
/// \brief The warning for a case's `structure.gravity` that is almost certainly a mistake: a
/// magnitude far from any planet's (written in mm/s², or in g), or pointing up the ground
/// frame's z axis (docs/case_file.md, "[structure]"). Nothing checked it: [0, 0, -9810] (mm/s²)
/// flew a plate a thousand times its weight without a word, [0, 0, 9.81] pulled it up.

#include <optional>
#include <string>

#include <Eigen/Core>

#include "wings/loader/input_warning.hpp"

namespace flapsim::io {

/// The plausible magnitudes [m/s²]: between a small moon's (Ceres 0.28) and Jupiter's
/// (24.8) with a margin; outside, the likely unit mistake is named.
inline constexpr double kLeastPlausibleGravity = 0.1;
inline constexpr double kGreatestPlausibleGravity = 50.0;

/// The warning for \p gravity [m/s², ground frame, z up] at \p file, \p line (key
/// structure.gravity), or nullopt for a plausible one (or none: zero).
std::optional<InputWarning> gravity_warning(const Eigen::Vector3d& gravity, const std::string& file,
                                            int line);

}  // namespace flapsim::io
