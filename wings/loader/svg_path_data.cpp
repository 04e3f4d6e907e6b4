#include "wings/loader/svg_path_data.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "wings/loader/svg_drawing.hpp"
#include "wings/loader/svg_numbers.hpp"

namespace flapsim::wings {

namespace {

using Vec = Eigen::Vector2d;

constexpr int kMaxPiecesPerCurve = 1000;  // a guard: the bound below gives at most 55

int bezier_pieces(double second_difference_bound, double control_polygon) {
  const double tol = kBezierFlatness * control_polygon;
  if (!(tol > 0.0)) return 1;
  const double n = std::ceil(std::sqrt(second_difference_bound / (8.0 * tol)));
  return static_cast<int>(std::clamp(n, 1.0, static_cast<double>(kMaxPiecesPerCurve)));
}

void cubic(std::vector<Vec>& pts, const Vec& p0, const Vec& p1, const Vec& p2, const Vec& p3) {
  // |B''| ≤ 6 max(|p0 − 2p1 + p2|, |p1 − 2p2 + p3|).
  const double m = 6.0 * std::max((p0 - 2 * p1 + p2).norm(), (p1 - 2 * p2 + p3).norm());
  const int n = bezier_pieces(m, (p1 - p0).norm() + (p2 - p1).norm() + (p3 - p2).norm());
  for (int k = 1; k <= n; ++k) {
    const double t = double(k) / n, u = 1.0 - t;
    append_svg_point(
        pts,
        k == n ? p3 : (u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3).eval());
  }
}

void quadratic(std::vector<Vec>& pts, const Vec& p0, const Vec& p1, const Vec& p2) {
  const double m = 2.0 * (p0 - 2 * p1 + p2).norm();
  const int n = bezier_pieces(m, (p1 - p0).norm() + (p2 - p1).norm());
  for (int k = 1; k <= n; ++k) {
    const double t = double(k) / n, u = 1.0 - t;
    append_svg_point(pts, k == n ? p2 : (u * u * p0 + 2 * u * t * p1 + t * t * p2).eval());
  }
}

// The points of an ellipse's arc from angle t0 through dt (radii rx, ry, x axis at phi),
// about centre c, the first point left out.
void ellipse_arc(std::vector<Vec>& pts, const Vec& c, double rx, double ry, double phi, double t0, double dt,
                 const std::optional<Vec>& last) {
  const int n =
      std::max(1, static_cast<int>(std::ceil(std::abs(dt) / (2 * std::numbers::pi) * kArcPiecesPerTurn)));
  const double cp = std::cos(phi), sp = std::sin(phi);
  for (int k = 1; k <= n; ++k) {
    if (k == n && last) {
      append_svg_point(pts, *last);
      break;
    }
    const double t = t0 + dt * k / n;
    const double x = rx * std::cos(t), y = ry * std::sin(t);
    append_svg_point(pts, Vec(c.x() + cp * x - sp * y, c.y() + sp * x + cp * y));
  }
}

// An elliptical arc from p0 to p1 (SVG 1.1, F.6.5 and F.6.6: out-of-range radii scaled up).
void arc(std::vector<Vec>& pts, const Vec& p0, double rx, double ry, double phi_deg, bool large, bool sweep,
         const Vec& p1) {
  if (p0 == p1) return;
  rx = std::abs(rx);
  ry = std::abs(ry);
  if (rx == 0.0 || ry == 0.0) {
    append_svg_point(pts, p1);
    return;
  }
  const double phi = phi_deg * std::numbers::pi / 180.0, cp = std::cos(phi), sp = std::sin(phi);
  const Vec h = 0.5 * (p0 - p1);
  const Vec q(cp * h.x() + sp * h.y(), -sp * h.x() + cp * h.y());
  const double lambda = q.x() * q.x() / (rx * rx) + q.y() * q.y() / (ry * ry);
  if (lambda > 1.0) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  const double num = rx * rx * ry * ry - rx * rx * q.y() * q.y() - ry * ry * q.x() * q.x();
  const double den = rx * rx * q.y() * q.y() + ry * ry * q.x() * q.x();
  double f = std::sqrt(std::max(0.0, num / den));
  if (large == sweep) f = -f;
  const Vec cq(f * rx * q.y() / ry, -f * ry * q.x() / rx);
  const Vec m = 0.5 * (p0 + p1);
  const Vec c(cp * cq.x() - sp * cq.y() + m.x(), sp * cq.x() + cp * cq.y() + m.y());
  const auto angle = [](const Vec& u, const Vec& v) {
    return std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
  };
  const Vec u((q.x() - cq.x()) / rx, (q.y() - cq.y()) / ry),
      v((-q.x() - cq.x()) / rx, (-q.y() - cq.y()) / ry);
  const double t0 = angle(Vec(1, 0), u);
  double dt = angle(u, v);
  if (!sweep && dt > 0) dt -= 2 * std::numbers::pi;
  if (sweep && dt < 0) dt += 2 * std::numbers::pi;
  ellipse_arc(pts, c, rx, ry, phi, t0, dt, p1);
}

}  // namespace

std::vector<SvgSubpath> parse_svg_path_data(std::string_view d, std::size_t points_before) {
  std::vector<SvgSubpath> out;
  std::size_t points = points_before;  // the drawing's points before this path's last subpath
  std::size_t counted = 0;             // this path's subpaths in `points`
  NumberScanner s(d);
  Vec current(0, 0), start(0, 0), last_control(0, 0);
  char previous = '\0', command = '\0';
  const auto bad = [&](const std::string& why) {
    throw SvgSyntaxError("path data (d) at character " + std::to_string(s.position() + 1) + ": " + why);
  };
  const auto num = [&]() {
    const auto v = s.number();
    if (!v) bad("expected a number");
    return *v;
  };
  const auto point = [&](bool relative) {
    const double x = num(), y = num();
    return relative ? Vec(current + Vec(x, y)) : Vec(x, y);
  };
  const auto open_subpath = [&]() {
    if (out.empty() || out.back().closed) {
      out.push_back({});
      out.back().points.push_back(current);
    }
  };
  while (!s.at_end()) {
    const char c = s.peek();
    if (std::isalpha(static_cast<unsigned char>(c))) {
      command = c;
      s.advance();
    } else if (command == '\0') {
      bad("path data must start with a moveto (M or m)");
    } else if (command == 'M') {
      command = 'L';  // pairs after a moveto are linetos
    } else if (command == 'm') {
      command = 'l';
    } else if (command == 'Z' || command == 'z') {
      bad("a number after closepath (Z)");
    }
    const bool rel = std::islower(static_cast<unsigned char>(command));
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
    // The reflection of the last control point about the current point if the previous
    // command was one of the two curves given, else the current point (SVG 1.1, 8.3.6, 8.3.7).
    const auto reflected_control = [&](char curve, char smooth) {
      const char p = static_cast<char>(std::toupper(static_cast<unsigned char>(previous)));
      return (p == curve || p == smooth) ? Vec(2 * current - last_control) : current;
    };
    switch (upper) {
      case 'M':
        current = start = point(rel);  // a leading 'm' is relative to (0, 0): absolute
        out.push_back({});
        out.back().points.push_back(current);
        break;
      case 'L':
        open_subpath();
        current = point(rel);
        append_svg_point(out.back().points, current);
        break;
      case 'H':
        open_subpath();
        current.x() = num() + (rel ? current.x() : 0.0);
        append_svg_point(out.back().points, current);
        break;
      case 'V':
        open_subpath();
        current.y() = num() + (rel ? current.y() : 0.0);
        append_svg_point(out.back().points, current);
        break;
      case 'C':
      case 'S': {  // S: the first control point is the last one's reflection (after C or S)
        open_subpath();
        const Vec p1 = upper == 'C' ? point(rel) : reflected_control('C', 'S');
        const Vec p2 = point(rel), p3 = point(rel);
        cubic(out.back().points, current, p1, p2, p3);
        last_control = p2;
        current = p3;
        break;
      }
      case 'Q':
      case 'T': {  // T: the control point is the last one's reflection (after Q or T)
        open_subpath();
        const Vec p1 = upper == 'Q' ? point(rel) : reflected_control('Q', 'T');
        const Vec p2 = point(rel);
        quadratic(out.back().points, current, p1, p2);
        last_control = p1;
        current = p2;
        break;
      }
      case 'A': {
        open_subpath();
        const double rx = num(), ry = num(), phi = num();
        const auto large = s.flag();
        if (!large) bad("an arc's large-arc flag must be 0 or 1");
        const auto sweep = s.flag();
        if (!sweep) bad("an arc's sweep flag must be 0 or 1");
        const Vec p1 = point(rel);
        arc(out.back().points, current, rx, ry, phi, *large, *sweep, p1);
        current = p1;
        break;
      }
      case 'Z':
        if (out.empty()) bad("closepath (Z) before any moveto");
        if (!out.back().closed) {
          out.back().closed = true;
          current = start;
        }
        break;
      default: bad(std::string("unknown command '") + command + "'");
    }
    previous = command;
    while (counted + 1 < out.size()) points += out[counted++].points.size();  // the finished subpaths
    if (!out.empty() && points + out.back().points.size() > kMaxDrawingPoints) bad(too_many_drawing_points());
  }
  return out;
}

void append_svg_point(std::vector<Vec>& pts, const Vec& p) {
  if (pts.empty() || pts.back() != p) pts.push_back(p);
}

std::vector<Vec> svg_ellipse_points(const Vec& c, double rx, double ry) {
  std::vector<Vec> points;
  for (int k = 0; k < kArcPiecesPerTurn; ++k) {
    const double t = 2 * std::numbers::pi * k / kArcPiecesPerTurn;
    append_svg_point(points, Vec(c.x() + rx * std::cos(t), c.y() + ry * std::sin(t)));
  }
  return points;
}

}  // namespace flapsim::wings
