#include "pipeline/app/lattice_coverage_warning.hpp"

#include <cstdio>

namespace flapsim::app {

std::string lattice_coverage_warning(const FsiSetup& setup) {
  if (!setup.model.air || !setup.grid) return "";
  const uvlm::PlanformGrid& g = *setup.grid;
  if (!(g.outline_area > 0.0) || g.lattice_area >= kLeastLatticeCoverage * g.outline_area) return "";
  char text[600];
  std::snprintf(
      text, sizeof text,
      "the vortex lattice covers %.1f %% of the wing's outline (%d chordwise x %d spanwise panels): "
      "its forces are the panels', its coefficients on the outline's area, so they come out low (the "
      "rigid hawkmoth hover: CL 0.56 with 13 %% covered, 2.41 with 63 %%, 2.77 with 97 %%); give "
      "numerics.spanwise_panels more panels (docs/uvlm.md, \"Planform grid\")",
      100.0 * g.lattice_area / g.outline_area, g.chordwise, g.spanwise);
  return text;
}

}  // namespace flapsim::app
