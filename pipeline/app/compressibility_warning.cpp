#include "pipeline/app/compressibility_warning.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace flapsim::app {

std::string compressibility_warning(const io::Case& c, const FsiSetup& setup) {
  if (!setup.model.air || !setup.wing) return "";
  const int samples = 400;  // per cycle
  const double period = 1.0 / c.kinematics.frequency;
  double peak = 0.0;  // [m/s]
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector3d v = span_point_velocity(c.kinematics, setup.wing->span, period * i / samples);
    peak = std::max(peak, (v - c.air.freestream).norm());
  }
  const double mach = peak / kSpeedOfSound;
  if (!(mach > kIncompressibleMach)) return "";
  char text[700];
  std::snprintf(text, sizeof text,
                "the wing tip meets the air at up to %.4g m/s, Mach %.2g (speed of sound %g m/s): the vortex "
                "lattice is incompressible, and beyond Mach %g compressibility changes the pressures by more "
                "than 5 %% (Prandtl-Glauert). Is frequency_hz in Hz (not rad/s or rpm), are the angles in "
                "degrees, the free stream in m/s and the wing's length_unit right? (docs/case_file.md, \"Warnings\")",
                peak, mach, kSpeedOfSound, kIncompressibleMach);
  return text;
}

}  // namespace flapsim::app
