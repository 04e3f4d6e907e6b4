#include "pipeline/io/recorded_frequency_warning.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace flapsim::io {

std::optional<InputWarning> recorded_frequency_warning(const std::vector<double>& phase,
                                                       const std::vector<double>& values, double frequency_hz,
                                                       const std::string& column, const std::string& file,
                                                       int line, const std::string& key) {
  if (phase.size() < 4 || values.size() != phase.size() || !(frequency_hz > 0.0)) return std::nullopt;
  const double last = phase.back() - phase.front();  // [cycles]
  if (!(last > 0.5 && last < 1.0)) return std::nullopt;
  const double first_value = values.front(), last_value = values.back();
  if (std::abs(last_value - first_value) > 1e-9 * std::max(1.0, std::abs(first_value))) return std::nullopt;
  const double recorded_hz = frequency_hz / last;
  char text[600];
  std::snprintf(
      text, sizeof text,
      "the last row repeats the first row's '%s' (%.6g) as a wingbeat's closing row does, but lies at "
      "phase %.4f of the case's %.6g Hz wingbeat: the rows look like one wingbeat of %.6g ms (%.4g Hz). "
      "Flown at %.6g Hz the row is an ordinary point, and the wing holds that value over the last %.1f %% "
      "of the cycle; give frequency_hz = %.4g to fly the wingbeat as recorded, or drop the row "
      "(docs/case_file.md, \"Measured kinematics\")",
      column.c_str(), first_value, last, frequency_hz, 1e3 / recorded_hz, recorded_hz, frequency_hz,
      100.0 * (1.0 - last), recorded_hz);
  return InputWarning{file, line, key, text};
}

}  // namespace flapsim::io
