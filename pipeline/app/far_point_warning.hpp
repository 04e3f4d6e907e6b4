#pragma once
/// \file far_point_warning.hpp
/// \brief A warning for a load's or marker's point far off the wing: written in another unit.
///
/// Points of [[loads]] and [[markers]] are in the case file's `length_unit`, metres by
/// default (docs/case_file.md), while wing files are often in mm: a marker at the tip of a
/// 50 mm wing written [0, 50, 0] without `length_unit = "mm"` lies 50 m from its body and
/// its path in history.csv is nonsense, a load there a lever a thousand times too long. A
/// point on (or near) the wing lies within the wing's length of any body's origin; one
/// farther than twice that is warned, with the unit that would put it on the wing.

#include <string>
#include <vector>

#include "pipeline/app/fsi_setup.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// Points farther than this many wing lengths from their body's origin are warned.
inline constexpr double kFarPointWingLengths = 2.0;

/// \brief One warning per load or marker whose point lies more than kFarPointWingLengths
/// times the wing's length (its span R; a chain file's bodies end to end) from its body's
/// origin, naming the case file, line and key and the unit that would bring it onto the wing.
std::vector<std::string> far_point_warnings(const io::Case& c, const FsiSetup& setup);

}  // namespace flapsim::app
