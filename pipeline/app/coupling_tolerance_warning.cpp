#include "pipeline/app/coupling_tolerance_warning.hpp"

#include <cstdio>

namespace flapsim::app {

std::string coupling_tolerance_warning(const FsiSetup& setup) {
  const fsi::FsiModel& m = setup.model;
  if (!m.air || !m.structure || m.structure->num_dofs() == 0) return "";
  if (!m.lattice.single_precision_wake || !(m.coupling.tolerance < kSinglePrecisionCouplingFloor)) return "";
  char text[600];
  std::snprintf(text, sizeof text,
                "numerics.coupling_tolerance = %g rad lies below the %g rad down to which the wake's "
                "single-precision sums let the coupling's sub-iterations converge: their change may stall "
                "just above the tolerance and stop the run. Set numerics.wake_precision = \"double\" or a "
                "tolerance of %g or more (docs/uvlm.md, \"Precision of the wake's sums\")",
                m.coupling.tolerance, kSinglePrecisionCouplingFloor, kSinglePrecisionCouplingFloor);
  return text;
}

}  // namespace flapsim::app
