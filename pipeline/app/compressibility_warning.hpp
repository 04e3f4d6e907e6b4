#pragma once
/// \file compressibility_warning.hpp
/// \brief A warning for a case whose wing tip moves through the air so fast that the
/// incompressible vortex lattice no longer holds (often a frequency in the wrong unit: a
/// hawkmoth at frequency_hz = 2610 ran silently with 72.7 N of lift, its tip at up to 691 m/s).

#include <string>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// Speed of sound in air at 20 °C [m/s] (c = sqrt(γ R T), γ = 1.4, R = 287 J/(kg K)).
inline constexpr double kSpeedOfSound = 343.0;

/// Mach number from which the case is warned about: the Prandtl–Glauert factor
/// 1/sqrt(1 − M²) on the pressures ([Anderson 2011] ch. 11, docs/references.md) is
/// 1.048 there, a 5 % effect the vortex lattice (incompressible) leaves out. A convention.
inline constexpr double kIncompressibleMach = 0.3;

/// \brief "" or the warning for a case in air whose wing tip meets the air (its velocity
/// against the free stream, the span axis at R, sampled over one cycle) faster than
/// kIncompressibleMach × kSpeedOfSound; names the speed, the Mach number and the likely
/// unit mistake.
std::string compressibility_warning(const io::Case& c, const FsiSetup& setup);

}  // namespace flapsim::app
