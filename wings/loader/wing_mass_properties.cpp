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

}  // namespace flapsim::wings
