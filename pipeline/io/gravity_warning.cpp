#include "pipeline/io/gravity_warning.hpp"

#include <cmath>
#include <cstdio>

namespace flapsim::io {

std::optional<InputWarning> gravity_warning(const Eigen::Vector3d& gravity, const std::string& file,
                                            int line) {
  const double g = gravity.norm();
  if (g == 0.0) return std::nullopt;
  char text[400];
  if (g > kGreatestPlausibleGravity)
    std::snprintf(text, sizeof text,
                  "gravity of %.4g m/s², %.3g times the Earth's 9.81: gravity is in m/s² whatever the "
                  "length_unit; was it written in mm/s² (%.4g m/s²)?",
                  g, g / 9.81, g * 1e-3);
  else if (g < kLeastPlausibleGravity)
    std::snprintf(
        text, sizeof text,
        "gravity of %.4g m/s², below any planet's or large moon's: gravity is in m/s²; was it written "
        "in km/s² or in g (%.4g g is %.4g m/s²)?",
        g, g, g * 9.81);
  else if (gravity.z() > 0.0 && std::hypot(gravity.x(), gravity.y()) < gravity.z())
    std::snprintf(
        text, sizeof text,
        "gravity points up the ground frame's z axis (%.4g m/s² along +z): the ground frame has z up, "
        "so the Earth's gravity is [0, 0, -9.81]",
        gravity.z());
  else
    return std::nullopt;
  return InputWarning{file, line, "structure.gravity", text};
}

}  // namespace flapsim::io
