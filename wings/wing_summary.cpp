#include "wings/wing_summary.hpp"

#include <cstdio>
#include <string>

#include "wings/planform_geometry.hpp"
#include "wings/wing_mass_properties.hpp"

namespace flapsim::wings {

namespace {

template <typename... Args>
std::string line(const char* format, Args... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, args...);
  return std::string(buf) + "\n";
}

}  // namespace

std::string describe_wing(const Wing& wing) {
  const PlanformProperties p = planform_properties(wing.outline);
  const WingMassEstimate m = estimate_wing_mass(wing);
  std::string s = "wing '" + wing.name + "' (" + wing.source_file + ")\n";
  s += line("  span R                 %10.3f mm", p.span * 1e3);
  s += line("  area S                 %10.3f mm^2", p.area * 1e6);
  s += line("  mean chord S/R         %10.3f mm", p.mean_chord * 1e3);
  s += line("  aspect ratio R^2/S     %10.4f", p.aspect_ratio);
  s += line("  r2/R                   %10.4f", p.r2);
  s += line("  root y (outline min)   %10.3f mm", p.root_y * 1e3);
  s += line("  outline points         %10zu", wing.outline.size());
  s += line("  veins                  %10zu", wing.veins.size());
  s += line("  membrane thickness     %10.4f mm (E %.3g GPa, nu %.3g, rho %.4g kg/m^3)",
            wing.membrane.thickness * 1e3, wing.membrane.material.youngs_modulus * 1e-9,
            wing.membrane.material.poisson_ratio, wing.membrane.material.density);
  s += line("  estimated mass         %10.3f mg (membrane %.3f, non-structural %.3f, veins %.3f)",
            m.total() * 1e6, m.membrane * 1e6, m.nonstructural * 1e6, m.veins * 1e6);
  s += line("  root clamp             y <= %.3f mm", wing.clamp_y * 1e3);
  s += line("  mesh size              %10.3f mm (veins %.3f mm)", wing.mesh.element_size * 1e3,
            wing.mesh.vein_element_size * 1e3);
  return s;
}

}  // namespace flapsim::wings
