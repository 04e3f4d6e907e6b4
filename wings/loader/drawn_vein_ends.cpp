#include "wings/loader/drawn_vein_ends.hpp"

#include <algorithm>
#include <optional>

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

// The parameter s along a → b where it crosses c → d (0 ≤ s, u ≤ 1), if it does.
std::optional<double> crossing_parameter(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  const Vec r = b - a, e = d - c;
  const double denom = r.x() * e.y() - r.y() * e.x();
  if (denom == 0.0) return std::nullopt;  // parallel
  const Vec ac = c - a;
  const double s = (ac.x() * e.y() - ac.y() * e.x()) / denom, u = (ac.x() * r.y() - ac.y() * r.x()) / denom;
  if (s < 0.0 || s > 1.0 || u < 0.0 || u > 1.0) return std::nullopt;
  return s;
}

// The join of the last end of \p vein with \p other, if within the limit: the cut where the
// vein's last `limit` of length crosses it, else the nearest point of its line.
struct EndJoin {
  double distance;
  bool crossed;
  std::size_t keep;  // points kept before the end's new point
  Vec point;
};
std::optional<EndJoin> join_last_end(const std::vector<Vec>& vein, const std::vector<Vec>& other,
                                     double limit) {
  double arc = 0.0;  // from the vein's end back to the segment's far point
  for (std::size_t k = vein.size() - 1; k-- > 0 && arc <= limit;) {
    const Vec a = vein[k], b = vein[k + 1];
    std::optional<double> last;  // the crossing nearest b on this segment
    for (std::size_t m = 0; m + 1 < other.size(); ++m)
      if (const auto s = crossing_parameter(a, b, other[m], other[m + 1]); s && (!last || *s > *last))
        last = s;
    if (last) {
      const double passed = arc + (1.0 - *last) * (b - a).norm();
      if (passed > limit || *last == 0.0) return std::nullopt;
      return EndJoin{passed, true, k + 1, a + *last * (b - a)};
    }
    arc += (b - a).norm();
  }
  const Vec q = nearest_point_on_polyline(other, vein.back());
  const double gap = (q - vein.back()).norm();
  if (gap > limit) return std::nullopt;
  return EndJoin{gap, false, vein.size() - 1, q};
}

}  // namespace

std::vector<DrawnVeinJoin> join_drawn_vein_ends(std::vector<std::vector<Vec>>& veins,
                                                const std::vector<bool>& drawn, const Polygon& outline,
                                                double tolerance, double limit) {
  std::vector<DrawnVeinJoin> joins;
  for (std::size_t i = 0; i < veins.size(); ++i) {
    if (!drawn[i]) continue;
    for (int end = 0; end < 2; ++end) {
      std::vector<Vec>& v = veins[i];
      if (end == 0) std::reverse(v.begin(), v.end());
      std::optional<EndJoin> best;
      std::size_t best_other = 0;
      if (distance_to_boundary(outline, v.back()) > tolerance)
        for (std::size_t j = 0; j < veins.size(); ++j) {
          if (j == i) continue;
          const auto join = join_last_end(v, veins[j], limit);
          if (join && join->distance > tolerance && (!best || join->distance < best->distance)) {
            best = join;
            best_other = j;
          }
        }
      if (best) {
        std::vector<Vec> joined(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(best->keep));
        if ((best->point - joined.back()).norm() > tolerance)
          joined.push_back(best->point);
        else
          joined.back() = best->point;  // its last point moved onto the other vein
        if (joined.size() >= 2) {
          v = std::move(joined);
          joins.push_back({i, best_other, end, best->distance, best->crossed});
        }
      }
      if (end == 0) std::reverse(v.begin(), v.end());
    }
  }
  return joins;
}

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
