#include "fem/root_clamp_warning.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <vector>

#include "fem/constraints.hpp"
#include "wings/loader/planform_geometry.hpp"

namespace flapsim::fem {

std::string root_clamp_warning(const Mesh& mesh, const wings::Wing& wing) {
  const std::vector<int> clamped = nodes_at_or_below_y(mesh, wing.clamp_y);
  if (clamped.empty()) return "";  // refused elsewhere: the root would be free
  std::vector<char> is_clamped(mesh.nodes.size(), 0);
  double x_min = std::numeric_limits<double>::infinity(), x_max = -x_min;
  for (int n : clamped) {
    is_clamped[static_cast<std::size_t>(n)] = 1;
    x_min = std::min(x_min, mesh.nodes[static_cast<std::size_t>(n)].x());
    x_max = std::max(x_max, mesh.nodes[static_cast<std::size_t>(n)].x());
  }
  for (const BeamElement& b : mesh.beams)
    for (int n : b.nodes)
      if (is_clamped[static_cast<std::size_t>(n)]) return "";  // a vein is held
  const double mean_chord = wings::planform_properties(wing.outline).mean_chord;
  const double extent = x_max - x_min;
  const bool narrow = extent < kNarrowClampChordShare * mean_chord;
  if (wing.veins.empty() && !narrow) return "";
  char text[1000];
  std::snprintf(
      text, sizeof text,
      "%s: the root clamp (the nodes at or below clamp_y = %.4g mm) holds %zu node%s over %.3g mm of "
      "chord (the mean chord %.3g mm) and no vein: the wing hangs on its membrane there, and its modes and "
      "deflections are the film's (a spar 0.4 mm above the clamp line: first mode 5.7 Hz against 36.6 Hz "
      "clamped). Start the root vein at or below clamp_y, or raise clamp_y to where the wing is held "
      "(docs/wing_file.md, \"Checks\")",
      wing.source_file.c_str(), wing.clamp_y * 1e3, clamped.size(), clamped.size() == 1 ? "" : "s",
      extent * 1e3, mean_chord * 1e3);
  return text;
}

}  // namespace flapsim::fem
