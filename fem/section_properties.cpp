#include "fem/section_properties.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace flapsim::fem {

SectionProperties section_properties(const wings::Section& section) {
  SectionProperties p;
  if (section.shape == wings::Section::Shape::HollowCircle) {
    const double D = section.outer_diameter;
    const double d = std::max(0.0, D - 2.0 * section.wall);  // inner diameter
    const double D2 = D * D, d2 = d * d;
    p.area = std::numbers::pi / 4.0 * (D2 - d2);
    p.I_y = std::numbers::pi / 64.0 * (D2 * D2 - d2 * d2);
    p.I_z = p.I_y;
    p.polar_moment = 2.0 * p.I_y;
    p.torsion_constant = p.polar_moment;  // circular: warping-free, J = I_p
  } else {
    const double w = section.width, h = section.height;
    p.area = w * h;
    p.I_y = w * h * h * h / 12.0;
    p.I_z = h * w * w * w / 12.0;
    p.polar_moment = p.I_y + p.I_z;
    const double a = std::max(w, h), b = std::min(w, h);
    if (a > 0.0) {
      const double r = b / a;
      p.torsion_constant = a * b * b * b * (1.0 / 3.0 - 0.21 * r * (1.0 - r * r * r * r / 12.0));
    }
  }
  return p;
}

wings::Section interpolate_section(const wings::Section& root, const wings::Section& tip, double s) {
  s = std::clamp(s, 0.0, 1.0);
  wings::Section out = root;
  if (tip.shape != root.shape) return out;
  auto lerp = [s](double a, double b) { return a + s * (b - a); };
  out.outer_diameter = lerp(root.outer_diameter, tip.outer_diameter);
  out.wall = lerp(root.wall, tip.wall);
  out.width = lerp(root.width, tip.width);
  out.height = lerp(root.height, tip.height);
  return out;
}

}  // namespace flapsim::fem
