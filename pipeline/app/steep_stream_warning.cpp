#include "pipeline/app/steep_stream_warning.hpp"

#include <cmath>
#include <cstdio>

#include "mbd/angle_units.hpp"

namespace flapsim::app {

std::string steep_stream_warning(const io::Case& c) {
  if (!c.air.enabled) return "";
  const Eigen::Vector3d& u = c.air.freestream;  // [m/s]
  const double speed = u.norm();
  const double horizontal = std::hypot(u.x(), u.y());
  if (!(speed > 0.0) || !(horizontal > 0.0)) return "";
  const double from_vertical = std::atan2(horizontal, std::abs(u.z()));  // [rad]
  if (!(from_vertical < kSteepStreamAngle)) return "";
  char text[700];
  std::snprintf(
      text, sizeof text,
      "the free stream is %.2g deg from the vertical (a %s): lift is taken normal to it in the vertical "
      "plane through it, here within %.2g deg of the horizontal, and drag along it, so the force that "
      "holds the wing up is reported as %s drag, and lift and drag turn with the stream's %.3g m/s "
      "horizontal part. The vertical force is summary.json's mean_Fz_N (history.csv Fz) "
      "(docs/case_file.md, [air])",
      from_vertical * kRadToDeg,
      u.z() < 0.0 ? "climb: the air falls past the wing" : "descent: the air rises past the wing",
      from_vertical * kRadToDeg, u.z() < 0.0 ? "negative" : "positive", horizontal);
  return text;
}

}  // namespace flapsim::app
