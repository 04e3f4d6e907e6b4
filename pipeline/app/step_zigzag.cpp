#include "pipeline/app/step_zigzag.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace flapsim::app {

StepZigzag largest_step_zigzag(const std::vector<double>& angle_rad) {
  StepZigzag largest;
  const auto step = [&](std::size_t i) {  // angle_rad[i + 1] − angle_rad[i], within ±π
    return std::remainder(angle_rad[i + 1] - angle_rad[i], 2.0 * std::numbers::pi);
  };
  for (std::size_t i = 1; i + 2 < angle_rad.size(); ++i) {
    const double before = step(i - 1), here = step(i), after = step(i + 1);
    if (!(before * here < 0.0 && here * after < 0.0)) continue;
    const double amplitude = 0.5 * std::min({std::abs(before), std::abs(here), std::abs(after)});
    if (amplitude > largest.amplitude) largest = {amplitude, static_cast<long>(i) + 1};
  }
  return largest;
}

}  // namespace flapsim::app
