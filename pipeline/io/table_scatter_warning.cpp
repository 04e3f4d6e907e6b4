#include "pipeline/io/table_scatter_warning.hpp"

#include "mbd/table_scatter.hpp"

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace flapsim::io {

void warn_scattered_kinematics_tables(const wings::TomlTable& root, Case& c) {
  const auto k = root.find_table("kinematics");
  if (!k) return;
  const std::pair<const char*, const char*> signals[] = {{"sweep", "deg"},    {"deviation", "deg"},
                                                         {"rotation", "deg"}, {"surge", "m"},
                                                         {"lateral", "m"},    {"heave", "m"}};
  for (const auto& [name, values_key] : signals) {
    if (!k->is_table(name)) continue;
    const wings::TomlTable s = k->get_table(name);
    if (!s.has("phase") || s.has("harmonics")) continue;
    // The table as read_periodic_signal took it (already checked): a closing phase 1 dropped.
    std::vector<double> phase = s.get_doubles("phase"), values = s.get_doubles(values_key);
    if (!phase.empty() && phase.back() == 1.0) {
      phase.pop_back();
      values.pop_back();
    }
    const auto scatter = mbd::measure_table_scatter(phase, values);
    if (!scatter || scatter->scatter_share < kScatterShareWarned) continue;
    char text[1200];
    std::snprintf(
        text, sizeof text,
        "%.0f %% of the rms acceleration of the spline through the table's %zu points is their "
        "scatter (rms %.3g %s) about the table's least-squares series of %d harmonics: the spline "
        "accelerates %.3g times as much as that series (rms), and the inertial loads, the drive's "
        "power and the wing's response follow the scatter (eq. 8's hover, cases/hover.toml, as "
        "1000-point tables rounded to 0.01 deg: mean lift +53 %%, aerodynamic power 3.9 times; "
        "rounded to 0.1 deg the run fails). Measured or rounded values: fly the table's Fourier "
        "series, harmonics = N in the table (harmonics = %d leaves the points about as far from it; "
        "check prints how far), or write the values with more digits (docs/case_file.md, "
        "\"Measured kinematics\")",
        100.0 * scatter->scatter_share, phase.size(), scatter->scatter_rms, values_key, scatter->harmonics,
        scatter->spline_acceleration / scatter->series_acceleration,
        mbd::fewest_harmonics_within_scatter(phase, values, *scatter));
    c.warnings.push_back({c.file, s.line_of(values_key), s.key_path(values_key), text});
  }
}

}  // namespace flapsim::io
