#pragma once
/// \file core_growth.hpp
/// \brief Viscous growth of the wake's vortex cores with age (docs/uvlm.md, "Wake").
///
/// A Lamb–Oseen vortex diffuses: its core radius (the radius of peak swirl velocity)
/// grows as r_c² = r_c0² + 4 α_L ν t, α_L = 1.25643 [Lamb 1932; Oseen 1912]. Squire
/// replaced ν by an eddy viscosity δν for the turbulent vortices of real wakes
/// [Squire 1965]; free-vortex-wake codes for rotors take δ from the vortex Reynolds
/// number, δ = 1 + a1 Γ/ν, with a1 ≈ 2e-4 from rotor tip-vortex measurements
/// [Bhagwat & Leishman 2002; Leishman 2006, ch. 10]:
///     r_c(t)² = r_c0² + 4 α_L δ ν t,   δ = 1 + a1 |Γ| / ν,
/// with t the segment's age since it left the trailing edge and Γ its own circulation.

#include "uvlm/biot_savart_kernel.hpp"

#include <cmath>

namespace flapsim::uvlm {

struct CoreGrowth {
  bool enabled = false;
  double kinematic_viscosity = 1.5e-5;  ///< ν of air [m²/s] (1.5e-5 at 20 °C, 1 atm)
  double squire_a1 = 2e-4;              ///< a1 of δ = 1 + a1 Γ/ν [Bhagwat & Leishman 2002]
};

/// Squire's eddy-viscosity factor δ = 1 + a1 |Γ|/ν for circulation gamma [m²/s].
inline double eddy_viscosity_factor(const CoreGrowth& g, double gamma) {
  return 1.0 + g.squire_a1 * std::abs(gamma) / g.kinematic_viscosity;
}

/// Core radius squared [m²] at age [s] of a vortex born with core rc0 [m] and circulation gamma [m²/s].
inline double grown_core_radius2(const CoreGrowth& g, double rc0, double age, double gamma) {
  if (!g.enabled) return rc0 * rc0;
  return rc0 * rc0 + 4.0 * detail::kLambOseen * eddy_viscosity_factor(g, gamma) * g.kinematic_viscosity * age;
}

}  // namespace flapsim::uvlm
