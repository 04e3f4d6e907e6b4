#include "pipeline/app/small_wing_precision_warning.hpp"

#include <cstdio>

namespace flapsim::app {

std::string small_wing_precision_warning(const FsiSetup& setup) {
  const fsi::FsiModel& m = setup.model;
  if (!m.air || !m.lattice.single_precision_wake ||
      !(setup.reference.mean_chord < kSinglePrecisionSmallestChord))
    return "";
  char text[600];
  std::snprintf(
      text, sizeof text,
      "the wing's mean chord, %.3g um, lies below the %.3g um down to which the wake's single-precision "
      "sums keep their digits: with a 10 um chord a plate's lift differs from the same flow at a 10 mm "
      "chord by 4e-4 at its second step, with 20 um by 7e-6, with 50 um and more by 1e-7. Set "
      "numerics.wake_precision = \"double\" (docs/uvlm.md, \"Precision of the wake's sums\")",
      setup.reference.mean_chord * 1e6, kSinglePrecisionSmallestChord * 1e6);
  return text;
}

}  // namespace flapsim::app
