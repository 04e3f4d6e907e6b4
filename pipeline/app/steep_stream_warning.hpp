#pragma once
/// \file steep_stream_warning.hpp
/// \brief A warning for a free stream close to the vertical (a wing in climb or descent).
///
/// Lift is taken normal to the free stream in the vertical plane through it, drag along it
/// (docs/fsi.md, "summary.json"). A vertical stream leaves that plane undefined and is
/// refused; a stream a little off the vertical puts lift almost horizontal and drag almost
/// vertical, both turning with the stream's small horizontal part. A hover in a climb of
/// 1 m/s (the air falling past the wing) with 0.01 m/s of horizontal stream (0.6° off the vertical) reported
/// its weight support, Fz = 5.31 mN, as a drag of −5.3 mN and a lift of 0.17 mN, without a word.

#include <string>

#include "mbd/angle_units.hpp"
#include "pipeline/io/case_model.hpp"

namespace flapsim::app {

/// A stream within this angle of the vertical is warned [rad] (10°: a convention; lift's
/// direction then lies within 10° of the horizontal).
inline constexpr double kSteepStreamAngle = 10.0 * kDegToRad;

/// \brief "" or the warning for the case's free stream within kSteepStreamAngle of the
/// vertical (and not vertical: that one is refused), naming its angle from the vertical and
/// where the vertical force is read.
std::string steep_stream_warning(const io::Case& c);

}  // namespace flapsim::app
