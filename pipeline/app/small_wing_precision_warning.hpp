#pragma once
/// \file small_wing_precision_warning.hpp
/// \brief A warning for a wing whose mean chord lies below what the wake's single-precision
/// sums resolve: their kernel's denominator grows as the sixth power of the distances
/// (uvlm/biot_savart_kernel.hpp), and below some micrometres it meets the float range's
/// floor, so the sums lose digits that a larger wing keeps (docs/uvlm.md, "Precision of the
/// wake's sums").

#include <string>

#include "pipeline/app/fsi_setup.hpp"

namespace flapsim::app {

/// Mean chord [m] below which single-precision wake sums are warned. Measured (1 Dec 2026)
/// on wings/flat_plate.toml scaled in length with the frequency scaled inversely (the same
/// flow; rigid, 40 steps a cycle): the CL of every step against the 10 mm plate's differs by
/// 4e-4 at the second step with a 10 µm chord, 7e-6 with 20 µm, 1e-7 with 50 µm and more (the
/// rounding of any rescaling; 1e-6 at 160 steps a cycle). Twice the 50 µm.
inline constexpr double kSinglePrecisionSmallestChord = 1e-4;

/// \brief "" or the warning for a case in air with `wake_precision = "single"` whose
/// wing's mean chord is below kSinglePrecisionSmallestChord.
std::string small_wing_precision_warning(const FsiSetup& setup);

}  // namespace flapsim::app
