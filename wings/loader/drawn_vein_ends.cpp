#include "wings/loader/drawn_vein_ends.hpp"

#include <algorithm>

namespace flapsim::wings {

namespace {

using Vec = Eigen::Vector2d;

// Cuts the end of the points (their last ones) outside the outline, at the last crossing of
// the edge; how far the cut part reached outside (0: not cut). Each segment from the end is
// sampled for inside points (a straight vein may leave the outline at both ends).
double cut_last_end(std::vector<Vec>& points, const Polygon& outline, double tolerance, double limit) {
  // An end within the tolerance is no overshoot (read_vein moves it onto the edge); the
  // crossing is the edge's own (containment without tolerance).
  if (points.size() < 2 || contains_point(outline, points.back(), tolerance)) return 0.0;
  const auto outside = [&](const Vec& q) { return !contains_point(outline, q, 0.0); };
  double reach = 0.0;
  for (std::size_t k = points.size() - 1; k-- > 0;) {  // the segment from k to k + 1
    reach = std::max(reach, distance_to_boundary(outline, points[k + 1]));
    if (reach > limit) return 0.0;  // too far: refused as a vein leaving the outline
    const Vec a = points[k], b = points[k + 1];
    constexpr int kSamples = 16;
    double in = -1.0, out = 1.0;  // parameters along the segment, inside and outside
    for (int i = kSamples; i-- > 0;) {
      const double t = double(i) / kSamples;
      if (!outside(a + t * (b - a))) {
        in = t;
        break;
      }
      out = t;
    }
    if (in < 0.0) continue;         // the whole segment outside: the end goes on before it
    for (int i = 0; i < 64; ++i) {  // the crossing, where contains_point changes, to round-off
      const double mid = 0.5 * (in + out);
      (outside(a + mid * (b - a)) ? out : in) = mid;
    }
    const bool distinct = in > 1e-9;
    if (k == 0 && !distinct) return 0.0;  // inside at its first point alone: refused later
    const Vec crossing = a + in * (b - a);
    points.resize(k + 1);
    if (distinct) points.push_back(crossing);
    return reach;
  }
  return 0.0;  // wholly outside: refused later
}

}  // namespace

std::array<double, 2> cut_overshooting_ends(std::vector<Vec>& points, const Polygon& outline,
                                            double tolerance, double limit) {
  std::array<double, 2> reach{};
  reach[1] = cut_last_end(points, outline, tolerance, limit);
  std::reverse(points.begin(), points.end());
  reach[0] = cut_last_end(points, outline, tolerance, limit);
  std::reverse(points.begin(), points.end());
  return reach;
}

}  // namespace flapsim::wings
