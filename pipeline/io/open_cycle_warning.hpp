#pragma once
/// \file open_cycle_warning.hpp
/// \brief The warning for a kinematics table that does not close: its last point and its
/// first (one wingbeat on) differ far more steeply than any two neighbouring points, as a
/// recorded wingbeat that drifts, or one cut at other phases than its period, does. The
/// periodic spline closes it within that last interval, with accelerations the record does
/// not have (docs/case_file.md, "Measured kinematics").

#include <optional>
#include <string>
#include <vector>

#include "wings/loader/input_warning.hpp"

namespace flapsim::io {

/// Warned when the step from the last point to the first, per unit of phase, is this many
/// times the steepest between neighbouring points. A smooth wingbeat's secants are all at most
/// its steepest slope, and the steepest interior one comes near it once the points are not
/// few: a sine of 4 or 5 points placed so that the closing interval straddles its steepest
/// part gives 1.0 and 1.24; noise raises the steepest interior step, not the closing one, so
/// noisy records are warned less, never more.
inline constexpr double kOpenCycleSlopeRatio = 2.0;

/// The warning for a table (phases strictly increasing in [0, 1), values as written in
/// `unit`, at least 4 points) whose closing step is at least kOpenCycleSlopeRatio times as
/// steep as its steepest interior one; nullopt for any other table. `file`, `line`, `key`
/// locate it.
std::optional<InputWarning> open_cycle_warning(const std::vector<double>& phase,
                                               const std::vector<double>& values, const std::string& unit,
                                               const std::string& file, int line, const std::string& key);

}  // namespace flapsim::io
