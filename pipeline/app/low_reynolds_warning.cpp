#include "pipeline/app/low_reynolds_warning.hpp"

#include <cstdio>

namespace flapsim::app {

namespace {

// The wing's speed through the air that sets its Reynolds number [m/s]: the larger of the free
// stream and the span's cycle-mean flapping speed at r2 R. The coefficients' reference speed
// is the free stream's wherever there is one, but a wing flapped at 2 m/s in a 0.02 m/s stream
// meets the air at 2 m/s (its Re was the stream's, 1 % of it, and warned as a fairyfly's).
bool flapping_sets_reynolds(const FsiSetup& setup) {
  return setup.reference.flapping_speed > setup.reference.free_stream_speed;
}

double reynolds_speed(const FsiSetup& setup) {
  return flapping_sets_reynolds(setup) ? setup.reference.flapping_speed : setup.reference.free_stream_speed;
}

}  // namespace

double reynolds_number(const io::Case& c, const FsiSetup& setup) {
  if (!setup.model.air || !(c.numerics.kinematic_viscosity > 0.0)) return 0.0;
  return reynolds_speed(setup) * setup.reference.mean_chord / c.numerics.kinematic_viscosity;
}

std::string describe_reynolds(const io::Case& c, const FsiSetup& setup) {
  const double re = reynolds_number(c, setup);
  char text[300];
  std::snprintf(text, sizeof text, re >= 100.0 ? "%.0f" : "%.3g", re);
  std::string out = text;
  std::snprintf(text, sizeof text, " (U c/nu: %.3g m/s at %s, mean chord %.3g mm, nu %.3g m^2/s)",
                reynolds_speed(setup),
                flapping_sets_reynolds(setup)
                    ? (setup.reference.free_stream_speed > 0.0 ? "r2 of the span, faster than the free stream"
                                                               : "r2 of the span")
                    : "the free stream",
                setup.reference.mean_chord * 1e3, c.numerics.kinematic_viscosity);
  return out + text;
}

std::string low_reynolds_warning(const io::Case& c, const FsiSetup& setup) {
  const double re = reynolds_number(c, setup);
  if (!setup.model.air || !(re > 0.0) || !(re < kLowestLatticeReynolds)) return "";
  char text[700];
  std::snprintf(
      text, sizeof text,
      ", below %g: there a wing's leading- and trailing-edge vortices stay attached through each half "
      "stroke, its lift falls and its drag rises (Miller & Peskin 2004, J. Exp. Biol. 207, 3073-3088), "
      "while the vortex lattice sheds its wake at the trailing edge as at large Reynolds numbers and "
      "has no viscous forces: expect its lift too high and its drag far too low; nu is "
      "numerics.kinematic_viscosity, air's by default (docs/uvlm.md, \"Reynolds number\")",
      kLowestLatticeReynolds);
  return "the Reynolds number is " + describe_reynolds(c, setup) + text;
}

}  // namespace flapsim::app
