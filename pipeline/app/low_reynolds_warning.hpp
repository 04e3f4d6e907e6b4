#pragma once
/// \file low_reynolds_warning.hpp
/// \brief The run's Reynolds number and a warning where it is too low for the vortex lattice.
///
/// The lattice is inviscid and sheds its wake at the trailing edge (the Kutta condition):
/// the flow of large Reynolds numbers. Miller & Peskin (2004, J. Exp. Biol. 207, 3073–3088,
/// "When vortices stick: an aerodynamic transition in tiny insect flight") computed a wing's
/// stroke at Re 8 … 128: for Re ≥ 64 the leading- and trailing-edge vortices are shed
/// alternately; for Re ≤ 32 both stay attached through each half stroke, the asymmetry that
/// makes an insect's lift is lost and the lift falls while the drag rises. Below Re = 32 the
/// lattice's lift is therefore an overestimate and its drag, without viscous forces, far too
/// low (the smallest insects, thrips and fairyflies, fly at Re of order 10 and less).

#include <string>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// Re below which a run in air is warned (Miller & Peskin 2004, above).
inline constexpr double kLowestLatticeReynolds = 32.0;

/// Re = U c̄ / ν: U the larger of the free stream and the span's cycle-mean flapping speed at
/// r2·R (LiftReference: the lift coefficients' reference speed, but for a wing flapped faster
/// than a free stream, whose coefficients stay on the stream), the mean chord S/R and
/// numerics.kinematic_viscosity (air's 1.5e-5 m²/s by default). 0 without air.
double reynolds_number(const io::Case& c, const FsiSetup& setup);

/// "3.22 (U c/nu: 0.413 m/s at r2 of the span, mean chord 0.117 mm, nu 1.5e-05 m^2/s)":
/// reynolds_number with what it is made of (check's summary, the warning).
std::string describe_reynolds(const io::Case& c, const FsiSetup& setup);

/// \brief "" or the warning for a run in air below kLowestLatticeReynolds.
std::string low_reynolds_warning(const io::Case& c, const FsiSetup& setup);

}  // namespace flapsim::app
