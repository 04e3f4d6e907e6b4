#include "wings/loader/wing_mass_properties.hpp"

#include <numbers>

#include "wings/loader/planform_geometry.hpp"

namespace flapsim::wings {

double section_area(const Section& s) {
  if (s.shape == Section::Shape::Rectangle) return s.width * s.height;
  const double d = s.outer_diameter;
  if (2.0 * s.wall >= d) return std::numbers::pi * d * d / 4.0;
  return std::numbers::pi * s.wall * (d - s.wall);
}

Section section_at(const Vein& vein, double u) {
  const Section& a = vein.root_section;
  const Section& b = vein.tip_section;
  Section s = a;
  s.outer_diameter = (1.0 - u) * a.outer_diameter + u * b.outer_diameter;
  s.wall = (1.0 - u) * a.wall + u * b.wall;
  s.width = (1.0 - u) * a.width + u * b.width;
  s.height = (1.0 - u) * a.height + u * b.height;
  return s;
}

double vein_length(const Vein& vein) {
  double len = 0.0;
  for (std::size_t i = 1; i < vein.points.size(); ++i)
    len += (vein.points[i] - vein.points[i - 1]).norm();
  return len;
}

double vein_mass(const Vein& vein) {
  // The area depends on the arc fraction only, so integrate over u ∈ [0, 1] and
  // multiply by the length. 64 Simpson intervals also resolve the kink where a
  // tapering wall reaches D/2 (solid section).
  constexpr int n = 64;
  double sum = section_area(section_at(vein, 0.0)) + section_area(section_at(vein, 1.0));
  for (int i = 1; i < n; ++i)
    sum += (i % 2 ? 4.0 : 2.0) * section_area(section_at(vein, double(i) / n));
  return vein.material.density * vein_length(vein) * sum / (3.0 * n);
}

WingMassEstimate estimate_wing_mass(const Wing& wing) {
  WingMassEstimate m;
  const double area = polygon_area(wing.outline);
  m.membrane = wing.membrane.material.density * wing.membrane.thickness * area;
  m.nonstructural = wing.membrane.nonstructural_mass_per_area * area;
  for (const auto& v : wing.veins) m.veins += vein_mass(v);
  return m;
}

namespace {

/// Mass and its moments about the origin: m, ∫ (x, y) dm, ∫ x² dm, ∫ y² dm, ∫ x y dm.
struct MassMoments {
  double mass = 0.0;
  Eigen::Vector2d first = Eigen::Vector2d::Zero();
  double xx = 0.0, yy = 0.0, xy = 0.0;
};

void add_vein_moments(const Vein& vein, MassMoments& m) {
  // Composite Simpson on each straight segment (16 intervals): the line density ρ A(u) is
  // quadratic in the arc fraction u, so the integrands are polynomials of degree ≤ 4 in s.
  const double length = vein_length(vein);
  if (length <= 0.0) return;
  constexpr int n = 16;
  double s0 = 0.0;
  for (std::size_t k = 1; k < vein.points.size(); ++k) {
    const Eigen::Vector2d a = vein.points[k - 1], b = vein.points[k];
    const double segment = (b - a).norm();
    for (int i = 0; i <= n; ++i) {
      const double w = (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0)) * segment / (3.0 * n);
      const double t = double(i) / n;
      const Eigen::Vector2d p = a + t * (b - a);
      const double dm =
          w * vein.material.density * section_area(section_at(vein, (s0 + t * segment) / length));
      m.mass += dm;
      m.first += dm * p;
      m.xx += dm * p.x() * p.x();
      m.yy += dm * p.y() * p.y();
      m.xy += dm * p.x() * p.y();
    }
    s0 += segment;
  }
}

}  // namespace

WingInertia estimate_wing_inertia(const Wing& wing) {
  MassMoments m;
  const PolygonMoments plate = polygon_moments(wing.outline);
  const double areal = wing.membrane.material.density * wing.membrane.thickness +
                       wing.membrane.nonstructural_mass_per_area;  // [kg/m²]
  m.mass = areal * plate.area;
  m.first = areal * plate.first;
  m.xx = areal * plate.xx;
  m.yy = areal * plate.yy;
  m.xy = areal * plate.xy;
  for (const auto& v : wing.veins) add_vein_moments(v, m);
  WingInertia w;
  w.mass = m.mass;
  if (!(m.mass > 0.0)) return w;
  const Eigen::Vector2d c = m.first / m.mass;
  w.center_of_mass = c;
  // Parallel axes: ∫ x'² dm = ∫ x² dm − m c_x², ∫ x' y' dm = ∫ x y dm − m c_x c_y.
  const double ixx = m.yy - m.mass * c.y() * c.y();
  const double iyy = m.xx - m.mass * c.x() * c.x();
  const double pxy = m.xy - m.mass * c.x() * c.y();
  w.inertia << ixx, -pxy, 0.0, -pxy, iyy, 0.0, 0.0, 0.0, ixx + iyy;
  return w;
}

}  // namespace flapsim::wings
