#include "wings/mesh_budget.hpp"

#include <algorithm>
#include <cmath>

#include "wings/planform_geometry.hpp"

namespace flapsim::wings {

double estimated_mesh_elements(const Wing& wing) {
  const double h = wing.mesh.element_size;
  const double hv = std::min(wing.mesh.vein_element_size > 0.0 ? wing.mesh.vein_element_size : h, h);
  const double triangle = std::sqrt(3.0) / 4.0;  // area of an equilateral triangle of side 1
  const double area = polygon_area(wing.outline);
  double vein_length = 0.0;
  for (const auto& v : wing.veins)
    for (std::size_t i = 0; i + 1 < v.points.size(); ++i) vein_length += (v.points[i + 1] - v.points[i]).norm();
  const double band = std::min(area, vein_length * 2.0 * (0.5 * hv + 3.0 * h));
  return area / (triangle * h * h) + band / (triangle * hv * hv) + vein_length / hv;
}

}  // namespace flapsim::wings
