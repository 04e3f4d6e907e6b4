#include "wings/loader/vein_junctions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

#include "wings/loader/planform_geometry.hpp"

namespace flapsim::wings {

double vein_junction_tolerance(double span, double vein_element_size) {
  return std::min(1e-3 * span, std::tan(kSliverAngleDeg * std::numbers::pi / 180.0) * vein_element_size);
}

int snap_vein_ends_onto_other_veins(std::vector<Vein>& veins, double tolerance, double round_off) {
  auto is_gap = [&](double d) { return d > round_off && d <= tolerance; };
  auto ends_of = [](Vein& v) { return std::array<Eigen::Vector2d*, 2>{&v.points.front(), &v.points.back()}; };
  int moved = 0;
  // 1. Ends that meet ends: each onto the end of an earlier vein it lies next to, exactly.
  //    (Taken onto each other's lines instead, two such ends would each land beside the
  //    other's moved end, a gap again.)
  for (std::size_t i = 0; i < veins.size(); ++i) {
    if (veins[i].points.empty()) continue;
    for (Eigen::Vector2d* end : ends_of(veins[i])) {
      for (std::size_t j = 0; j < i; ++j) {
        if (veins[j].points.empty()) continue;
        const auto other = ends_of(veins[j]);
        Eigen::Vector2d* onto = (*other[0] - *end).norm() <= (*other[1] - *end).norm() ? other[0] : other[1];
        if (is_gap((*onto - *end).norm())) {
          *end = *onto;
          ++moved;
          break;
        }
      }
    }
  }
  // 2. Ends beside another vein's line: onto its nearest point (a T-junction).
  for (std::size_t i = 0; i < veins.size(); ++i) {
    if (veins[i].points.empty()) continue;
    for (Eigen::Vector2d* end : ends_of(veins[i])) {
      double best = std::numeric_limits<double>::infinity();  // [m]
      Eigen::Vector2d nearest = *end;
      for (std::size_t j = 0; j < veins.size(); ++j) {
        if (j == i || veins[j].points.empty()) continue;
        const Eigen::Vector2d c = nearest_point_on_polyline(veins[j].points, *end);
        if (const double d = (c - *end).norm(); d < best) {
          best = d;
          nearest = c;
        }
      }
      if (is_gap(best)) {
        *end = nearest;
        ++moved;
      }
    }
  }
  return moved;
}

}  // namespace flapsim::wings
