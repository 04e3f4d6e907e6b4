#include "pipeline/io/table_scatter_warning.hpp"

#include <cstdio>

#include "mbd/table_scatter.hpp"

namespace flapsim::io {

std::optional<InputWarning> scattered_table_warning(const std::vector<double>& phase,
                                                    const std::vector<double>& values,
                                                    const std::string& unit, const std::string& file,
                                                    int line, const std::string& key) {
  const auto scatter = mbd::measure_table_scatter(phase, values);
  if (!scatter || scatter->scatter_share < kScatterShareWarned) return std::nullopt;
  char text[1200];
  std::snprintf(text, sizeof text,
                "%.0f %% of the rms acceleration of the spline through the table's %zu points is their "
                "scatter (rms %.3g %s) about the table's least-squares series of %d harmonics: the spline "
                "accelerates %.3g times as much as that series (rms), and the inertial loads, the drive's "
                "power and the wing's response follow the scatter (eq. 8's hover, cases/hover.toml, as "
                "1000-point tables rounded to 0.01 deg: mean lift +53 %%, aerodynamic power 3.9 times; "
                "rounded to 0.1 deg the run fails). Measured or rounded values: fly the table's Fourier "
                "series, harmonics = N in the table (harmonics = %d leaves the points about as far from it; "
                "check prints how far), or write the values with more digits (docs/case_file.md, "
                "\"Measured kinematics\")",
                100.0 * scatter->scatter_share, phase.size(), scatter->scatter_rms, unit.c_str(),
                scatter->harmonics, scatter->spline_acceleration / scatter->series_acceleration,
                mbd::fewest_harmonics_within_scatter(phase, values, *scatter));
  return InputWarning{file, line, key, text};
}

}  // namespace flapsim::io
