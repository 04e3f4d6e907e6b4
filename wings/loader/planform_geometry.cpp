#include "wings/loader/planform_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flapsim::wings {

namespace {

// Twice the signed area of triangle (a, b, c): > 0 if c lies left of a -> b.
double orient(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

int sign(double v) { return (v > 0.0) - (v < 0.0); }

// For collinear a, b, c: does c lie within the bounding box of segment [a, b]?
bool on_segment_box(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= c.y() && c.y() <= std::max(a.y(), b.y());
}

double distance_to_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                           const Eigen::Vector2d& p) {
  return (nearest_point_on_segment(a, b, p) - p).norm();
}

}  // namespace

Eigen::Vector2d nearest_point_on_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                         const Eigen::Vector2d& p) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0.0) return a;
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return a + t * ab;
}

double polygon_signed_area(const Polygon& poly) {
  const std::size_t n = poly.size();
  double twice = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % n];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

double polygon_area(const Polygon& poly) { return std::abs(polygon_signed_area(poly)); }

Eigen::Vector2d polygon_centroid(const Polygon& poly) {
  const std::size_t n = poly.size();
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  double twice_area = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % n];
    const double cross = a.x() * b.y() - b.x() * a.y();
    twice_area += cross;
    c += cross * (a + b);
  }
  return c / (3.0 * twice_area);
}

double polygon_second_moment_y(const Polygon& poly) {
  // Green's theorem: ∫∫ y² dA = (1/12) Σ (x_i y_{i+1} − x_{i+1} y_i)(y_i² + y_i y_{i+1} + y_{i+1}²),
  // signed like the area, hence the abs for either orientation.
  const std::size_t n = poly.size();
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % n];
    const double cross = a.x() * b.y() - b.x() * a.y();
    sum += cross * (a.y() * a.y() + a.y() * b.y() + b.y() * b.y());
  }
  return std::abs(sum / 12.0);
}

PolygonMoments polygon_moments(const Polygon& poly) {
  // Green's theorem over each edge (a, b) with c = a_x b_y − b_x a_y:
  //   ∫∫ x² dA = Σ c (a_x² + a_x b_x + b_x²) / 12,  ∫∫ x y dA = Σ c (a_x b_y + 2 a_x a_y + 2 b_x b_y + b_x
  //   a_y) / 24,
  // all signed like the area (Σ c / 2), hence the sign flip for clockwise outlines.
  PolygonMoments m;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % n];
    const double c = a.x() * b.y() - b.x() * a.y();
    m.area += c / 2.0;
    m.first += c * (a + b) / 6.0;
    m.xx += c * (a.x() * a.x() + a.x() * b.x() + b.x() * b.x()) / 12.0;
    m.yy += c * (a.y() * a.y() + a.y() * b.y() + b.y() * b.y()) / 12.0;
    m.xy += c * (a.x() * b.y() + 2.0 * a.x() * a.y() + 2.0 * b.x() * b.y() + b.x() * a.y()) / 24.0;
  }
  if (m.area < 0.0) {
    m.area = -m.area;
    m.first = -m.first;
    m.xx = -m.xx;
    m.yy = -m.yy;
    m.xy = -m.xy;
  }
  return m;
}

bool segments_intersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                        const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  const int o1 = sign(orient(a, b, c)), o2 = sign(orient(a, b, d));
  const int o3 = sign(orient(c, d, a)), o4 = sign(orient(c, d, b));
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && on_segment_box(a, b, c)) return true;
  if (o2 == 0 && on_segment_box(a, b, d)) return true;
  if (o3 == 0 && on_segment_box(c, d, a)) return true;
  if (o4 == 0 && on_segment_box(c, d, b)) return true;
  return false;
}

