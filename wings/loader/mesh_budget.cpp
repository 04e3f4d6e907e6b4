#include "wings/loader/mesh_budget.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "wings/loader/planform_geometry.hpp"

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

namespace {

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::optional<MeshSizeProblem> mesh_size_problem(const Wing& wing, const MeshSizeKeys& keys) {
  const double h = wing.mesh.element_size, hv = wing.mesh.vein_element_size;
  const auto length = [&](double metres) { return number(metres / keys.length_scale) + " " + keys.unit; };
  if (hv > h * (1 + 1e-12)) {
    const std::string& membrane =
        keys.element_given || keys.element_not_given.empty() ? keys.element : keys.element_not_given;
    return MeshSizeProblem{keys.vein_given ? keys.vein : keys.element,
                           "must not exceed " + membrane + " (" + length(hv) + " against " + length(h) + ")"};
  }
  if (h > 0.5 * wing.span)
    return MeshSizeProblem{keys.element, "must not exceed half the span (" + keys.element + " " + length(h) +
                                             ", span " + length(wing.span) + ")"};
  if (const double n = estimated_mesh_elements(wing); n > kMaxMeshElements) {
    const bool vein = keys.vein_given && (hv < h || !keys.element_given);
    const std::string& key = vein ? keys.vein : keys.element;
    return MeshSizeProblem{key, "the mesh would have about " + number(n) + " elements, more than the budget of " +
                                    number(kMaxMeshElements) + "; use a larger " + key};
  }
  return std::nullopt;
}

}  // namespace flapsim::wings
