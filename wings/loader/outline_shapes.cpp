#include "wings/loader/outline_shapes.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace flapsim::wings {

namespace {

constexpr double kPi = std::numbers::pi;

// Adds p unless it repeats the last point (shapes whose straight parts have zero length).
void add_point(Polygon& poly, const Eigen::Vector2d& p) {
  if (poly.empty() || (poly.back() - p).norm() > 1e-12 * std::max(1.0, p.norm())) poly.push_back(p);
}

// n points of the arc of centre c, radii (a, b), from angle t0 to t1, end points included.
void add_arc(Polygon& poly, const Eigen::Vector2d& c, double a, double b, double t0, double t1, int n) {
  for (int k = 0; k <= n; ++k) {
    const double t = t0 + (t1 - t0) * k / n;
    add_point(poly, c + Eigen::Vector2d(a * std::cos(t), b * std::sin(t)));
  }
}

}  // namespace

Polygon closed_spline(const Polygon& control, int samples) {
  const int n = static_cast<int>(control.size());
  if (n < 3) throw std::invalid_argument("a closed spline needs at least 3 control points");
  // Chord-length parameter: h_i = |P_{i+1} − P_i|, the last interval closing the curve.
  Eigen::VectorXd h(n);
  for (int i = 0; i < n; ++i) {
    h(i) = (control[static_cast<size_t>((i + 1) % n)] - control[static_cast<size_t>(i)]).norm();
    if (!(h(i) > 0.0))
      throw std::invalid_argument("control points " + std::to_string(i + 1) + " and " +
                                  std::to_string((i + 1) % n + 1) + " coincide");
  }
  // Periodic cubic spline: second derivatives M from
  //   h_{i−1} M_{i−1} + 2 (h_{i−1} + h_i) M_i + h_i M_{i+1} = 6 (d_i − d_{i−1}),  d_i = ΔP_i / h_i,
  // indices modulo n (de Boor, A Practical Guide to Splines, ch. IV; the periodic end condition).
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd rhs(n, 2);
  for (int i = 0; i < n; ++i) {
    const int im = (i + n - 1) % n, ip = (i + 1) % n;
    a(i, im) += h(im);
    a(i, i) += 2.0 * (h(im) + h(i));
    a(i, ip) += h(i);
    const Eigen::Vector2d d_i = (control[static_cast<size_t>(ip)] - control[static_cast<size_t>(i)]) / h(i);
    const Eigen::Vector2d d_im = (control[static_cast<size_t>(i)] - control[static_cast<size_t>(im)]) / h(im);
    rhs.row(i) = 6.0 * (d_i - d_im).transpose();
  }
  const Eigen::MatrixXd m = a.partialPivLu().solve(rhs);  // strictly diagonally dominant

  // Sub-intervals per control interval in proportion to its length, at least one.
  const double total = h.sum();
  const int wanted = std::max(samples, n);
  Polygon out;
  for (int i = 0; i < n; ++i) {
    const int ip = (i + 1) % n;
    const int pieces = std::max(1, static_cast<int>(std::lround(wanted * h(i) / total)));
    const Eigen::Vector2d p0 = control[static_cast<size_t>(i)], p1 = control[static_cast<size_t>(ip)];
    const Eigen::Vector2d m0 = m.row(i).transpose(), m1 = m.row(ip).transpose();
    const double hi = h(i);
    for (int k = 0; k < pieces; ++k) {  // the interval's end point is the next one's start
      const double u = hi * k / pieces, v = hi - u;
      out.push_back(m0 * (v * v * v) / (6.0 * hi) + m1 * (u * u * u) / (6.0 * hi) +
                    (p0 / hi - m0 * hi / 6.0) * v + (p1 / hi - m1 * hi / 6.0) * u);
    }
  }
  if (polygon_signed_area(out) < 0.0) std::reverse(out.begin(), out.end());
  return out;
}

Polygon shape_outline(OutlineShape shape, const ShapeSize& s, int samples) {
  const double length = s.tip_y - s.root_y;
  if (!(s.chord > 0.0)) throw std::invalid_argument("the chord must be > 0");
  if (!(length > 0.0)) throw std::invalid_argument("the tip must lie beyond the root (tip_y > root_y)");
  const int n = std::max(samples, 16);
  const double half = 0.5 * s.chord;
  const double xc = s.leading_edge_x - half;  // x of the chord's middle
  Polygon p;
  switch (shape) {
    case OutlineShape::ellipse: {  // centre half-way, semi-axes chord/2 and L/2
      // A multiple of 4 points, so that the root, the foremost, the tip and the rearmost
      // point are points of it (18 points put the foremost 0.12 mm behind leading_edge_x and
      // the chord 1.5 % short; an odd count missed the tip, and the scaling to the span then
      // stretched the whole outline).
      const int m = (n + 3) / 4 * 4;
      for (int k = 0; k < m; ++k) {
        const double t = 2.0 * kPi * k / m - 0.5 * kPi;  // from the root point, counter-clockwise
        p.emplace_back(xc + half * std::cos(t), s.root_y + 0.5 * length * (1.0 + std::sin(t)));
      }
      break;
    }
    case OutlineShape::half_ellipse:  // centre on the root edge, semi-axes chord/2 and L
      // An even number of segments (an odd number of points), so that the tip is a point of it:
      // with 96 points the tip fell between two, and the scaling to the span moved the root edge
      // to y = 1.000134 mm (written 1) and made the chord 16.0021 mm.
      add_arc(p, {xc, s.root_y}, half, length, 0.0, kPi, n % 2 == 1 ? n - 1 : n);
      break;
    case OutlineShape::rounded_rectangle: {
      const double r = s.tip_radius;
      if (!(r > 0.0 && r <= std::min(half, length) * (1 + 1e-12)))
        throw std::invalid_argument("the tip radius must be > 0 and at most half the chord and the length");
      // n points: the two root corners and the two arcs' end points and inner points (the
      // arcs of a semicircular tip, r = chord/2, share a point: the second gets one more).
      // (Before: n/4 segments per arc, 52 points at n = 96.)
      const double le = s.leading_edge_x, te = s.leading_edge_x - s.chord;
      const bool arcs_touch = (le - r) - (te + r) <= 1e-12 * s.chord;
      const int leading_arc = (n - 4) / 2, trailing_arc = n - 4 - leading_arc + (arcs_touch ? 1 : 0);
      add_point(p, {te, s.root_y});
      add_point(p, {le, s.root_y});
      add_arc(p, {le - r, s.tip_y - r}, r, r, 0.0, 0.5 * kPi, leading_arc);
      add_arc(p, {te + r, s.tip_y - r}, r, r, 0.5 * kPi, kPi, trailing_arc);
      break;
    }
  }
  return p;
}

bool drop_closing_point(Polygon& outline, double tolerance) {
  if (outline.size() < 4) return false;
  if ((outline.back() - outline.front()).norm() > tolerance) return false;
  outline.pop_back();
  return true;
}

}  // namespace flapsim::wings