std::optional<std::pair<int, int>> find_self_intersection(const Polygon& poly) {
  const int n = static_cast<int>(poly.size());
  if (n < 3) return std::nullopt;
  // Repeated points first (zero-length edges): else the edge ending at a repeat of point 0
  // was reported as touching edge 0, not as the repeat it is.
  for (int i = 0; i < n; ++i)
    if (poly[i] == poly[(i + 1) % n]) return std::make_pair(i, (i + 1) % n);
  for (int i = 0; i < n; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % n];
    // Adjacent edge folding back on this one (a spike of zero width).
    const auto& c = poly[(i + 2) % n];
    if (orient(a, b, c) == 0.0 && (b - a).dot(c - b) < 0.0) return std::make_pair(i, (i + 1) % n);
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // edges n-1 and 0 share point 0
      if (segments_intersect(a, b, poly[j], poly[(j + 1) % n])) return std::make_pair(i, j);
    }
  }
  return std::nullopt;
}

double distance_to_boundary(const Polygon& poly, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i)
    best = std::min(best, distance_to_segment(poly[i], poly[(i + 1) % n], p));
  return best;
}

Eigen::Vector2d nearest_point_on_polyline(const std::vector<Eigen::Vector2d>& points,
                                          const Eigen::Vector2d& p, bool closed) {
  const std::size_t n = points.size();
  if (n == 1) return points[0];
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector2d nearest = p;
  for (std::size_t i = 0; i < (closed ? n : n - 1); ++i) {
    const Eigen::Vector2d q = nearest_point_on_segment(points[i], points[(i + 1) % n], p);
    if ((p - q).norm() < best) {
      best = (p - q).norm();
      nearest = q;
    }
  }
  return nearest;
}

Eigen::Vector2d nearest_boundary_point(const Polygon& poly, const Eigen::Vector2d& p) {
  return nearest_point_on_polyline(poly, p, true);
}

bool contains_point(const Polygon& poly, const Eigen::Vector2d& p, double tolerance) {
  if (distance_to_boundary(poly, p) <= tolerance) return true;
  // Even-odd ray cast toward +x; points on the boundary were handled above.
  bool inside = false;
  const std::size_t n = poly.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const auto& a = poly[i];
    const auto& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

std::optional<ChordLine> chord_at(const Polygon& poly, double y) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % n];
    if (y < std::min(a.y(), b.y()) || y > std::max(a.y(), b.y())) continue;
    if (a.y() == b.y()) {  // horizontal edge lying on the station
      lo = std::min({lo, a.x(), b.x()});
      hi = std::max({hi, a.x(), b.x()});
      continue;
    }
    const double x = a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  if (!(lo <= hi)) return std::nullopt;
  return ChordLine{hi, lo};
}

std::vector<Eigen::Vector2d> edge_vertices_between(const Polygon& poly, double y_from, double y_to,
                                                   bool leading_edge) {
  double span = 0.0;  // [m]
  for (const auto& q : poly) span = std::max(span, std::abs(q.y()));
  const double lo = std::min(y_from, y_to), hi = std::max(y_from, y_to);
  std::vector<Eigen::Vector2d> out;
  for (const auto& v : poly) {
    if (!(v.y() > lo && v.y() < hi)) continue;
    const auto c = chord_at(poly, v.y());
    if (c && std::abs((leading_edge ? c->leading_x : c->trailing_x) - v.x()) <= 1e-9 * span) out.push_back(v);
  }
  std::sort(out.begin(), out.end(), [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return y_to >= y_from ? a.y() < b.y() : a.y() > b.y();
  });
  return out;
}

PlanformProperties planform_properties(const Polygon& poly) {
  PlanformProperties p;
  p.span = -std::numeric_limits<double>::infinity();
  p.root_y = std::numeric_limits<double>::infinity();
  for (const auto& q : poly) {
    p.span = std::max(p.span, q.y());
    p.root_y = std::min(p.root_y, q.y());
  }
  p.area = polygon_area(poly);
  p.mean_chord = p.area / p.span;
  p.aspect_ratio = p.span * p.span / p.area;
  p.r2 = std::sqrt(polygon_second_moment_y(poly) / p.area) / p.span;
  p.centroid = polygon_centroid(poly);
  return p;
}

double clamp_span_share(const PlanformProperties& props, double clamp_y) {
  const double range = props.span - props.root_y;  // [m]
  return range > 0.0 ? (clamp_y - props.root_y) / range : 0.0;
}

}  // namespace flapsim::wings
