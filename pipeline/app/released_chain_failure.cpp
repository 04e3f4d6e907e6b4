#include "pipeline/app/released_chain_failure.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace flapsim::app {

std::string released_chain_at_failure(const io::Case& c, long failed_step) {
  const auto& s = c.structure;
  auto bent = [](const std::vector<double>& v) {
    return std::any_of(v.begin(), v.end(), [](double x) { return x != 0.0; });
  };
  const bool angles = bent(s.initial_angles), rates = bent(s.initial_rates);
  if (s.kind != io::Case::Structure::Kind::Flexible || !c.air.enabled || (!angles && !rates)) return "";
  if (!(c.numerics.rho_infinity > kReleasedChainRhoInfinity) || failed_step < 0 ||
      failed_step >= c.numerics.steps_per_cycle)
    return "";
  char text[700];
  std::snprintf(text, sizeof text,
                "The chain was released from bent or moving joints (%s, line %d): such a start rings in the chain's "
                "stiffest modes, far faster than a step, and in air the coupling can diverge on them while "
                "numerics.rho_infinity = %g leaves them undamped; with rho_infinity = %g such starts ran, and so "
                "did the same chain from rest (docs/case_file.md, \"[structure]\")",
                angles ? "initial_angles_deg" : "initial_rates_deg_per_s",
                angles ? s.initial_angles_line : s.initial_rates_line, c.numerics.rho_infinity,
                kReleasedChainRhoInfinity);
  return text;
}

}  // namespace flapsim::app
