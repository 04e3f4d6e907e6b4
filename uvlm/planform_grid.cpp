#include "uvlm/planform_grid.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace flapsim::uvlm {

namespace {

/// Station fraction k/n in [0, 1] for the spacing.
double station(int k, int n, Spacing spacing) {
  const double s = static_cast<double>(k) / n;
  if (spacing == Spacing::Uniform) return s;
  return 0.5 * (1.0 - std::cos(std::numbers::pi * s));
}

void check_counts(const PlanformGridOptions& o) {
  if (o.chordwise < 1 || o.spanwise < 1)
    throw std::invalid_argument("planform grid: panel counts must be >= 1");
}

double grid_area(const Eigen::Matrix3Xd& nodes, int nc, int ns) {
  double area = 0.0;
  const int n1 = nc + 1;
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nc; ++i) {
      const Eigen::Vector3d d1 = nodes.col(i + 1 + n1 * (j + 1)) - nodes.col(i + n1 * j);
      const Eigen::Vector3d d2 = nodes.col(i + n1 * (j + 1)) - nodes.col(i + 1 + n1 * j);
      area += 0.5 * d1.cross(d2).norm();
    }
  return area;
}

}  // namespace

double polygon_area(const std::vector<Eigen::Vector2d>& p) {
  double a = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto& q = p[k];
    const auto& r = p[(k + 1) % p.size()];
    a += q.x() * r.y() - r.x() * q.y();
  }
  return 0.5 * std::abs(a);
}

Eigen::Vector2d chord_extent(const std::vector<Eigen::Vector2d>& p, double y) {
  double xmax = -std::numeric_limits<double>::infinity();
  double xmin = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto& q = p[k];
    const auto& r = p[(k + 1) % p.size()];
    const double lo = std::min(q.y(), r.y()), hi = std::max(q.y(), r.y());
    if (y < lo || y > hi || hi == lo) continue;
    const double x = q.x() + (y - q.y()) / (r.y() - q.y()) * (r.x() - q.x());
    xmax = std::max(xmax, x);
    xmin = std::min(xmin, x);
  }
  if (xmax < xmin) return {0.0, 0.0};
  return {xmax, xmin};
}

PlanformGrid make_planform_grid(const std::vector<Eigen::Vector2d>& outline,
                                const PlanformGridOptions& o) {
  check_counts(o);
  if (outline.size() < 3) throw std::invalid_argument("planform outline needs at least 3 points");
  const double area = polygon_area(outline);
  if (!(area > 0.0)) throw std::invalid_argument("planform outline has no area");

  double ymin = outline[0].y(), ymax = outline[0].y();
  for (const auto& q : outline) {
    ymin = std::min(ymin, q.y());
    ymax = std::max(ymax, q.y());
  }
  auto chord = [&](double y) {
    const Eigen::Vector2d e = chord_extent(outline, y);
    return e(0) - e(1);
  };
  // Largest chord from a dense scan of the span.
  double cmax = 0.0;
  constexpr int kScan = 400;
  for (int k = 0; k <= kScan; ++k) cmax = std::max(cmax, chord(ymin + (ymax - ymin) * k / kScan));
  const double cmin = o.min_end_chord * cmax;

  // Move an end station inboard (bisection) until its chord reaches cmin. An end square to
  // within kSquareEndFraction of the span (a root edge off perpendicular by round-off, as a
  // drawing rotated by 90° gives it) has its full chord that far in: the station goes there,
  // not to the point of its sub-micron slant where the chord passes cmin (there the root
  // strip started from 0.19 of its chord, and a corner moved by 1e-12 mm cost 1.8 % of CL).
  const double square_end = kSquareEndFraction * (ymax - ymin);
  auto inboard = [&](double y_end, double y_in) {
    if (chord(y_end) >= cmin) return y_end;
    const double just_in = y_end + (y_in > y_end ? square_end : -square_end);
    if (chord(just_in) >= cmin) return just_in;
    double a = y_end, b = y_in;  // chord(a) < cmin; b: a station with chord >= cmin
    for (int it = 0; it < 60; ++it) {
      const double m = 0.5 * (a + b);
      (chord(m) < cmin ? a : b) = m;
    }
    return b;
  };
  double ymid = ymin;  // a station at the largest chord
  for (int k = 0; k <= kScan; ++k) {
    const double y = ymin + (ymax - ymin) * k / kScan;
    if (chord(y) >= cmax) { ymid = y; break; }
  }
  const double y0 = inboard(ymin, ymid);
  const double y1 = inboard(ymax, ymid);

  PlanformGrid g;
  g.chordwise = o.chordwise;
  g.spanwise = o.spanwise;
  g.y_root = y0;
  g.y_tip = y1;
  g.outline_area = area;
  const int n1 = o.chordwise + 1;
  g.nodes.resize(3, n1 * (o.spanwise + 1));
  for (int j = 0; j <= o.spanwise; ++j) {
    const double y = y0 + (y1 - y0) * station(j, o.spanwise, o.spanwise_spacing);
    const Eigen::Vector2d e = chord_extent(outline, y);
    for (int i = 0; i < n1; ++i) {
      const double xi = station(i, o.chordwise, o.chordwise_spacing);
      g.nodes.col(i + n1 * j) = Eigen::Vector3d(e(0) - xi * (e(0) - e(1)), y, 0.0);
    }
  }
  g.lattice_area = grid_area(g.nodes, o.chordwise, o.spanwise);
  return g;
}

PlanformGrid make_rectangular_grid(double chord, double span, const PlanformGridOptions& o) {
  check_counts(o);
  if (!(chord > 0.0) || !(span > 0.0))
    throw std::invalid_argument("rectangular grid: chord and span must be > 0");
  PlanformGrid g;
  g.chordwise = o.chordwise;
  g.spanwise = o.spanwise;
  g.y_root = 0.0;
  g.y_tip = span;
  g.outline_area = chord * span;
  const int n1 = o.chordwise + 1;
  g.nodes.resize(3, n1 * (o.spanwise + 1));
  for (int j = 0; j <= o.spanwise; ++j) {
    const double y = span * station(j, o.spanwise, o.spanwise_spacing);
    for (int i = 0; i < n1; ++i)
      g.nodes.col(i + n1 * j) =
          Eigen::Vector3d(-chord * station(i, o.chordwise, o.chordwise_spacing), y, 0.0);
  }
  g.lattice_area = grid_area(g.nodes, o.chordwise, o.spanwise);
  return g;
}

}  // namespace flapsim::uvlm
