#pragma once
/// \file coupling_tolerance_warning.hpp
/// \brief A warning for a flexible case in air whose coupling tolerance lies below what the
/// wake's single-precision sums let the sub-iterations reach (docs/uvlm.md, "Precision of
/// the wake's sums"): such a run stalls with its change just above the tolerance and stops.

#include <string>

#include "pipeline/app/fsi_setup.hpp"

namespace flapsim::app {

/// Coupling tolerance [rad] below which a case with single-precision wake sums is warned:
/// measured floors of the sub-iterations' change with those sums, 6e-10–2e-9 rad (the
/// 8-body MAV film wing at 12 Hz) up to 9e-9 rad (a 1.2 m wing); in double precision the
/// same runs converge. A convention from these measurements.
inline constexpr double kSinglePrecisionCouplingFloor = 1e-8;

/// \brief "" or the warning for a coupled (flexible or FEM) case in air with
/// `wake_precision = "single"` and `coupling_tolerance` below kSinglePrecisionCouplingFloor.
std::string coupling_tolerance_warning(const FsiSetup& setup);

}  // namespace flapsim::app
