#pragma once
/// \file table_scatter_warning.hpp
/// \brief The warning for a kinematics table whose spline accelerates with its points'
/// scatter (mbd/table_scatter.hpp): measured or rounded values flown as they are.

#include "pipeline/io/case_model.hpp"
#include "wings/loader/toml_reader.hpp"

namespace flapsim::io {

/// At this share of a table's spline's rms acceleration from its scatter the spline's rms
/// acceleration is at least 1/sqrt(1 − 0.5²) = 1.15 times the motion's (the scatter's
/// curvature and the motion's nearly orthogonal): warned.
inline constexpr double kScatterShareWarned = 0.5;

/// For each of kinematics.sweep, deviation, rotation, surge, lateral, heave that is a table
/// without `harmonics`: a warning at its values' key when its scatter makes at least
/// kScatterShareWarned of its spline's rms acceleration, with how much and what to do.
void warn_scattered_kinematics_tables(const wings::TomlTable& root, Case& c);

}  // namespace flapsim::io
