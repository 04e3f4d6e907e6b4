#include "pipeline/app/lattice_surface.hpp"

#include <algorithm>

#include "wings/loader/surface_shape.hpp"

namespace flapsim::app {

void shape_lattice_surface(const wings::Wing& wing, uvlm::PlanformGrid& grid) {
  if (wing.surface.flat()) return;
  double y_root = wing.outline.empty() ? 0.0 : wing.outline.front().y(), y_tip = y_root;
  for (const auto& p : wing.outline) {
    y_root = std::min(y_root, p.y());
    y_tip = std::max(y_tip, p.y());
  }
  const int n1 = grid.chordwise + 1;
  for (int j = 0; j <= grid.spanwise; ++j) {
    // Node (i, j) is column i + (nc + 1) j, i = 0 at the leading edge (planform_grid.hpp).
    const double x_le = grid.nodes(0, n1 * j), x_te = grid.nodes(0, grid.chordwise + n1 * j);
    for (int i = 0; i < n1; ++i) {
      auto node = grid.nodes.col(i + n1 * j);
      node = wings::shaped_point(wing.surface, node.x(), node.y(), x_le, x_te, y_root, y_tip);
    }
  }
}

}  // namespace flapsim::app
