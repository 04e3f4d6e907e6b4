#include "pipeline/app/far_point_warning.hpp"

#include <cstdio>
#include <utility>

namespace flapsim::app {

namespace {

// The wing's length [m]: its span R, or without a wing file its chain's bodies end to end.
double wing_length(const FsiSetup& setup) {
  if (setup.wing) return setup.wing->span;
  double length = 0.0;
  for (const auto& body : setup.chain().bodies) length += body.length;
  return length;
}

// ": was it written in mm (length_unit = "mm")?" for the first unit that puts a point
// written as `written` within `reach` [m], or "" if none does.
std::string unit_guess(const io::Case& c, double written, double reach) {
  for (const auto& [unit, scale] :
       {std::pair{"m", 1.0}, std::pair{"cm", 1e-2}, std::pair{"mm", 1e-3}, std::pair{"um", 1e-6}})
    if (unit != c.length_unit && written * scale <= reach)
      return ": was it written in " + std::string(unit) + " (length_unit = \"" + unit + "\")?";
  return "";
}

std::string far_point(const io::Case& c, const char* table, std::size_t i, const std::string& what,
                      const Eigen::Vector3d& point, double length) {
  const double distance = point.norm();  // [m]
  if (!(distance > kFarPointWingLengths * length)) return "";
  const std::string key = std::string(table) + "." + std::to_string(i + 1) + ".point";
  char text[300];
  std::snprintf(text, sizeof text,
                "%s lies %.4g %s from its body's origin, %.3g times the wing's length (%.4g %s)",
                what.c_str(), distance / c.length_scale, c.length_unit.c_str(), distance / length,
                length / c.length_scale, c.length_unit.c_str());
  // The headline (before the first ": ") names what, where and the key: summary.json's notes.
  const std::string where = " (" + c.file + ":" + std::to_string(c.line_of(key)) + ", key '" + table + "[" +
                            std::to_string(i) + "].point')";
  return std::string(text) + where + ": points are in the case file's length_unit = \"" + c.length_unit +
         "\" (docs/case_file.md)" + unit_guess(c, distance / c.length_scale, length);
}

}  // namespace

std::vector<std::string> far_point_warnings(const io::Case& c, const FsiSetup& setup) {
  std::vector<std::string> out;
  const double length = wing_length(setup);
  if (!(length > 0.0)) return out;
  for (std::size_t i = 0; i < c.loads.size(); ++i)
    if (std::string w = far_point(c, "loads", i, "the load's point", c.loads[i].point, length); !w.empty())
      out.push_back(std::move(w));
  for (std::size_t i = 0; i < c.markers.size(); ++i)
    if (std::string w =
            far_point(c, "markers", i, "marker '" + c.markers[i].name + "'", c.markers[i].point, length);
        !w.empty())
      out.push_back(std::move(w));
  return out;
}

}  // namespace flapsim::app
