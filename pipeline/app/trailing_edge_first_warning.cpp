#include "pipeline/app/trailing_edge_first_warning.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "pipeline/io/case_summary.hpp"

namespace flapsim::app {

double trailing_edge_first_share(const io::Case& c, const FsiSetup& setup) {
  if (!setup.model.air || !(c.kinematics.frequency > 0.0)) return 0.0;
  const double radius = setup.reference.r2 * setup.reference.span;  // [m]
  const double period = 1.0 / c.kinematics.frequency;               // [s]
  const double end = static_cast<double>(c.numerics.total_steps()) / c.numerics.steps_per_cycle * period;
  constexpr int kSamples = 720;
  double all = 0.0, trailing_first = 0.0;  // Σ |w|² [m²/s²]
  for (int i = 0; i < kSamples; ++i) {
    const double t = end - period + (i + 0.5) * period / kSamples;
    const auto a = io::angle_of_attack_in_stream(c.kinematics, c.air.freestream, radius, t);
    if (!a) continue;
    const double q = a->speed * a->speed;
    all += q;
    if (std::abs(a->angle) > 0.5 * std::numbers::pi + 1e-6) trailing_first += q;
  }
  return all > 0.0 ? trailing_first / all : 0.0;
}

std::string trailing_edge_first_warning(const io::Case& c, const FsiSetup& setup) {
  const double share = trailing_edge_first_share(c, setup);
  if (!(share >= kTrailingEdgeFirstShare - kTrailingEdgeFirstRoundOff)) return "";
  char text[900];
  std::snprintf(
      text, sizeof text,
      "the wing moves trailing edge first for %.0f %% of its last wingbeat (its angle of attack in "
      "the stream at r2 of the span beyond 90 degrees, the share weighted by the air's speed squared "
      "there): the lattice sheds its wake at the wing file's trailing edge, which then leads, and its "
      "loads are not a wing's (a plate revolving at 160 degrees with leading_edge = \"none\": lift of "
      "the wrong side, CD -0.60 and a negative aerodynamic power, the air driving the wing); check "
      "kinematics.rotation: the leading edge leads while the geometric angle of attack lies between 0 "
      "and 90 degrees (docs/kinematics.md, \"Which edge leads\")",
      100.0 * share);
  return text;
}

}  // namespace flapsim::app
