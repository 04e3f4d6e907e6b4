#include "pipeline/io/kinematics_samples.hpp"

#include "mbd/angle_units.hpp"
#include "pipeline/io/csv_writer.hpp"

namespace flapsim::io {

std::vector<std::string> kinematics_samples_header() {
  return {"phase",
          "t_s",
          "phi_deg",
          "theta_deg",
          "alpha_deg",
          "phi_rate_deg_per_s",
          "theta_rate_deg_per_s",
          "alpha_rate_deg_per_s",
          "phi_acceleration_deg_per_s2",
          "theta_acceleration_deg_per_s2",
          "alpha_acceleration_deg_per_s2"};
}

void write_kinematics_samples(const std::filesystem::path& path, const mbd::WingKinematics& kinematics,
                              int steps_per_cycle) {
  std::vector<std::vector<double>> rows;
  rows.reserve(static_cast<std::size_t>(steps_per_cycle) + 1);
  for (int k = 0; k <= steps_per_cycle; ++k) {
    const double phase = static_cast<double>(k) / steps_per_cycle, t = phase / kinematics.frequency;
    const mbd::WingKinematics::Angles a = kinematics.angles(t);
    rows.push_back({phase, t, a.sweep.value * kRadToDeg, a.deviation.value * kRadToDeg,
                    a.rotation.value * kRadToDeg, a.sweep.rate * kRadToDeg, a.deviation.rate * kRadToDeg,
                    a.rotation.rate * kRadToDeg, a.sweep.acceleration * kRadToDeg,
                    a.deviation.acceleration * kRadToDeg, a.rotation.acceleration * kRadToDeg});
  }
  write_csv(path, kinematics_samples_header(), rows);
}

}  // namespace flapsim::io
