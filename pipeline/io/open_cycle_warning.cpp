#include "pipeline/io/open_cycle_warning.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace flapsim::io {

std::optional<InputWarning> open_cycle_warning(const std::vector<double>& phase,
                                               const std::vector<double>& values, const std::string& unit,
                                               const std::string& file, int line, const std::string& key) {
  const std::size_t n = phase.size();
  if (n < 4 || values.size() != n) return std::nullopt;
  double steepest = 0.0;  // [unit per cycle]
  for (std::size_t i = 1; i < n; ++i)
    steepest = std::max(steepest, std::abs(values[i] - values[i - 1]) / (phase[i] - phase[i - 1]));
  const double closing_interval = phase.front() + 1.0 - phase.back();  // [cycles]
  const double closing_step = values.front() - values.back();
  const double closing = std::abs(closing_step) / closing_interval;
  if (!(closing > kOpenCycleSlopeRatio * steepest)) return std::nullopt;
  char text[1000];
  std::snprintf(
      text, sizeof text,
      "the table does not close: from its last point (phase %.4g, %.6g %s) to its first one wingbeat on "
      "(phase %.4g, %.6g %s) it changes by %.3g %s in %.3g of the cycle, %.3g times as steeply as the "
      "steepest step between its neighbouring points; the periodic spline closes the wingbeat in that "
      "interval, with "
      "accelerations the record does not have (a recorded wingbeat that drifts, or one not cut at its "
      "period). Give one whole wingbeat (a last row at phase 1 repeating the first row's value), or "
      "remove the record's drift (docs/case_file.md, \"Measured kinematics\")",
      phase.back(), values.back(), unit.c_str(), phase.front() + 1.0, values.front(), unit.c_str(),
      closing_step, unit.c_str(), closing_interval, steepest > 0.0 ? closing / steepest : HUGE_VAL);
  return InputWarning{file, line, key, text};
}

}  // namespace flapsim::io
