#pragma once
/// \file skin_friction.hpp
/// \brief Laminar skin friction on the lattice's panels (an option; the lattice is
/// otherwise inviscid).
///
/// Each panel feels, on its two sides together, the mean skin friction of a flat plate in a
/// laminar boundary layer (Blasius; Schlichting & Gersten, Boundary-Layer Theory, ch. 6:
/// c_f = 1.328/√Re_c per side over a plate of chord c), with the air's speed relative to the
/// panel tangential to it, u_t, and the strip's chord c:
///   f = ½ ρ |u_t|² · 2A · 1.328 / √(|u_t| c / ν),  along u_t.
/// u_t is the tangential part of the free stream, the wake's induced velocity and the
/// surface's motion at the collocation point; the jump of the tangential velocity across the
/// bound vorticity (faster on the suction side) is left out, as are transition, the
/// leading-edge vortex's own shear and separated-flow friction: an estimate of the viscous
/// drag a flat plate at insect Reynolds numbers has and the lattice lacks (docs/uvlm.md,
/// "Skin friction").

#include "uvlm/vortex_lattice.hpp"

namespace flapsim::uvlm {

/// Blasius' mean laminar skin-friction coefficient of one side of a flat plate,
/// 1.328 / √Re_c (Re_c > 0).
double blasius_mean_skin_friction(double reynolds);

/// Adds the skin friction to d.loads.force (m.skin_friction_viscosity > 0; nothing otherwise)
/// and to d.loads.skin_friction_force; call before the loads' totals.
void add_skin_friction(const VortexLatticeModel& m, VortexLatticeData& d);

}  // namespace flapsim::uvlm
