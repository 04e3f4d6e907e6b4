#pragma once
/// \file table_scatter_warning.hpp
/// \brief The warning for a kinematics table whose spline accelerates with its points'
/// scatter (mbd/table_scatter.hpp): measured or rounded values flown as they are.

#include <optional>
#include <string>
#include <vector>

#include "wings/loader/input_warning.hpp"

namespace flapsim::io {

/// At this share of a table's spline's rms acceleration from its scatter the spline's rms
/// acceleration is at least 1/sqrt(1 − 0.5²) = 1.15 times the motion's (the scatter's
/// curvature and the motion's nearly orthogonal): warned.
inline constexpr double kScatterShareWarned = 0.5;

/// The warning for a table (phases in [0, 1), values as written in `unit`) whose scatter makes
/// at least kScatterShareWarned of its spline's rms acceleration, with how much and the
/// harmonics to fit it with; nullopt for any other table. `file`, `line`, `key` locate it.
std::optional<InputWarning> scattered_table_warning(const std::vector<double>& phase,
                                                    const std::vector<double>& values,
                                                    const std::string& unit, const std::string& file,
                                                    int line, const std::string& key);

}  // namespace flapsim::io
